// Choosing the solid of a translated STEP file and checking that it is one closed, valid
// B-rep. A reader of untrusted files cannot rely on the read status: a corrupted file may
// still translate into a compound of solids and loose faces (see data/step/SOURCES.md).
#include <BRepCheck.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepCheck_ListOfStatus.hxx>
#include <BRepCheck_Result.hxx>
#include <BRep_Tool.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

#include <cctype>
#include <optional>
#include <sstream>

#include "step/step_internal.h"

namespace gvm::step_internal {
namespace {

std::string S(size_t v) { return std::to_string(v); }
std::string plural(size_t n, const std::string& word) { return S(n) + " " + word + (n == 1 ? "" : "s"); }

// How many of `type` the shape holds that lie in none of `solids`.
size_t outside_solids(const TopoDS_Shape& shape, const TopTools_IndexedMapOfShape& solids,
                      TopAbs_ShapeEnum type) {
  TopTools_IndexedMapOfShape all, inside;
  TopExp::MapShapes(shape, type, all);
  for (int i = 1; i <= solids.Extent(); ++i) TopExp::MapShapes(solids(i), type, inside);
  size_t n = 0;
  for (int i = 1; i <= all.Extent(); ++i) n += inside.Contains(all(i)) ? 0 : 1;
  return n;
}

// Edges bounding only one face (a seam counts twice in its face; degenerated edges are
// not boundaries).
size_t free_edges(const TopoDS_Shape& shape) {
  TopTools_IndexedDataMapOfShapeListOfShape edge_faces;
  TopExp::MapShapesAndAncestors(shape, TopAbs_EDGE, TopAbs_FACE, edge_faces);
  size_t n = 0;
  for (int i = 1; i <= edge_faces.Extent(); ++i)
    if (edge_faces(i).Extent() < 2 && !BRep_Tool::Degenerated(TopoDS::Edge(edge_faces.FindKey(i))))
      ++n;
  return n;
}

// " (and 2 loose faces, 1 shell outside them)" or "".
std::string loose_parts(const TopoDS_Shape& shape, const TopTools_IndexedMapOfShape& solids) {
  size_t shells = outside_solids(shape, solids, TopAbs_SHELL);
  size_t faces = outside_solids(shape, solids, TopAbs_FACE);
  if (shells == 0 && faces == 0) return "";
  std::string s = plural(faces, "loose face");
  if (shells > 0) s += " in " + plural(shells, "shell");
  return s;
}

std::string no_solid(const TopoDS_Shape& shape, const std::string& source) {
  TopTools_IndexedMapOfShape shells, faces;
  TopExp::MapShapes(shape, TopAbs_SHELL, shells);
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  return source + ": holds no solid, only " + plural(shells.Extent(), "shell") + " with " +
         plural(faces.Extent(), "face") + " and " + plural(free_edges(shape), "free edge") +
         " (edges bounding a single face): the surface is not closed, so it has no inside "
         "to machine";
}

std::string status_name(BRepCheck_Status s) {
  std::ostringstream out;
  BRepCheck::Print(s, out);
  std::string name = out.str();
  while (!name.empty() && std::isspace(static_cast<unsigned char>(name.back()))) name.pop_back();
  return name;
}

std::optional<BRepCheck_Status> first_error(const BRepCheck_ListOfStatus& list) {
  for (BRepCheck_Status s : list)
    if (s != BRepCheck_NoError) return s;
  return std::nullopt;
}

// The first defect BRepCheck recorded on `shape`, alone or in the context of any shape.
std::optional<BRepCheck_Status> first_error(const BRepCheck_Analyzer& check, const TopoDS_Shape& shape) {
  const Handle(BRepCheck_Result)& r = check.Result(shape);
  if (r.IsNull()) return std::nullopt;
  if (auto s = first_error(r->Status())) return s;
  for (r->InitContextIterator(); r->MoreShapeInContext(); r->NextShapeInContext())
    if (auto s = first_error(r->StatusOnShape())) return s;
  return std::nullopt;
}

// The face itself first, then its wires, edges and vertices.
std::optional<BRepCheck_Status> face_error(const BRepCheck_Analyzer& check, const TopoDS_Shape& face) {
  if (auto s = first_error(check, face)) return s;
  for (TopAbs_ShapeEnum type : {TopAbs_WIRE, TopAbs_EDGE, TopAbs_VERTEX}) {
    TopTools_IndexedMapOfShape subs;
    TopExp::MapShapes(face, type, subs);
    for (int i = 1; i <= subs.Extent(); ++i)
      if (auto s = first_error(check, subs(i))) return s;
  }
  return std::nullopt;
}

Status check_valid(const TopoDS_Shape& solid, const std::string& source) {
  BRepCheck_Analyzer check(solid, /*GeomControls=*/true, /*theIsParallel=*/true);
  if (check.IsValid()) return Status::Ok();
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(solid, TopAbs_FACE, faces);
  for (int i = 1; i <= faces.Extent(); ++i) {
    if (check.IsValid(faces(i))) continue;
    auto s = face_error(check, faces(i));
    return InvalidArgument(source + ": invalid B-rep: " +
                           face_label(TopoDS::Face(faces(i)), uint32_t(i - 1)) +
                           " fails Open CASCADE's shape check (" +
                           (s ? status_name(*s) : std::string("no status recorded")) + ")");
  }
  TopTools_IndexedMapOfShape shells;
  TopExp::MapShapes(solid, TopAbs_SHELL, shells);
  std::optional<BRepCheck_Status> s = first_error(check, solid);
  for (int i = 1; i <= shells.Extent() && !s; ++i) s = first_error(check, shells(i));
  return InvalidArgument(source + ": invalid B-rep: the solid or its shell fails Open CASCADE's "
                         "shape check (" + (s ? status_name(*s) : std::string("no status recorded")) + ")");
}

}  // namespace

StatusOr<TopoDS_Shape> select_solid(const TopoDS_Shape& shape, int choice, const std::string& source) {
  TopTools_IndexedMapOfShape solids;
  TopExp::MapShapes(shape, TopAbs_SOLID, solids);
  const size_t n = solids.Extent();
  if (n == 0) return InvalidArgument(no_solid(shape, source));
  const std::string loose = loose_parts(shape, solids);
  if (choice < 0 && (n > 1 || !loose.empty()))
    return InvalidArgument(source + ": holds " + plural(n, "solid") +
                           (loose.empty() ? "" : " and " + loose + " outside them") +
                           "; choose one with --solid N (a request's step.solid), N from 0 to " + S(n - 1));
  if (choice >= int(n))
    return InvalidArgument(source + ": solid " + S(choice) + " asked for (--solid, step.solid) but the file holds only " +
                           plural(n, "solid") + " (0.." + S(n - 1) + ")");
  TopoDS_Shape solid = solids(choice < 0 ? 1 : choice + 1);
  if (size_t open = free_edges(solid); open > 0)
    return InvalidArgument(source + ": solid " + S(choice < 0 ? 0 : choice) + " is not closed: " +
                           plural(open, "free edge") + " (edges bounding a single face)");
  if (Status s = check_valid(solid, source); !s.ok()) return s;
  return solid;
}

}  // namespace gvm::step_internal
