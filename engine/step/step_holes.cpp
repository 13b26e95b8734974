// Holes of a B-rep: the faces a machinist calls one hole -- the pieces of its wall, a
// countersink or counterbore, a drill point or flat bottom -- proposed as one feature.
//
// A CAD proposal, not a geometric decision: the GVMs stay exact whatever the grouping. The
// rule is kept simple enough to state in docs/step.md:
//   1. a hole face is a cylinder or cone whose material lies outside it (its outward
//      normal points towards the axis);
//   2. hole faces that share an edge and have the same axis line are one hole;
//   3. a plane normal to that axis whose every edge is shared with that hole's faces (a
//      flat bottom, a counterbore's step) joins it.
// "The same axis" compares Open CASCADE's doubles with tolerances: kAngular radians between
// the directions, and the edge's tolerance (at least kLinear mm) between the lines.
#include <BRepAdaptor_Surface.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Ax1.hxx>
#include <gp_Lin.hxx>
#include <gp_Vec.hxx>

#include <algorithm>
#include <map>

#include "sphere/union_find.h"
#include "step/step_internal.h"

namespace gvm::step_internal {
namespace {

constexpr double kAngular = 1e-6;  // radians
constexpr double kLinear = 1e-6;   // mm

// The surface normal at the middle of the face's parameter box, pointing out of the
// material (face orientation applied).
std::optional<gp_Dir> outward_normal(const TopoDS_Face& face, const BRepAdaptor_Surface& s, gp_Pnt& at) {
  double u0, u1, v0, v1;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  gp_Vec du, dv;
  s.D1(0.5 * (u0 + u1), 0.5 * (v0 + v1), at, du, dv);
  gp_Vec n = du.Crossed(dv);
  if (n.Magnitude() == 0) return std::nullopt;
  if (face.Orientation() == TopAbs_REVERSED) n.Reverse();
  return gp_Dir(n);
}

// The axis of a cylinder or cone face whose material lies outside it.
std::optional<gp_Ax1> hole_axis(const TopoDS_Face& face) {
  BRepAdaptor_Surface s(face, /*R=*/false);
  gp_Ax1 axis;
  if (s.GetType() == GeomAbs_Cylinder) axis = s.Cylinder().Axis();
  else if (s.GetType() == GeomAbs_Cone) axis = s.Cone().Axis();
  else return std::nullopt;
  gp_Pnt p;
  std::optional<gp_Dir> n = outward_normal(face, s, p);
  if (!n) return std::nullopt;
  // From the axis out to the face's point: a hole's outward normal points back in.
  const gp_Vec along(axis.Direction());
  gp_Vec radial(axis.Location(), p);
  radial -= along * radial.Dot(along);
  if (radial.Magnitude() == 0 || gp_Vec(*n).Dot(radial) >= 0) return std::nullopt;
  return axis;
}

bool same_line(const gp_Ax1& a, const gp_Ax1& b, double linear) {
  if (!a.IsParallel(b, kAngular)) return false;
  return gp_Lin(a).Distance(b.Location()) <= linear && gp_Lin(b).Distance(a.Location()) <= linear;
}

bool normal_to(const TopoDS_Face& face, const gp_Ax1& axis) {
  BRepAdaptor_Surface s(face, /*R=*/false);
  if (s.GetType() != GeomAbs_Plane) return false;
  return s.Plane().Axis().IsParallel(axis, kAngular);
}

// The faces of `faces` (0-based) on both sides of each edge, seams and degenerated edges
// left out.
std::vector<std::pair<int, int>> face_pairs(const TopoDS_Shape& solid, const TopTools_IndexedMapOfShape& faces,
                                            std::vector<double>& tolerance) {
  TopTools_IndexedDataMapOfShapeListOfShape edge_faces;
  TopExp::MapShapesAndAncestors(solid, TopAbs_EDGE, TopAbs_FACE, edge_faces);
  std::vector<std::pair<int, int>> pairs;
  for (int e = 1; e <= edge_faces.Extent(); ++e) {
    const TopoDS_Edge& edge = TopoDS::Edge(edge_faces.FindKey(e));
    if (BRep_Tool::Degenerated(edge)) continue;
    std::vector<int> around;
    for (const TopoDS_Shape& f : edge_faces(e)) {
      int i = faces.FindIndex(f) - 1;
      if (i >= 0 && std::find(around.begin(), around.end(), i) == around.end()) around.push_back(i);
    }
    if (around.size() != 2) continue;
    pairs.emplace_back(around[0], around[1]);
    tolerance.push_back(std::max(kLinear, BRep_Tool::Tolerance(edge)));
  }
  return pairs;
}

// Rule 3: for each plane whose every neighbour is a wall of one axis line (so a
// counterbore's step joins both its walls), those walls; empty for every other face.
std::vector<std::vector<int>> closing_planes(const TopTools_IndexedMapOfShape& faces,
                                             const std::vector<std::optional<gp_Ax1>>& axis,
                                             const std::vector<std::pair<int, int>>& pairs,
                                             const std::vector<double>& tolerance) {
  std::vector<std::vector<int>> walls(axis.size());
  std::vector<bool> refused(axis.size(), false);
  for (size_t k = 0; k < pairs.size(); ++k) {
    auto [a, b] = pairs[k];
    for (auto [plane, wall] : {std::pair{a, b}, std::pair{b, a}}) {
      if (axis[plane] || refused[plane]) continue;
      const std::vector<int>& seen = walls[plane];
      refused[plane] = !axis[wall] || !normal_to(TopoDS::Face(faces(plane + 1)), *axis[wall]) ||
                       (!seen.empty() && !same_line(*axis[seen.front()], *axis[wall], tolerance[k]));
      walls[plane].push_back(wall);
    }
  }
  for (size_t i = 0; i < walls.size(); ++i)
    if (refused[i]) walls[i].clear();
  return walls;
}

}  // namespace

std::vector<CadHole> find_holes(const TopoDS_Shape& solid, const TopTools_IndexedMapOfShape& faces,
                                const std::vector<CadFace>& cad) {
  const int n = faces.Extent();
  std::vector<std::optional<gp_Ax1>> axis(n);
  for (int i = 0; i < n; ++i) axis[i] = hole_axis(TopoDS::Face(faces(i + 1)));
  std::vector<double> tolerance;
  const std::vector<std::pair<int, int>> pairs = face_pairs(solid, faces, tolerance);

  sphere::UnionFind holes(n);  // rule 2
  for (size_t k = 0; k < pairs.size(); ++k) {
    auto [a, b] = pairs[k];
    if (axis[a] && axis[b] && same_line(*axis[a], *axis[b], tolerance[k])) holes.unite(a, b);
  }
  const std::vector<std::vector<int>> closed = closing_planes(faces, axis, pairs, tolerance);
  for (int i = 0; i < n; ++i)
    for (int wall : closed[i]) holes.unite(i, wall);

  std::map<int, CadHole> by_root;
  for (int i = 0; i < n; ++i) {
    if (!axis[i] && closed[i].empty()) continue;
    CadHole& h = by_root[holes.find(i)];
    h.faces.push_back(uint32_t(i));
    if (cad[i].type == CadSurfaceType::kCylinder && (h.radius == 0 || cad[i].radius < h.radius)) {
      h.radius = cad[i].radius;
      h.axis = *cad[i].axis;
      h.location = *cad[i].location;
    }
  }
  std::vector<CadHole> out;
  for (auto& [root, h] : by_root)
    if (h.faces.size() >= 2 && h.radius > 0) out.push_back(std::move(h));  // one face is one feature already
  std::sort(out.begin(), out.end(), [](const CadHole& a, const CadHole& b) { return a.faces[0] < b.faces[0]; });
  return out;
}

}  // namespace gvm::step_internal
