// Reading a STEP file (AP203/AP214/AP242 B-rep) into a closed triangle mesh with one record
// per B-rep face.
//
// Why a topological weld: the mesh must be closed for build_solid, and welding nodes by
// rounded coordinates either misses points (two faces compute the same edge node with
// different roundings) or merges distinct ones (sliver faces, small fillets). Open CASCADE
// already knows which triangulation nodes are the same point -- the B-rep vertices and the
// shared discretisation of every edge -- so the weld follows the topology and never
// compares coordinates.
//
// Isolation: Open CASCADE is not hardened against hostile input, so the reading runs in a
// short-lived worker process (gvm-step-worker, found beside the program, then where the
// build put it), under limits of memory and time, with no descriptors but its pipes; the
// mesh and the face records come back as a protobuf message (step_worker.proto).
// read_step may be called from several threads: each call has its own worker.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <stop_token>
#include <string_view>
#include <utility>
#include <vector>

#include "gvm/mesh.h"
#include "gvm/status.h"

namespace gvm {

// The geometry under a B-rep face, as Open CASCADE classifies it (BRepAdaptor_Surface).
enum class CadSurfaceType {
  kPlane, kCylinder, kCone, kSphere, kTorus, kBezier, kBSpline, kRevolution, kExtrusion,
  kOffset, kOther
};

// "plane", "cylinder", "cone", "sphere", "torus", "bezier", "bspline", "revolution",
// "extrusion", "offset", "other".
std::string_view name_of(CadSurfaceType t);

// One B-rep face of the solid.
struct CadFace {
  uint32_t index = 0;  // 0-based, in TopExp::MapShapes(shape, TopAbs_FACE) order
  CadSurfaceType type = CadSurfaceType::kOther;
  // Plane: the face's outward normal (face orientation applied); cylinder, cone: the axis
  // direction (as OCCT gives it, gp_Ax1 of the surface's position, with location applied);
  // unset otherwise.
  std::optional<std::array<double, 3>> axis;
  std::optional<std::array<double, 3>> location;  // a point of the plane / on the axis
  double radius = 0;                               // cylinder radius, cone reference radius
};

// Faces a machinist calls one hole (walls, countersink or counterbore, drill point or flat
// bottom), found from the B-rep's topology and axes (step_holes.cpp says the rule).
struct CadHole {
  std::vector<uint32_t> faces;  // B-rep face indices, ascending, at least two
  // Of its narrowest cylinder wall, as the B-rep gives them.
  std::array<double, 3> axis{}, location{};
  double radius = 0;
};

// A direction of the B-rep (a plane's normal, a cylinder's or extrusion's axis) and the
// integer vector the faithful tessellation keeps exactly for it.
struct ExactDirection {
  std::array<double, 3> brep{};    // as the B-rep gives it (unit; the class's first face)
  std::array<int64_t, 3> exact{};  // the facets' relations hold for this vector exactly
  double angle = 0;                // radians between the two lines (largest over the class)
  uint32_t faces = 0;              // B-rep faces with this normal or axis
};

// A relation of the B-rep the faithful tessellation could not keep exactly: points of a
// face off its plane, or off their ruling's line (a point where faces of two frames meet).
struct InexactRelation {
  uint32_t cad_face = 0;
  bool ruling = false;
  uint32_t points = 0;
  double distance_mm = 0;  // the largest distance of one of them
};

// What the tessellation kept of the B-rep (StepOptions::faithful).
struct StepTessellation {
  bool faithful = false;
  std::vector<ExactDirection> directions;
  double max_direction_angle = 0;      // radians, over `directions`
  double max_node_displacement = 0;    // mm: mesh point from its place on the B-rep
  double grid = 0;                     // mm: the points are integers times this
  uint32_t inserted_points = 0;        // edge points added so that rulings meet both rims
  uint32_t ruled_faces = 0;            // meshed along their rulings
  std::vector<InexactRelation> inexact;
  // Ruled faces left as BRepMesh triangulated them, and why.
  std::vector<std::pair<uint32_t, std::string>> brepmesh_faces;
};

struct StepOptions {
  double linear_deflection = 0;  // mm; 0: 0.1% of the bounding box diagonal
  double angular_deflection_degrees = 10;
  int solid = -1;  // -1: the file must hold exactly one solid; else the 0-based solid to take
  bool group_holes = false;  // find StepPart::holes
  // 0: no limit; else more triangles fail with kResourceExhausted before the mesh is built:
  // more B-rep faces than that (each gives a triangle at least) before meshing, more
  // triangles from BRepMesh before they are welded.
  uint32_t max_triangles = 0;
  // The faithful tessellation (docs/step.md): the B-rep's directions kept exactly
  // (hole walls parallel to their axes, parallel planes parallel). false: BRepMesh's
  // triangles as they are.
  bool faithful = true;
  // The reading runs in a worker process (gvm-step-worker) under these limits: its
  // address space (0: 1 GiB plus 256 times the file's size, at least 2 GiB) and its time
  // (0: 600 s of CPU, and as long in wall time). A worker over a limit, killed by a
  // signal or answering nonsense fails this part only, with the reason.
  uint64_t max_memory_bytes = 0;
  double max_seconds = 0;
  // A stop request ends the reading (kCancelled) within about 50 ms: the worker is killed.
  std::stop_token stop;
};

struct StepPart {
  // Triangles counter-clockwise seen from outside, in mm; mesh.groups left empty. A planar
  // face Open CASCADE cannot triangulate may appear as one polygon of its boundary points
  // (build_solid splits it into triangles).
  RawMesh mesh;
  std::vector<uint32_t> face_cad;   // per mesh face: the index of its CAD face
  std::vector<CadFace> cad_faces;   // every B-rep face of the solid
  std::vector<CadHole> holes;       // with StepOptions::group_holes, in order of first face
  std::string file_unit;            // the length unit the file declares ("millimetre", "metre", "inch", ...)
  double linear_deflection = 0, angular_deflection_degrees = 0;  // as applied
  StepTessellation tessellation;
};

// Reads the file, checks that it holds the wanted solid and that the solid is a valid
// B-rep, tessellates it and welds the triangulation by topology -- in a worker process,
// so that Open CASCADE crashing or looping on a file costs this call only. Fails with
// kNotFound when the file does not exist, kInvalidArgument (message naming the file and
// the problem: not STEP, no solid, several solids, invalid B-rep face, face that cannot
// be triangulated, the reader crashed on it) otherwise, kResourceExhausted over a limit,
// kCancelled on a stop request, kInternal when the worker cannot be started.
StatusOr<StepPart> read_step(const std::string& path, const StepOptions& options);

// The same on bytes in memory (STEPControl_Reader::ReadStream); `source` names the part in
// messages.
StatusOr<StepPart> read_step(std::string_view bytes, const StepOptions& options,
                             const std::string& source);

// One face group per B-rep face, named "face 12 (cylinder)" (the features of a STEP part),
// except that the faces of each of part.holes form one group, "hole 3 (faces 12+13+40)".
std::map<std::string, std::vector<uint32_t>> brep_face_groups(const StepPart& part);

}  // namespace gvm
