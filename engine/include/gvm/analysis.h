// The engine's entry point: a part in, every concave region and feature with its exact
// visibility maps out. The Analysis object owns those maps (and the part), so that a
// planner -- or a daemon caching it -- can decide on exact sets, never on the rounded
// doubles of the JSON; `gvm/analysis_proto.h` turns it into the message gvm.v1.Analysis.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <stop_token>
#include <string>
#include <string_view>
#include <vector>

#include <spdlog/fwd.h>

#include "gvm/direction.h"
#include "gvm/direction_set.h"
#include "gvm/geometry.h"
#include "gvm/mesh.h"
#include "gvm/status.h"
#include "gvm/step.h"
#include "gvm/v1/gvm.pb.h"

namespace gvm {

struct AnalyzeRequest {
  std::string part_path;            // a mesh (OFF, OBJ, STL, PLY) or a STEP file (options.step)
  std::string groups_path;          // optional JSON of named face groups
  v1::AnalyzeOptions options;
  // Called now and then from the computing threads with (surfaces done, surfaces total);
  // returning false cancels the analysis (kCancelled), as a stop request does.
  std::function<bool(size_t, size_t)> progress;
  // The part from memory instead of part_path when part_bytes is set (the bytes must outlive
  // analyze()); part_name names it in messages and in the summary's source.
  std::optional<std::string_view> part_bytes;
  MeshFormat part_format = MeshFormat::kStl;
  std::string part_name;
  std::string groups_json;   // the face groups as JSON text instead of groups_path (same format)
  uint32_t max_faces = 0;    // 0: no limit; more input faces -> kResourceExhausted before validation, naming the count and the limit
  std::stop_token stop;      // a stop request cancels the analysis within milliseconds (kCancelled)
  std::shared_ptr<spdlog::logger> logger;  // null: spdlog's default logger (a daemon gives each request its own, so lines carry the request id)
};

// What the map called gvm is, for one surface.
enum class GvmStatus {
  kExactNoPotentialOccluders,   // O_S empty: GVM = LVM(S + N_S)
  kGlobalOcclusionNotComputed,  // O_S not empty, occlusion skipped: only the LVM is known
  kGlobalOcclusionComputed,     // GVM = LVM(S + N_S) - GOM(S, O_S)
  kEmptyVoid,                   // S touches an internal void: never visible
};

// Sizes of the computation for one surface (paper Tables 1-2).
struct SurfaceStatistics {
  uint32_t neighbor_occluders = 0;   // |N_S| in input faces
  uint32_t potential_occluders = 0;  // |O_S| in input faces
  uint64_t envelope_border_arcs = 0, envelope_faces = 0, envelope_patches = 0;
  uint64_t first_pass_occluders = 0;  // triangles; 0 when the closure took one pass
  uint64_t pairwise_maps = 0, pairwise_map_arcs = 0;
  uint64_t arrangement_vertices = 0, occluded_boundary_arcs = 0;
  bool envelope_ran = false;         // the effective Minkowski envelope was computed
  bool pairwise_ran = false;         // convex decomposition was computed
  double seconds = 0;
};

struct SurfaceMaps {
  DirectionSet lvm;                  // LVM(S + N_S)
  std::optional<DirectionSet> gvm;   // set when known exactly
  GvmStatus status = GvmStatus::kGlobalOcclusionNotComputed;
  SurfaceStatistics statistics;
};

// A concave region or a feature with its maps.
struct Surface {
  enum class Kind { kRegion, kFeature };
  Kind kind = Kind::kFeature;
  uint32_t id = 0;
  std::string name;                  // features: the user's group name or "F<id>"
  std::vector<uint32_t> faces;       // input face indices, ascending
  bool on_hull = false;              // features: every face is a hull facet
  bool automatic = false;            // features: found by the feature angle (not a group or B-rep face)
  int32_t region = -1;               // features: the concave region, -1 on the hull
  bool is_void = false;              // regions: bounds an internal void
  std::vector<uint32_t> features;    // regions: the features inside
  // Every triangle lies in one plane with one orientation: its outward normal, exactly.
  std::optional<Direction> planar_normal;
  std::optional<CadFace> cad_face;   // features of a STEP part: the B-rep face they are
  std::optional<CadHole> cad_hole;   // ... or the hole (StepOptions::group_holes)
  SurfaceMaps maps;
};

struct PartSummary {
  std::string source;
  uint32_t input_faces = 0, input_vertices = 0, triangles = 0;
  uint32_t shells = 0, void_shells = 0, hull_faces = 0;
  Point3 box_min, box_max;
  // STEP parts: the file's declared length unit (coordinates are mm), the B-rep faces and
  // the tessellation's deflections as applied.
  std::string file_unit;
  uint32_t cad_faces = 0;
  double linear_deflection = 0, angular_deflection_degrees = 0;
  StepTessellation tessellation;
};

struct AnalysisTiming {
  double read = 0, validate = 0, part = 0, visibility = 0, total = 0;
  uint32_t threads = 0;
};

class Analysis {
 public:
  const PartSummary& part() const;
  // The validated solid the maps were computed on, at the file's scale (the engine works on
  // it scaled by a power of two, see docs/exactness.md), input face numbering: to draw it.
  const SolidMesh& mesh() const;
  const std::vector<Surface>& regions() const;
  const std::vector<Surface>& features() const;
  const AnalysisTiming& timing() const;
  const v1::AnalyzeOptions& options() const;
  uint32_t surfaces_with_potential_occluders() const;

