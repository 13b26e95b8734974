// Tessellation with BRepMesh and the topological weld of the face triangulations (see
// gvm/step.h for why the weld follows the topology).
//
// BRepMesh discretises every edge once and gives each face using the edge a
// Poly_PolygonOnTriangulation: the triangulation nodes lying on the edge, in the order of
// the edge's parameter. Node k of that polygon is the same point for every face, so it is
// keyed by (edge, k); its end nodes are the edge's vertices. A seam edge appears twice in
// its face with two polygons (one per side of the parameter seam) that share the keys; a
// degenerated edge (cone apex, sphere pole) collapses to its single vertex. When BRepMesh
// gives both vertices of a tiny edge one node (trj10_b2-oc-214.stp has an edge 6.5e-8 long),
// their points are merged, again following the triangulation rather than coordinates.
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <IMeshData_Status.hxx>
#include <Poly_PolygonOnTriangulation.hxx>
#include <Poly_Triangulation.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>

#include <algorithm>
#include <limits>
#include <utility>

#include "step/step_internal.h"

namespace gvm::step_internal {

uint32_t Weld::add(const gp_Pnt& p) {
  mesh->points.push_back({p.X(), p.Y(), p.Z()});
  parent.push_back(uint32_t(parent.size()));
  return parent.back();
}

uint32_t Weld::find(uint32_t p) {
  while (parent[p] != p) p = parent[p] = parent[parent[p]];
  return p;
}

void Weld::unite(uint32_t a, uint32_t b) {
  a = find(a), b = find(b);
  if (a != b) parent[std::max(a, b)] = std::min(a, b);
}

uint32_t Weld::vertex(const TopoDS_Vertex& v, const gp_Pnt& p) {
  uint32_t& id = vertex_point[vertices.FindIndex(v) - 1];
  if (id == kNone) id = add(p);
  return id;
}

namespace {

constexpr uint32_t kNone = Weld::kNone;

// A face's triangulation and the location that places it.
struct FaceMesh {
  uint32_t index;
  Handle(Poly_Triangulation) tri;
  TopLoc_Location loc;
};

std::string S(size_t v) { return std::to_string(v); }

// Gives every node of the polygon of `edge` on the face's triangulation its welded point:
// node_point[n - 1] is the point of triangulation node n.
Status weld_edge(const TopoDS_Edge& edge, const FaceMesh& fm, Weld& weld,
                 std::vector<uint32_t>& node_point) {
  const std::string& src = weld.mesh->source;
  const int e = weld.edges.FindIndex(edge) - 1;
  const Handle(Poly_PolygonOnTriangulation)& poly = BRep_Tool::PolygonOnTriangulation(edge, fm.tri, fm.loc);
  if (poly.IsNull() || poly->NbNodes() < 2)
    return InvalidArgument(src + ": BRepMesh triangulated face " + S(fm.index) +
                           " but left its edge " + S(e) + " without a discretisation");
  TopoDS_Vertex first, last;
  TopExp::Vertices(TopoDS::Edge(edge.Oriented(TopAbs_FORWARD)), first, last);
  if (first.IsNull() || last.IsNull())
    return InvalidArgument(src + ": edge " + S(e) + " of face " + S(fm.index) + " has no end vertex");
  const size_t n = size_t(poly->NbNodes());
  std::vector<uint32_t>& points = weld.edge_points[e];
  if (points.empty()) points.assign(n, kNone);
  std::vector<double>& params = weld.edge_params[e];
  if (params.empty()) params.assign(n, std::numeric_limits<double>::quiet_NaN());
  if (points.size() != n)
    return Internal(src + ": edge " + S(e) + " has " + S(n) + " discretisation nodes on face " +
                    S(fm.index) + " but " + S(points.size()) + " on a neighbouring face");
  // Nodes are stored along the parameter; read them that way even if a polygon runs backwards.
  const bool backwards = poly->HasParameters() && poly->Parameter(1) > poly->Parameter(int(n));
  const bool degenerated = BRep_Tool::Degenerated(edge);
  const gp_Trsf place = fm.loc.Transformation();
  for (size_t k = 0; k < n; ++k) {
    const int node = poly->Node(backwards ? int(n - k) : int(k + 1));
    if (poly->HasParameters()) params[k] = poly->Parameter(backwards ? int(n - k) : int(k + 1));
    uint32_t& id = points[k];
    if (id == kNone) {
      const gp_Pnt p = fm.tri->Node(node).Transformed(place);
      if (degenerated || k == 0) id = weld.vertex(first, p);
      else if (k + 1 == n) id = weld.vertex(last, p);
      else id = weld.add(p);
    }
    // A node already on another edge point: BRepMesh collapsed a tiny edge into one node,
    // and the mesh follows it.
    uint32_t& mapped = node_point[node - 1];
    if (mapped != kNone) weld.unite(mapped, id);
    else mapped = id;
  }
  return Status::Ok();
}

// The face's triangles over welded points, counter-clockwise seen from outside.
Status weld_face(const TopoDS_Face& face, const FaceMesh& fm, Weld& weld,
                 std::vector<std::vector<uint32_t>>& polygons) {
  std::vector<uint32_t> node_point(size_t(fm.tri->NbNodes()), kNone);
  // The edges with their orientation in the face's own definition, which is what selects
  // the polygon of each side of a seam.
  for (TopExp_Explorer ex(face.Oriented(TopAbs_FORWARD), TopAbs_EDGE); ex.More(); ex.Next())
    if (Status s = weld_edge(TopoDS::Edge(ex.Current()), fm, weld, node_point); !s.ok()) return s;
  const gp_Trsf place = fm.loc.Transformation();
  for (size_t i = 0; i < node_point.size(); ++i)
    if (node_point[i] == kNone) node_point[i] = weld.add(fm.tri->Node(int(i + 1)).Transformed(place));
  // Triangles follow the surface's parameterisation; a reversed face points the other way.
  const bool flip = face.Orientation() == TopAbs_REVERSED;
  for (int t = 1; t <= fm.tri->NbTriangles(); ++t) {
    int a, b, c;
    fm.tri->Triangle(t).Get(a, b, c);
    if (flip) std::swap(b, c);
    polygons.push_back({node_point[a - 1], node_point[b - 1], node_point[c - 1]});
  }
  return Status::Ok();
}

// Moves the polygons into the mesh over the merged points, numbered in order of first
// index. Polygons that collapse (two equal corners of a triangle: at a degenerated edge or
// a merged tiny edge) are dropped.
void emit(std::vector<std::vector<std::vector<uint32_t>>>& per_face, Weld& weld, StepPart& part) {
  std::vector<uint32_t> index(weld.parent.size(), kNone);
  std::vector<Point3> points;
  for (uint32_t p = 0; p < weld.parent.size(); ++p)
    if (weld.find(p) == p) {
      index[p] = uint32_t(points.size());
      points.push_back(part.mesh.points[p]);
    }
  part.mesh.points = std::move(points);
  for (uint32_t f = 0; f < per_face.size(); ++f)
    for (auto& polygon : per_face[f]) {
      std::vector<uint32_t> merged;
      for (uint32_t p : polygon) {
        uint32_t q = index[weld.find(p)];
        if (merged.empty() || merged.back() != q) merged.push_back(q);
      }
      if (merged.size() > 1 && merged.front() == merged.back()) merged.pop_back();
      if (merged.size() < 3) continue;
      part.mesh.faces.push_back(std::move(merged));
      part.face_cad.push_back(f);
    }
}

std::string mesher_status(int flags) {
  std::string s;
  auto add = [&](int bit, const char* name) {
    if (flags & bit) s += (s.empty() ? "" : ", ") + std::string(name);
  };
  add(IMeshData_OpenWire, "OpenWire");
  add(IMeshData_SelfIntersectingWire, "SelfIntersectingWire");
  add(IMeshData_Failure, "Failure");
  add(IMeshData_ReMesh, "ReMesh");
  add(IMeshData_UnorientedWire, "UnorientedWire");
  add(IMeshData_TooFewPoints, "TooFewPoints");
  return s.empty() ? "no status" : s;
}

}  // namespace

Status tessellate(const TopoDS_Shape& solid, double linear, double angular_radians, uint32_t max_triangles,
                  bool faithful, const std::stop_token& stop, StepPart& part) {
  // A file may carry its own triangulation; ours must come from one BRepMesh run.
  BRepTools::Clean(solid);
  IMeshTools_Parameters parameters;
  parameters.Deflection = linear;
  parameters.Angle = angular_radians;
  parameters.InParallel = true;
  Handle(StopOnRequest) progress = new StopOnRequest(stop);
  BRepMesh_IncrementalMesh mesher(solid, parameters, progress->Start());
  if (stop.stop_requested()) return cancelled(part.mesh.source);
  const std::string why = "BRepMesh left it without triangles (mesher status: " +
                          mesher_status(mesher.GetStatusFlags()) + ")";
  Weld weld;
  weld.mesh = &part.mesh;
  TopExp::MapShapes(solid, TopAbs_EDGE, weld.edges);
  TopExp::MapShapes(solid, TopAbs_VERTEX, weld.vertices);
  weld.vertex_point.assign(size_t(weld.vertices.Extent()), kNone);
  weld.edge_points.resize(size_t(weld.edges.Extent()));
  weld.edge_params.resize(size_t(weld.edges.Extent()));
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(solid, TopAbs_FACE, faces);

  if (max_triangles > 0) {
    uint64_t triangles = 0;
    for (int i = 1; i <= faces.Extent(); ++i) {
      TopLoc_Location loc;
      const Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(TopoDS::Face(faces(i)), loc);
      triangles += tri.IsNull() ? 1 : uint64_t(std::max(tri->NbTriangles(), 1));
    }
    if (triangles > max_triangles) {
      return ResourceExhausted(part.mesh.source + ": the tessellation has " + std::to_string(triangles) +
                               " triangles, more than the limit of " + std::to_string(max_triangles) +
                               " faces (a larger linear or angular deflection gives fewer)");
    }
  }
  std::vector<std::vector<std::vector<uint32_t>>> per_face(size_t(faces.Extent()));
  std::vector<uint32_t> untriangulated;
  for (int i = 1; i <= faces.Extent(); ++i) {
    const TopoDS_Face& face = TopoDS::Face(faces(i));
    FaceMesh fm{uint32_t(i - 1), nullptr, {}};
    fm.tri = BRep_Tool::Triangulation(face, fm.loc);
    if (fm.tri.IsNull() || fm.tri->NbTriangles() == 0) {
      untriangulated.push_back(fm.index);
      continue;
    }
    if (Status s = weld_face(face, fm, weld, per_face[fm.index]); !s.ok()) return s;
  }
  if (faithful) {
    if (Status s = make_faithful(solid, faces, linear, weld, per_face, part); !s.ok()) return s;
  }
  // After all meshed faces, so that the boundary takes the neighbours' edge points.
  for (uint32_t f : untriangulated) {
    if (!per_face[f].empty()) continue;  // the faithful tessellation triangulated it
    auto polygon = planar_boundary(TopoDS::Face(faces(int(f) + 1)), part.cad_faces[f], weld, why);
    if (!polygon.ok()) return polygon.status();
    per_face[f].push_back(std::move(*polygon));
  }
  emit(per_face, weld, part);
  if (max_triangles > 0 && part.mesh.faces.size() > max_triangles) {
    return ResourceExhausted(part.mesh.source + ": the tessellation has " + std::to_string(part.mesh.faces.size()) +
                             " triangles, more than the limit of " + std::to_string(max_triangles) +
                             " faces (a larger linear or angular deflection gives fewer)");
  }
  return Status::Ok();
}

}  // namespace gvm::step_internal
