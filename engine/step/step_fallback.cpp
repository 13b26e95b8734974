// A planar face BRepMesh cannot triangulate (typically a sliver, like face 73 of
// trj10_b2-oc-214.stp, 0.004 x 0.00005 mm) becomes one polygon of its boundary points:
// the points its neighbours already put on the shared edges, so the mesh stays closed.
// build_solid then checks the polygon (exactly planar, simple) and splits it into
// triangles by ear clipping.
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Wire.hxx>

#include <algorithm>
#include <unordered_set>

#include "step/step_internal.h"

namespace gvm::step_internal {
namespace {

// The welded points along the edge, in the order of its parameter: the neighbours'
// discretisation when there is one, else the two vertices.
std::vector<uint32_t> edge_chain(const TopoDS_Edge& edge, Weld& weld) {
  const std::vector<uint32_t>& points = weld.edge_points[weld.edges.FindIndex(edge) - 1];
  if (!points.empty()) return points;
  TopoDS_Vertex first, last;
  TopExp::Vertices(TopoDS::Edge(edge.Oriented(TopAbs_FORWARD)), first, last);
  if (first.IsNull() || last.IsNull()) return {};
  return {weld.vertex(first, BRep_Tool::Pnt(first)), weld.vertex(last, BRep_Tool::Pnt(last))};
}

}  // namespace

StatusOr<std::vector<uint32_t>> planar_boundary(const TopoDS_Face& face, const CadFace& cad,
                                                Weld& weld, const std::string& why) {
  auto reject = [&](const std::string& what) {
    return InvalidArgument(weld.mesh->source + ": " + face_label(face, cad.index) +
                           " cannot be triangulated: " + why + "; " + what);
  };
  if (cad.type != CadSurfaceType::kPlane)
    return reject("only a planar face can be replaced by the polygon of its boundary");
  TopTools_IndexedMapOfShape wires;
  TopExp::MapShapes(face, TopAbs_WIRE, wires);
  if (wires.Extent() != 1)
    return reject("it has " + std::to_string(wires.Extent()) +
                  " wires, so its boundary is not one polygon");

  // In the face's own definition the outer wire runs counter-clockwise around the surface
  // normal (the face lies to the left of its edges).
  const TopoDS_Face forward = TopoDS::Face(face.Oriented(TopAbs_FORWARD));
  TopExp_Explorer wire(forward, TopAbs_WIRE);
  std::vector<uint32_t> polygon;
  for (BRepTools_WireExplorer ex(TopoDS::Wire(wire.Current()), forward); ex.More(); ex.Next()) {
    const TopoDS_Edge& edge = ex.Current();
    if (BRep_Tool::Degenerated(edge)) continue;
    std::vector<uint32_t> chain = edge_chain(edge, weld);
    if (chain.empty()) return reject("an edge of its boundary has no vertices");
    if (ex.Orientation() == TopAbs_REVERSED) std::reverse(chain.begin(), chain.end());
    for (uint32_t raw : chain) {
      const uint32_t p = weld.find(raw);
      if (polygon.empty() || polygon.back() != p) polygon.push_back(p);
    }
  }
  if (polygon.size() > 1 && polygon.front() == polygon.back()) polygon.pop_back();
  std::unordered_set<uint32_t> seen;
  for (uint32_t p : polygon)
    if (!seen.insert(p).second)
      return reject("its boundary passes twice through mesh point " + std::to_string(p));
  if (polygon.size() < 3)
    return reject("its boundary has only " + std::to_string(polygon.size()) + " distinct points");
  if (face.Orientation() == TopAbs_REVERSED) std::reverse(polygon.begin(), polygon.end());
  return polygon;
}

}  // namespace gvm::step_internal
