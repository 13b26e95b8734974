// Edge points added by the faithful tessellation, and BRepMesh's triangles cut along them
// (step_edge_points.h).
#include "step/step_edge_points.h"

#include <BRepAdaptor_Curve.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <cmath>
#include <memory>
#include <tuple>

#include "step/step_face_boundary.h"

namespace gvm::step_internal {

std::vector<std::vector<uint32_t>> edge_chains(Weld& weld) {
  std::vector<std::vector<uint32_t>> out(weld.edge_points.size());
  for (size_t e = 0; e < out.size(); ++e)
    for (uint32_t p : weld.edge_points[e]) out[e].push_back(weld.find(p));
  return out;
}

uint32_t insert_points(std::vector<EdgeInsertion>& insertions, Weld& weld, std::map<uint32_t, uint32_t>& asked_by) {
  std::sort(insertions.begin(), insertions.end(),
            [](const EdgeInsertion& a, const EdgeInsertion& b) { return std::tie(a.edge, a.parameter) < std::tie(b.edge, b.parameter); });
  uint32_t added = 0;
  std::unique_ptr<BRepAdaptor_Curve> curve;
  int curve_edge = -1;
  for (const EdgeInsertion& ins : insertions) {
    std::vector<double>& params = weld.edge_params[ins.edge];
    std::vector<uint32_t>& points = weld.edge_points[ins.edge];
    const double range = std::fabs(params.back() - params.front());
    auto it = std::lower_bound(params.begin(), params.end(), ins.parameter);
    const double near = std::min(it == params.end() ? INFINITY : *it - ins.parameter,
                                 it == params.begin() ? INFINITY : ins.parameter - *(it - 1));
    if (near <= 1e-9 * range) continue;  // there already (the other face asked too)
    if (curve_edge != ins.edge) {
      curve = std::make_unique<BRepAdaptor_Curve>(TopoDS::Edge(weld.edges(ins.edge + 1)));
      curve_edge = ins.edge;
    }
    const size_t at = size_t(it - params.begin());
    params.insert(params.begin() + long(at), ins.parameter);
    const uint32_t point = weld.add(curve->Value(ins.parameter));
    points.insert(points.begin() + long(at), point);
    asked_by[point] = ins.face;
    ++added;
  }
  return added;
}

Splits splits_of(const std::vector<std::vector<uint32_t>>& before, Weld& weld) {
  Splits out;
  for (size_t e = 0; e < before.size(); ++e) {
    const std::vector<uint32_t>& old = before[e];
    if (old.size() == weld.edge_points[e].size()) continue;
    std::vector<uint32_t> now;
    for (uint32_t p : weld.edge_points[e]) now.push_back(weld.find(p));
    size_t j = 0;
    for (size_t k = 0; k + 1 < old.size(); ++k) {
      while (j < now.size() && now[j] != old[k]) ++j;
      std::vector<uint32_t> inner;
      for (size_t i = j + 1; i < now.size() && now[i] != old[k + 1]; ++i) inner.push_back(now[i]);
      if (inner.empty() || old[k] == old[k + 1]) continue;
      out[{old[k], old[k + 1]}] = inner;
      std::reverse(inner.begin(), inner.end());
      out[{old[k + 1], old[k]}] = std::move(inner);
    }
  }
  return out;
}

Polygons fan_split(const Polygons& triangles, const Splits& splits, Weld& weld) {
  // Each piece carries which of its edges are still a whole edge of BRepMesh's triangle:
  // only those are looked up. The fan's own edges (pieces of the split edge, the diagonals
  // to the apex) never are, so that a file whose welded points make the splits refer to
  // each other in a cycle cannot fan without end: a triangle splits at most three times.
  struct Piece {
    std::array<uint32_t, 3> v;
    std::array<bool, 3> whole;  // edge k: v[k] -> v[k + 1]
  };
  std::vector<Piece> work;
  for (const auto& t : triangles) {
    if (t.size() != 3) continue;
    work.push_back({{weld.find(t[0]), weld.find(t[1]), weld.find(t[2])}, {true, true, true}});
  }
  Polygons out;
  while (!work.empty()) {
    const Piece t = work.back();
    work.pop_back();
    bool split = false;
    for (int k = 0; k < 3 && !split; ++k) {
      if (!t.whole[k]) continue;
      auto it = splits.find({t.v[k], t.v[(k + 1) % 3]});
      if (it == splits.end()) continue;
      const uint32_t apex = t.v[(k + 2) % 3];
      uint32_t prev = t.v[k];
      // The first piece keeps the edge apex -> v[k], the last the edge v[k + 1] -> apex.
      bool first = true;
      for (uint32_t m : it->second) {
        work.push_back({{prev, m, apex}, {false, false, first && t.whole[(k + 2) % 3]}});
        prev = m;
        first = false;
      }
      work.push_back({{prev, t.v[(k + 1) % 3], apex}, {false, t.whole[(k + 1) % 3], first && t.whole[(k + 2) % 3]}});
      split = true;
    }
    if (!split) out.push_back({t.v[0], t.v[1], t.v[2]});
  }
  return out;
}

bool touches_splits(const TopoDS_Face& face, const Weld& weld, const std::vector<std::vector<uint32_t>>& before) {
  for (const auto& wire : face_wires(face, weld))
    for (const EdgeUse& use : wire)
      if (before[use.edge].size() != weld.edge_points[use.edge].size()) return true;
  return false;
}

}  // namespace gvm::step_internal
