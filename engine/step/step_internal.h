// Internals of the STEP reader, shared by its source files. Open CASCADE types stay here
// and out of gvm/step.h.
#pragma once

#include <Message_ProgressIndicator.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <TopoDS_Vertex.hxx>
#include <gp_Pnt.hxx>

#include <cstdint>
#include <string>
#include <stop_token>
#include <string_view>
#include <vector>

#include "gvm/step.h"

namespace gvm::step_internal {

// What the STEP translation gives: every root shape, in one compound.
struct Translated {
  TopoDS_Shape shape;
  std::string file_unit;  // lower case, "" when the file declares none
  int damaged_entities = 0;  // entities with syntax errors or references to missing ones
};

// Open CASCADE's progress indicator that asks it to stop once `stop` is requested: its
// translation and meshing poll UserBreak() (step_reader.cpp).
class StopOnRequest : public Message_ProgressIndicator {
 public:
  explicit StopOnRequest(std::stop_token stop) : stop_(std::move(stop)) {}
  Standard_Boolean UserBreak() override { return stop_.stop_requested(); }
  void Show(const Message_ProgressScope&, const Standard_Boolean) override {}

 private:
  std::stop_token stop_;
};

// "SOURCE: reading cancelled", kCancelled (step_reader.cpp).
Status cancelled(const std::string& source);

// Parses the bytes and transfers all roots, lengths in mm (step_reader.cpp).
StatusOr<Translated> translate(std::string_view bytes, const std::string& source, const std::stop_token& stop);

// Picks the solid asked for by `choice` (StepOptions::solid) and checks it: one solid
// when choice is -1, no loose faces, a valid B-rep without free edges (step_solid.cpp).
StatusOr<TopoDS_Shape> select_solid(const TopoDS_Shape& shape, int choice,
                                    const std::string& source);

// The CAD record of each face of `faces` (step_faces.cpp).
std::vector<CadFace> describe_faces(const TopTools_IndexedMapOfShape& faces);

// The holes among `faces` of `solid`; `cad` describes them (step_holes.cpp).
std::vector<CadHole> find_holes(const TopoDS_Shape& solid, const TopTools_IndexedMapOfShape& faces,
                                const std::vector<CadFace>& cad);

// "face 73 (plane, 0.004 x 5e-05 x 0 mm, area 2e-07 mm^2)", for messages (step_faces.cpp).
std::string face_label(const TopoDS_Face& face, uint32_t index);

// Tessellates `solid` and welds the triangulation by topology into part.mesh and
// part.face_cad; part.cad_faces must already be filled (step_tessellation.cpp). More than
// max_triangles triangles (0: no limit) fail with kResourceExhausted before welding.
// `faithful`: then rebuilt by make_faithful.
Status tessellate(const TopoDS_Shape& solid, double linear, double angular_radians, uint32_t max_triangles,
                  bool faithful, const std::stop_token& stop, StepPart& part);

// The points of the welded mesh, keyed by topology: one per B-rep vertex, one per interior
// node of each edge's discretisation (shared by the faces on both sides of the edge).
struct Weld {
  static constexpr uint32_t kNone = UINT32_MAX;
  RawMesh* mesh = nullptr;
  TopTools_IndexedMapOfShape edges, vertices;  // TopExp::MapShapes order of the solid
  std::vector<uint32_t> vertex_point;          // per B-rep vertex, kNone until seen
  // Per edge: the point of each discretisation node, in the order of the edge's parameter
  // (first and last are the edge's vertices); empty until a face using the edge is meshed.
  std::vector<std::vector<uint32_t>> edge_points;
  // The edge curve's parameter of each of those nodes (NaN where BRepMesh gave none).
  std::vector<std::vector<double>> edge_params;

  // Points BRepMesh made one triangulation node (the two vertices of an edge far shorter
  // than the deflection) are merged: parent is a union-find forest over the points.
  std::vector<uint32_t> parent;

  uint32_t add(const gp_Pnt& p);
  // The vertex's point; made at `p` the first time the vertex is seen.
  uint32_t vertex(const TopoDS_Vertex& v, const gp_Pnt& p);
  uint32_t find(uint32_t p);
  void unite(uint32_t a, uint32_t b);  // the smaller index stays the representative
};

// The boundary of a planar face with one wire that BRepMesh could not triangulate, as one
// polygon of welded points, counter-clockwise seen from outside; an error naming the face
// when that is impossible (step_fallback.cpp). `why` says how meshing failed.
StatusOr<std::vector<uint32_t>> planar_boundary(const TopoDS_Face& face, const CadFace& cad,
                                                Weld& weld, const std::string& why);

// Bounding-box diagonal of a shape, in its units.
double diagonal(const TopoDS_Shape& shape);

// The faithful tessellation (step_faithful.cpp): the BRepMesh triangulation in `per_face`
// (per B-rep face, polygons over welded points; empty for a face BRepMesh left without
// triangles) rebuilt so that the B-rep's directions hold exactly -- ruled faces meshed
// along their rulings, planar faces exactly planar, the points moved onto integer lattices
// -- and part.tessellation filled. The welded points are moved in place.
Status make_faithful(const TopoDS_Shape& solid, const TopTools_IndexedMapOfShape& faces, double linear,
                     Weld& weld, std::vector<std::vector<std::vector<uint32_t>>>& per_face, StepPart& part);

}  // namespace gvm::step_internal