  // The surface made of any set of input faces, with its maps computed now as for a
  // feature, with the analysis's options (to plan an unreachable feature piece by piece);
  // its id and name are left unset. kInvalidArgument names a face not in the part.
  // Called inside a TBB task group that gets cancelled (the planner's, on a stop request),
  // it stops within milliseconds with kCancelled.
  StatusOr<Surface> surface_of(std::span<const uint32_t> faces) const;
  // The input faces that rays from the given faces along u meet from the front (they
  // enter the solid there), decided exactly; u should be in the faces' LVM(S + N_S).
  // Empty when the calling TBB task group is cancelled.
  std::vector<uint32_t> blocking_faces(std::span<const uint32_t> faces, const Direction& u) const;
  // LVM(S) of the given faces alone, without their neighbouring occluders: the directions
  // every one of their triangles faces (the intersection of the closed hemispheres of their
  // normals), exactly. Empty when the faces have no common direction: an undercut of their
  // own shape. kInvalidArgument names a face not in the part.
  StatusOr<DirectionSet> own_lvm(std::span<const uint32_t> faces) const;
  // N_S of the given faces as input faces (faces outside S beside it across a concave edge,
  // or covering a vertex of S from behind: Part::neighbor_occluders), ascending.
  std::vector<uint32_t> neighbor_faces(std::span<const uint32_t> faces) const;
  // The given faces in maximal edge-connected pieces that lie in one plane with one
  // orientation (a triangulated CAD face is one piece; each facet of a curved face is
  // its own), each ascending, in order of their smallest face.
  std::vector<std::vector<uint32_t>> planar_pieces(std::span<const uint32_t> faces) const;
  // How visible_pieces grows a piece from its seed (the largest planar piece left).
  enum class Growth {
    kCommonDirection,  // while some direction sees it all: the fewest pieces
    kAlongSeedNormal,  // while the seed's normal does: pieces cut from one side each
  };
  // The given faces in edge-connected pieces each of which has a direction of its own
  // (LVM(S + N_S) is not empty), grown face by face while the hemispheres of the normals
  // of their faces and N_S keep one (decided exactly): a flat top with the fillets and
  // walls it was joined to comes apart where no one direction sees them all. Each
  // ascending, in order of their smallest face; empty when the calling TBB task group is
  // cancelled or a face is not in the part.
  std::vector<std::vector<uint32_t>> visible_pieces(std::span<const uint32_t> faces,
                                                    Growth growth = Growth::kCommonDirection) const;

  struct Impl;
  explicit Analysis(std::shared_ptr<const Impl> impl);

 private:
  std::shared_ptr<const Impl> impl_;  // immutable: copies share it
};

// kInvalidArgument for an unreadable or invalid part or face groups, kNotFound for a
// file that cannot be opened, kResourceExhausted above max_faces, kCancelled on a stop
// request or when progress returns false.
// Checks the options; the error names the field and the value (analyze() checks them too).
Status validate(const v1::AnalyzeOptions& options);

StatusOr<Analysis> analyze(const AnalyzeRequest& request);

// The validated solid analyze() would work on for this request -- a mesh, or a STEP part
// tessellated the same way -- without any maps: to draw a result computed elsewhere.
StatusOr<SolidMesh> load_part_solid(const AnalyzeRequest& request);

}  // namespace gvm
