// Face boundaries as edge uses and as loops of welded points (step_face_boundary.h).
#include "step/step_face_boundary.h"

#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Pnt2d.hxx>

#include <algorithm>
#include <cmath>

namespace gvm::step_internal {
namespace {

// The ends of an edge's points taken in one direction.
struct Oriented {
  const std::vector<uint32_t>* points;
  bool backwards;
  uint32_t first(Weld& w) const { return w.find(backwards ? points->back() : points->front()); }
  uint32_t last(Weld& w) const { return w.find(backwards ? points->front() : points->back()); }
};

// Whether use i, run in direction `b`, begins where the previous use ends.
bool joins(const std::vector<EdgeUse>& wire, const std::vector<bool>& dir, size_t i, bool b, Weld& weld) {
  return Oriented{&weld.edge_points[wire[i].edge], b}.first(weld) ==
         Oriented{&weld.edge_points[wire[i - 1].edge], dir[i - 1]}.last(weld);
}

// Directions for the uses of one wire so that each ends where the next begins: the stated
// ones where they join, else each flipped as needed, starting from the first use either way.
std::vector<bool> joining_directions(const std::vector<EdgeUse>& wire, Weld& weld) {
  std::vector<bool> stated;
  for (const EdgeUse& u : wire) stated.push_back(u.reversed);
  if (wire.size() < 2) return stated;
  for (bool flip_first : {false, true}) {
    std::vector<bool> dir = stated;
    dir[0] = stated[0] != flip_first;
    bool ok = true;
    for (size_t i = 1; i < wire.size() && ok; ++i) {
      if (joins(wire, dir, i, stated[i], weld)) dir[i] = stated[i];
      else if (joins(wire, dir, i, !stated[i], weld)) dir[i] = !stated[i];
      else ok = false;
    }
    if (ok && Oriented{&weld.edge_points[wire.back().edge], dir.back()}.last(weld) ==
                  Oriented{&weld.edge_points[wire.front().edge], dir.front()}.first(weld))
      return dir;
  }
  return stated;
}

// The uses reordered and directed so that each begins in (u, v) where the one before ends.
// The wire explorer can state directions that join in space but not in (u, v) (a face of
// revolution bounded by two closed rims and the two uses of one seam edge): in (u, v) each
// use is one polyline, so there the joins are unambiguous. Empty when they do not join.
std::vector<bool> uv_directions(std::vector<EdgeUse>& wire) {
  std::vector<bool> backwards(wire.size(), false);
  if (std::any_of(wire.begin(), wire.end(), [](const EdgeUse& u) { return u.pcurve.IsNull(); })) return {};
  auto at = [](const EdgeUse& u, bool end_of_param) { return u.pcurve->Value(end_of_param ? u.last : u.first); };
  backwards[0] = wire[0].reversed;
  for (size_t i = 1; i < wire.size(); ++i) {
    const gp_Pnt2d end = at(wire[i - 1], !backwards[i - 1]);
    size_t best = i;
    bool best_back = false;
    double best_d = INFINITY;
    for (size_t j = i; j < wire.size(); ++j)
      for (bool back : {false, true}) {
        const double d = at(wire[j], back).SquareDistance(end);
        if (d < best_d) best_d = d, best = j, best_back = back;
      }
    std::swap(wire[i], wire[best]);
    backwards[i] = best_back;
  }
  return backwards;
}

}  // namespace

std::vector<std::vector<EdgeUse>> face_wires(const TopoDS_Face& face, const Weld& weld) {
  const TopoDS_Face forward = TopoDS::Face(face.Oriented(TopAbs_FORWARD));
  std::vector<std::vector<EdgeUse>> out;
  for (TopExp_Explorer w(forward, TopAbs_WIRE); w.More(); w.Next()) {
    std::vector<EdgeUse> uses;
    for (BRepTools_WireExplorer ex(TopoDS::Wire(w.Current()), forward); ex.More(); ex.Next()) {
      // The orientation the explorer reports (it composes the wire's), which is also what
      // selects a seam edge's pcurve for this use.
      const TopoDS_Edge edge = TopoDS::Edge(ex.Current().Oriented(ex.Orientation()));
      EdgeUse use;
      use.edge = weld.edges.FindIndex(edge) - 1;
      use.reversed = ex.Orientation() == TopAbs_REVERSED;
      use.degenerated = BRep_Tool::Degenerated(edge);
      use.pcurve = BRep_Tool::CurveOnSurface(edge, forward, use.first, use.last);
      uses.push_back(use);
    }
    out.push_back(std::move(uses));
  }
  return out;
}

std::vector<std::vector<LoopPoint>> boundary_loops(std::vector<std::vector<EdgeUse>>& wires, Weld& weld, bool by_uv) {
  std::vector<std::vector<LoopPoint>> out;
  for (auto& wire : wires) {
    std::vector<bool> backwards = by_uv ? uv_directions(wire) : std::vector<bool>{};
    if (backwards.empty()) backwards = joining_directions(wire, weld);
    std::vector<LoopPoint> loop;
    // A repeated point is one point, except at a degenerated edge (a cone's apex), which
    // stays as one entry of its own between its neighbours.
    auto repeats = [&](const LoopPoint& a, const LoopPoint& b) {
      return a.id == b.id && !wire[a.use].degenerated && !wire[b.use].degenerated;
    };
    for (uint32_t u = 0; u < wire.size(); ++u) {
      const std::vector<uint32_t>& points = weld.edge_points[wire[u].edge];
      const size_t n = wire[u].degenerated ? std::min<size_t>(points.size(), 1) : points.size();
      for (size_t i = 0; i < n; ++i) {
        const uint32_t k = uint32_t(backwards[u] ? n - 1 - i : i);
        const LoopPoint p{weld.find(points[k]), u, k};
        if (loop.empty() || !repeats(loop.back(), p)) loop.push_back(p);
      }
    }
    while (loop.size() > 1 && repeats(loop.front(), loop.back())) loop.pop_back();
    out.push_back(std::move(loop));
  }
  return out;
}

}  // namespace gvm::step_internal
