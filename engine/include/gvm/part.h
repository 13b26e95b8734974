// Part analysis (paper Sec. 2-3): hull facets, concave regions, features, and for any
// surface S its neighboring occluders N_S and potential occluders O_S.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "gvm/mesh.h"
#include "gvm/status.h"

namespace gvm {

// A maximal edge-connected set of non-hull triangles.
struct ConcaveRegion {
  uint32_t id = 0;
  std::vector<uint32_t> triangles;   // ascending
  bool is_void = false;              // lies on an internal void shell
};

// A patch a CAD user would call a face: given by the user, or found automatically.
struct Feature {
  uint32_t id = 0;
  std::string name;
  std::vector<uint32_t> triangles;   // ascending
  int32_t region = -1;               // concave region id, -1 when every triangle is on the hull
  bool on_hull = false;
  bool automatic = false;            // found by the feature angle, not given as a group
};

struct PartOptions {
  // Automatic features: normals may turn by less than this across an edge inside one
  // feature. Features never straddle a hull/non-hull or region boundary.
  double feature_angle_degrees = 30.0;
  // User features (named lists of input face indices); when set, they replace the
  // automatic ones. Faces not in any group become features of their own.
  std::map<std::string, std::vector<uint32_t>> face_groups;
};

// Occluders of a surface S (sets of triangles, ascending).
struct Occluders {
  std::vector<uint32_t> neighbor;    // N_S
  std::vector<uint32_t> potential;   // O_S
};

class Part {
 public:
  static StatusOr<Part> analyze(SolidMesh mesh, const PartOptions& options);

  Part(Part&&) noexcept;
  Part& operator=(Part&&) noexcept;
  ~Part();

  const SolidMesh& mesh() const;
  bool is_hull(uint32_t triangle) const;
  int32_t region_of(uint32_t triangle) const;  // -1 for hull triangles
  const std::vector<ConcaveRegion>& regions() const;
  const std::vector<Feature>& features() const;

  // N_S: triangles outside S sharing a concave edge with S, or incident to a vertex v of S
  // with every edge at v on their closed back side (they cover the whole open half-space
  // behind them at v, so rays from v into it are blocked at once).
  std::vector<uint32_t> neighbor_occluders(std::span<const uint32_t> s) const;

  // O_S: non-hull triangles F' outside S + N_S, in the concave region of some F_S in S,
  // with F_S partly in the open positive half-space of F' and F' partly in the closed
  // positive half-space of F_S, and for which `may_be_front_hit(F')` holds (the caller
  // decides condition (3) of Def. 5 from LVM(S + N_S): some direction of it meets F' from
  // the front). Faces touching S are not excluded: they may occlude.
  std::vector<uint32_t> potential_occluders(
      std::span<const uint32_t> s, std::span<const uint32_t> neighbor,
      const std::function<bool(uint32_t)>& may_be_front_hit) const;

 private:
  struct Impl;
  explicit Part(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

// Reads a JSON file of named face groups: {"name": [face, ...], ...}. Every index must be
// an input face of a part with `face_count` faces; a face may be in one group only.
StatusOr<std::map<std::string, std::vector<uint32_t>>> read_face_groups(
    const std::string& path, uint32_t face_count);

// The same from the JSON text itself; `source` names it in messages (as the path does).
StatusOr<std::map<std::string, std::vector<uint32_t>>> parse_face_groups(
    std::string_view json, uint32_t face_count, const std::string& source);

}  // namespace gvm
