#include "sphere/arrangement.h"

#include "sphere/box_tree.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <unordered_map>

namespace gvm::sphere {
namespace {

using exact::ExactVec;

bool positive(Sign s) { return s == Sign::kPositive; }

// X on the circle of `a`, strictly between its endpoints (the arc is < 180 degrees).
bool strictly_inside(const ArrangementArc& a, const ExactVec& x) {
  return positive(exact::sign_det(a.normal, a.from, x)) &&
         positive(exact::sign_det(a.normal, x, a.to));
}

class UnionFind {
 public:
  explicit UnionFind(size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0u); }
  uint32_t find(uint32_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void unite(uint32_t a, uint32_t b) { parent_[find(a)] = find(b); }

 private:
  std::vector<uint32_t> parent_;
};

Box point_box(const exact::UnitEstimate& e) {
  Box b;
  for (int i = 0; i < 3; ++i) {
    b.lo[i] = e.unit[i] - e.radius;
    b.hi[i] = e.unit[i] + e.radius;
  }
  return b;
}

// A box around the whole arc: the chord's box grown by the sagitta of the arc.
Box arc_box(const exact::UnitEstimate& a, const exact::UnitEstimate& b) {
  double chord = 0;
  for (int i = 0; i < 3; ++i) chord += (a.unit[i] - b.unit[i]) * (a.unit[i] - b.unit[i]);
  chord = std::min(2.0, std::sqrt(chord));
  double half_angle = std::asin(chord / 2);
  double grow = (1 - std::cos(half_angle)) * 1.01 + a.radius + b.radius + 1e-12;
  Box box;
  for (int i = 0; i < 3; ++i) {
    box.lo[i] = std::min(a.unit[i], b.unit[i]) - grow;
    box.hi[i] = std::max(a.unit[i], b.unit[i]) + grow;
  }
  return box;
}

}  // namespace

Arrangement::Arrangement(std::span<const ArrangementArc> arcs,
                         std::span<const ArrangementPoint> points, int layers,
                         const ExactVec& reference, std::span<const int> reference_coverage) {
  build(arcs, points, reference);
  // Join the components that do not touch by bridges to the component of vertex 0, then
  // build again: bridges may cross other arcs, which only adds connections.
  UnionFind uf(vertices_.size());
  for (const Edge& e : edges_) uf.unite(e.v0, e.v1);
  std::vector<ArrangementArc> with_bridges(arcs.begin(), arcs.end());
  const uint32_t root = uf.find(reference_vertex_ == 0 && vertices_.size() > 1 ? 1 : 0);
  std::vector<exact::UnitEstimate> est;
  for (const Vertex& v : vertices_) est.push_back(exact::unit_estimate(v.p));
  // Vertices of the root component (never the reference point), to bridge to.
  std::vector<uint32_t> targets;
  std::vector<Box> target_boxes;
  for (uint32_t w = 0; w < vertices_.size(); ++w) {
    if (w == reference_vertex_ || uf.find(w) != root) continue;
    targets.push_back(w);
    target_boxes.push_back(point_box(est[w]));
  }
  const BoxTree target_tree(target_boxes);
  std::vector<bool> done(vertices_.size(), false);
  for (uint32_t v = 0; v < vertices_.size(); ++v) {
    uint32_t c = uf.find(v);
    if (c == root || done[c] || targets.empty()) continue;
    done[c] = true;
    // A near vertex of the root component: short bridges cross few arcs. Any one would do.
    uint32_t best = UINT32_MAX;
    double best_d = 1e300;
    for (double h = 1e-3; best == UINT32_MAX; h *= 4) {
      Box query;
      for (int i = 0; i < 3; ++i) query.lo[i] = est[v].unit[i] - h, query.hi[i] = est[v].unit[i] + h;
      for (uint32_t t : target_tree.overlapping(query)) {
        const uint32_t w = targets[t];
        double d = 0;
        for (int i = 0; i < 3; ++i) d += (est[v].unit[i] - est[w].unit[i]) * (est[v].unit[i] - est[w].unit[i]);
        if (d < best_d) best_d = d, best = w;
      }
    }
    const ExactVec& a = vertices_[v].p;
    const ExactVec& b = vertices_[best].p;
    if (exact::parallel(a, b)) {
      // Antipodal: go through a point a quarter circle away.
      ExactVec m = exact::cross(a, ExactVec::from_point({1, 0, 0}));
      if (exact::is_zero(m)) m = exact::cross(a, ExactVec::from_point({0, 1, 0}));
      with_bridges.push_back({a, m, exact::cross(a, m), -1, 0});
      with_bridges.push_back({m, b, exact::cross(m, b), -1, 0});
    } else {
      with_bridges.push_back({a, b, exact::cross(a, b), -1, 0});
    }
  }
  if (with_bridges.size() != arcs.size()) build(with_bridges, points, reference);
  link_half_edges();
  label_faces(layers, reference_coverage);
}

void Arrangement::build(std::span<const ArrangementArc> input,
                        std::span<const ArrangementPoint> points, const ExactVec& reference) {
  vertices_.clear();
  edges_.clear();
  // Arcs of zero length carry nothing.
  std::vector<const ArrangementArc*> arcs;
  for (const ArrangementArc& a : input) {
    if (!exact::same_direction(a.from, a.to)) arcs.push_back(&a);
  }

  // Point occurrences: arc endpoints, split points, input points, the reference.
  std::vector<ExactVec> occ;
  std::vector<std::vector<uint32_t>> on_arc(arcs.size());  // occurrences on each arc
  auto add_occ = [&](const ExactVec& p) {
    occ.push_back(p);
    return static_cast<uint32_t>(occ.size() - 1);
  };
  for (size_t i = 0; i < arcs.size(); ++i) {
    on_arc[i].push_back(add_occ(arcs[i]->from));
    on_arc[i].push_back(add_occ(arcs[i]->to));
  }
  std::vector<uint32_t> point_occ;
  for (const ArrangementPoint& p : points) point_occ.push_back(add_occ(p.p));
  const uint32_t reference_occ = add_occ(reference);

  // Candidate pairs from a tree of boxes.
  std::vector<exact::UnitEstimate> from_est(arcs.size()), to_est(arcs.size());
  std::vector<Box> boxes(arcs.size());
  for (size_t i = 0; i < arcs.size(); ++i) {
    from_est[i] = exact::unit_estimate(arcs[i]->from);
    to_est[i] = exact::unit_estimate(arcs[i]->to);
    boxes[i] = arc_box(from_est[i], to_est[i]);
  }
  const BoxTree tree(boxes);
  const std::vector<std::pair<uint32_t, uint32_t>> pairs = tree.overlapping_pairs();

  for (auto [i, j] : pairs) {
    const ArrangementArc& A = *arcs[i];
    const ArrangementArc& B = *arcs[j];
    if (exact::parallel(A.normal, B.normal)) {
      // Same great circle: endpoints of one strictly inside the other split it.
      if (strictly_inside(A, B.from)) on_arc[i].push_back(add_occ(B.from));
      if (strictly_inside(A, B.to)) on_arc[i].push_back(add_occ(B.to));
      if (strictly_inside(B, A.from)) on_arc[j].push_back(add_occ(A.from));
      if (strictly_inside(B, A.to)) on_arc[j].push_back(add_occ(A.to));
      continue;
    }
    const Sign af = exact::sign_dot(A.from, B.normal), at = exact::sign_dot(A.to, B.normal);
    const Sign bf = exact::sign_dot(B.from, A.normal), bt = exact::sign_dot(B.to, A.normal);
    if ((af == at && af != Sign::kZero) || (bf == bt && bf != Sign::kZero)) continue;
    if (af != Sign::kZero && at != Sign::kZero && bf != Sign::kZero && bt != Sign::kZero) {
      // Proper crossing at X = s (N_A x N_B): inside A iff s = sign(A.from . N_B), inside B
      // iff -s = sign(B.from . N_A) (the two circles meet at +-X).
      if (af == -bf) {
        ExactVec x = af == Sign::kPositive ? exact::cross(A.normal, B.normal)
                                           : exact::cross(B.normal, A.normal);
        on_arc[i].push_back(add_occ(x));
        on_arc[j].push_back(add_occ(x));
      }
      continue;
    }
    // An endpoint of one arc on the other's circle is the only meeting point there.
    if (af == Sign::kZero && strictly_inside(B, A.from)) on_arc[j].push_back(add_occ(A.from));
    if (at == Sign::kZero && strictly_inside(B, A.to)) on_arc[j].push_back(add_occ(A.to));
    if (bf == Sign::kZero && strictly_inside(A, B.from)) on_arc[i].push_back(add_occ(B.from));
    if (bt == Sign::kZero && strictly_inside(A, B.to)) on_arc[i].push_back(add_occ(B.to));
  }
  // Input points (and the reference) lying inside arcs split them.
  for (size_t k = 0; k <= points.size(); ++k) {
    const ExactVec& p = k < points.size() ? points[k].p : reference;
    Box b = point_box(exact::unit_estimate(p));
    for (uint32_t i : tree.overlapping(b)) {
      if (exact::sign_dot(p, arcs[i]->normal) == Sign::kZero && strictly_inside(*arcs[i], p)) {
        on_arc[i].push_back(k < points.size() ? point_occ[k] : reference_occ);
      }
    }
  }

  // Identify equal directions. Occurrences of one shared node are one direction (arcs
  // that meet share their endpoint's node, often dozens of times); the distinct nodes
  // are compared exactly when their boxes overlap.
  UnionFind same(occ.size());
  std::unordered_map<const void*, uint32_t> first_of_node;
  std::vector<uint32_t> distinct;
  std::vector<Box> occ_boxes;
  for (uint32_t k = 0; k < occ.size(); ++k) {
    auto [it, inserted] = first_of_node.try_emplace(occ[k].node(), k);
    if (!inserted) {
      same.unite(k, it->second);
      continue;
    }
    distinct.push_back(k);
    occ_boxes.push_back(point_box(exact::unit_estimate(occ[k])));
  }
  for (auto [i, j] : BoxTree(occ_boxes).overlapping_pairs()) {
    const uint32_t a = distinct[i], b = distinct[j];
    if (same.find(a) != same.find(b) && exact::same_direction(occ[a], occ[b])) same.unite(a, b);
  }
  std::vector<uint32_t> vertex_of(occ.size(), UINT32_MAX), vertex_of_root(occ.size(), UINT32_MAX);
  for (uint32_t k = 0; k < occ.size(); ++k) {
    uint32_t r = same.find(k);
    if (vertex_of_root[r] == UINT32_MAX) {
      vertex_of_root[r] = static_cast<uint32_t>(vertices_.size());
      vertices_.push_back({occ[r], {}, 0});
    }
    vertex_of[k] = vertex_of_root[r];
  }
  for (size_t k = 0; k < points.size(); ++k) {
    vertices_[vertex_of[point_occ[k]]].point_layers |= 1u << points[k].layer;
  }
  reference_vertex_ = vertex_of[reference_occ];

  // Split every arc at its vertices, in order along it, and merge coinciding pieces.
  std::unordered_map<uint64_t, uint32_t> edge_index;
  for (size_t i = 0; i < arcs.size(); ++i) {
    const ArrangementArc& arc = *arcs[i];
    std::vector<uint32_t> vs;
    for (uint32_t k : on_arc[i]) vs.push_back(vertex_of[k]);
    const uint32_t first = vs[0], last = vs[1];
    std::sort(vs.begin(), vs.end());
    vs.erase(std::unique(vs.begin(), vs.end()), vs.end());
    std::erase_if(vs, [&](uint32_t v) { return v == first || v == last; });
    std::sort(vs.begin(), vs.end(), [&](uint32_t a, uint32_t b) {
      return positive(exact::sign_det(arc.normal, vertices_[a].p, vertices_[b].p));
    });
    vs.insert(vs.begin(), first);
    vs.push_back(last);
    for (size_t k = 0; k + 1 < vs.size(); ++k) {
      uint32_t a = vs[k], b = vs[k + 1];
      uint64_t key = uint64_t(std::min(a, b)) << 32 | std::max(a, b);
      auto [it, inserted] = edge_index.try_emplace(key, static_cast<uint32_t>(edges_.size()));
      if (inserted) {
        Edge e;
        e.v0 = a;
        e.v1 = b;
        e.normal = arc.normal;
        edges_.push_back(e);
      }
      Edge& e = edges_[it->second];
      const bool along = e.v0 == a;
      if (arc.layer >= 0) {
        e.weight[arc.layer] += along ? arc.weight : -arc.weight;
        e.arc_layers |= 1u << arc.layer;
        e.bridge_only = false;
      }
    }
  }
}

void Arrangement::link_half_edges() {
  half_.assign(2 * edges_.size(), {});
  for (auto& v : vertices_) v.out.clear();
  for (uint32_t e = 0; e < edges_.size(); ++e) {
    HalfEdge& f = half_[2 * e];
    HalfEdge& b = half_[2 * e + 1];
    f = {edges_[e].v0, 2 * e + 1, 0, 0, e, true};
    b = {edges_[e].v1, 2 * e, 0, 0, e, false};
    vertices_[edges_[e].v0].out.push_back(2 * e);
    vertices_[edges_[e].v1].out.push_back(2 * e + 1);
  }
  // Counter-clockwise order of the outgoing half-edges around each vertex P, seen from
  // outside. A half-edge leaving P counter-clockwise around N' has tangent N' x P; for
  // two of them P . (T1 x T2) = |P|^2 det(N1', N2', P) and T1 . T2 = |P|^2 N1' . N2'.
  auto oriented = [&](uint32_t h) {
    const Edge& e = edges_[half_[h].edge];
    return half_[h].forward ? e.normal : -e.normal;
  };
  for (Vertex& v : vertices_) {
    if (v.out.size() < 2) continue;
    const ExactVec n0 = oriented(v.out[0]);
    auto group = [&](const ExactVec& n) {
      Sign s = exact::sign_det(n0, n, v.p);
      if (s == Sign::kPositive) return 1;
      if (s == Sign::kNegative) return 3;
      return exact::sign_dot(n0, n) == Sign::kPositive ? 0 : 2;
    };
    std::vector<std::pair<int, uint32_t>> keyed;
    for (uint32_t h : v.out) keyed.push_back({group(oriented(h)), h});
    std::sort(keyed.begin(), keyed.end(), [&](const auto& a, const auto& b) {
      if (a.first != b.first) return a.first < b.first;
      return positive(exact::sign_det(oriented(a.second), oriented(b.second), v.p));
    });
    for (size_t k = 0; k < keyed.size(); ++k) v.out[k] = keyed[k].second;
  }
  // next(h) for h = (u -> v): the outgoing half-edge at v just clockwise of twin(h), so
  // that the face on the left of h continues on the left of next(h).
  for (Vertex& v : vertices_) {
    const size_t n = v.out.size();
    for (size_t k = 0; k < n; ++k) {
      uint32_t t = v.out[k];
      half_[half_[t].twin].next = v.out[(k + n - 1) % n];
    }
  }
  faces_.clear();
  std::vector<bool> seen(half_.size(), false);
  for (uint32_t h = 0; h < half_.size(); ++h) {
    if (seen[h]) continue;
    const uint32_t f = static_cast<uint32_t>(faces_.size());
    faces_.push_back({h, {}});
    for (uint32_t g = h; !seen[g]; g = half_[g].next) {
      seen[g] = true;
      half_[g].face = f;
    }
  }
  if (faces_.empty()) faces_.push_back({UINT32_MAX, {}});  // no arcs: the whole sphere
}

void Arrangement::label_faces(int layers, std::span<const int> reference_coverage) {
  const auto& ref_out = vertices_[reference_vertex_].out;
  const uint32_t start = ref_out.empty() ? 0 : half_[ref_out[0]].face;
  for (int k = 0; k < layers; ++k) faces_[start].coverage[k] = reference_coverage[k];
  std::vector<bool> known(faces_.size(), false);
  known[start] = true;
  std::vector<uint32_t> queue = {start};
  for (size_t qi = 0; qi < queue.size(); ++qi) {
    const uint32_t f = queue[qi];
    if (faces_[f].first_half_edge == UINT32_MAX) continue;
    uint32_t h = faces_[f].first_half_edge;
    do {
      const uint32_t g = half_[half_[h].twin].face;
      if (!known[g]) {
        known[g] = true;
        const Edge& e = edges_[half_[h].edge];
        for (int k = 0; k < layers; ++k) {
          // The face of h is on h's left: coverage(left) - coverage(right) = +-weight.
          faces_[g].coverage[k] =
              faces_[f].coverage[k] - (half_[h].forward ? e.weight[k] : -e.weight[k]);
        }
        queue.push_back(g);
      }
      h = half_[h].next;
    } while (h != faces_[f].first_half_edge);
  }
}

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
  for (uint32_t v = 0; v < vertices_.size(); ++v) {
    if (on_curve[v] || !vertex_in(v)) continue;
    bool in_face = false;
    for (uint32_t h : vertices_[v].out) in_face |= fin[half_[h].face] != 0;
    if (!in_face) out.add_point(vertices_[v].p);
  }
  return out;
}

}  // namespace gvm::sphere
