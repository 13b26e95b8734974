// Arrangement::extract: the cells a caller selects, as a canonical SphericalImage.
#include "sphere/arrangement.h"

#include <algorithm>

#include "parallel/interrupt.h"

#include "sphere/union_find.h"

namespace gvm::sphere {

using exact::ExactVec;

SphericalImage Arrangement::extract(const std::function<bool(uint32_t)>& face_in,
                                    const std::function<bool(uint32_t)>& edge_in,
                                    const std::function<bool(uint32_t)>& vertex_in) const {
  SphericalImage out;
  std::vector<char> fin(faces_.size());
  for (uint32_t f = 0; f < faces_.size(); ++f) fin[f] = face_in(f);
  if (half_.empty()) {
    if (fin[0]) return SphericalImage::full_sphere();
  } else if (std::all_of(fin.begin(), fin.end(), [](char c) { return c; })) {
    return SphericalImage::full_sphere();
  }
  auto oriented = [&](uint32_t h) {
    const Edge& e = edges_[half_[h].edge];
    return half_[h].forward ? e.normal : -e.normal;
  };
  auto dest = [&](uint32_t h) { return half_[half_[h].twin].origin; };

  // 2-cells: boundary half-edges have a selected face on the left only. Loops follow the
  // boundary around each vertex; faces joined across edges form one polygon.
  UnionFind group(faces_.size());
  std::vector<bool> boundary(half_.size(), false);
  for (uint32_t h = 0; h < half_.size(); ++h) {
    const uint32_t f = half_[h].face, g = half_[half_[h].twin].face;
    if (fin[f] && fin[g]) group.unite(f, g);
    boundary[h] = fin[f] && !fin[g];
  }
  std::vector<std::vector<Loop>> polygon_loops(faces_.size());
  std::vector<bool> used(half_.size(), false);
  for (uint32_t h0 = 0; h0 < half_.size(); ++h0) {
    if (!boundary[h0] || used[h0]) continue;
    Loop loop;
    uint32_t h = h0;
    do {
      used[h] = true;
      Arc arc{vertices_[half_[h].origin].p, vertices_[dest(h)].p, oriented(h), false};
      if (!loop.arcs.empty() && exact::same_direction(loop.arcs.back().normal, arc.normal)) {
        loop.arcs.back().end = arc.end;
      } else {
        loop.arcs.push_back(arc);
      }
      uint32_t g = half_[h].next;
      while (!boundary[g]) g = half_[half_[g].twin].next;
      h = g;
    } while (h != h0);
    if (loop.arcs.size() > 1 && exact::same_direction(loop.arcs.back().normal, loop.arcs.front().normal)) {
      loop.arcs.front().start = loop.arcs.back().start;
      loop.arcs.pop_back();
    }
    if (loop.arcs.size() == 1) loop.arcs[0].full = true;  // a whole great circle
    polygon_loops[group.find(half_[h0].face)].push_back(std::move(loop));
  }
  for (auto& loops : polygon_loops) {
    if (!loops.empty()) out.add_face({std::move(loops), false});
  }

  // 1-cells: selected edges with no selected face on either side, merged along circles.
  std::vector<bool> curve(edges_.size(), false);
  for (uint32_t e = 0; e < edges_.size(); ++e) {
    curve[e] = edge_in(e) && !fin[half_[2 * e].face] && !fin[half_[2 * e + 1].face];
  }
  std::vector<bool> taken(edges_.size(), false);
  std::vector<bool> on_curve(vertices_.size(), false);
  for (uint32_t e = 0; e < edges_.size(); ++e) {
    if (!curve[e]) continue;
    on_curve[edges_[e].v0] = on_curve[edges_[e].v1] = true;
  }
  // Continuation of a curve through vertex v along the same circle, if unique.
  auto continuation = [&](uint32_t v, uint32_t e) -> int64_t {
    int64_t found = -1;
    int count = 0;
    for (uint32_t h : vertices_[v].out) {
      uint32_t f = half_[h].edge;
      if (f == e || !curve[f]) continue;
      ++count;
      if (exact::parallel(edges_[f].normal, edges_[e].normal)) found = f;
    }
    return count == 1 ? found : -1;
  };
  for (uint32_t e0 = 0; e0 < edges_.size(); ++e0) {
    if (!curve[e0] || taken[e0]) continue;
    // Walk back to the start of the maximal run on one circle, then forward.
    uint32_t e = e0, v = edges_[e0].v0;
    for (size_t guard = 0; guard < edges_.size(); ++guard) {
      int64_t p = continuation(v, e);
      if (p < 0 || static_cast<uint32_t>(p) == e0) break;
      e = static_cast<uint32_t>(p);
      v = edges_[e].v0 == v ? edges_[e].v1 : edges_[e].v0;
    }
    // Now walk forward from vertex v through edge e.
    uint32_t start_v = v;
    ExactVec n = edges_[e].v0 == v ? edges_[e].normal : -edges_[e].normal;
    uint32_t cur_v = v;
    bool closed = false;
    while (true) {
      taken[e] = true;
      cur_v = edges_[e].v0 == cur_v ? edges_[e].v1 : edges_[e].v0;
      if (cur_v == start_v) {
        closed = true;
        break;
      }
      int64_t nx = continuation(cur_v, e);
      if (nx < 0 || taken[nx]) break;
      e = static_cast<uint32_t>(nx);
    }
    Arc arc{vertices_[start_v].p, vertices_[cur_v].p, n, closed};
    out.add_curve(arc);
  }

  // 0-cells.
  Interruptions interruptions(16);  // vertex_in may probe rays
  for (uint32_t v = 0; v < vertices_.size(); ++v) {
    interruptions.tick();
    if (on_curve[v] || !vertex_in(v)) continue;
    bool in_face = false;
    for (uint32_t h : vertices_[v].out) in_face |= fin[half_[h].face] != 0;
    if (!in_face) out.add_point(vertices_[v].p);
  }
  return out;
}

}  // namespace gvm::sphere
