#include "sphere/arrangement.h"

#include "parallel/interrupt.h"
#include "sphere/arrangement_vertices.h"
#include "sphere/box_tree.h"
#include "sphere/union_find.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <tuple>
#include <utility>
#include <vector>

#include <absl/container/flat_hash_map.h>

namespace gvm::sphere {
namespace {

using exact::ExactVec;

bool positive(Sign s) { return s == Sign::kPositive; }

// (arc, occurrence) pairs grouped by arc, each arc's in the order they were found (its
// endpoints first): a counting sort.
class OccurrencesByArc {
 public:
  OccurrencesByArc(std::span<const std::pair<uint32_t, uint32_t>> on_arc, size_t arcs)
      : begin_(arcs + 1, 0), occ_(on_arc.size()) {
    for (auto [i, k] : on_arc) ++begin_[i + 1];
    for (size_t i = 0; i < arcs; ++i) begin_[i + 1] += begin_[i];
    std::vector<uint32_t> fill(begin_.begin(), begin_.end() - 1);
    for (auto [i, k] : on_arc) occ_[fill[i]++] = k;
  }
  std::span<const uint32_t> of(size_t arc) const {
    return std::span<const uint32_t>(occ_).subspan(begin_[arc], begin_[arc + 1] - begin_[arc]);
  }

 private:
  std::vector<uint32_t> begin_, occ_;
};

}  // namespace

Arrangement::Arrangement(std::span<const ArrangementArc> arcs,
                         std::span<const ArrangementPoint> points, const ExactVec& reference) {
  build_with_bridges(arcs, points, reference);
}

Arrangement::Arrangement(std::span<const ArrangementArc> arcs,
                         std::span<const ArrangementPoint> points, int layers,
                         const ExactVec& reference, std::span<const int> reference_coverage)
    : Arrangement(arcs, points, reference) {
  label_faces(layers, reference_coverage);
}

bool Arrangement::edge_on_layer(uint32_t e, int k) const {
  for (const LayerWeight& lw : edge_layers(e)) {
    if (lw.layer == k) return true;
  }
  return false;
}

int Arrangement::edge_weight(uint32_t e, int k) const {
  for (const LayerWeight& lw : edge_layers(e)) {
    if (lw.layer == k) return lw.weight;
  }
  return 0;
}

bool Arrangement::vertex_has_point(uint32_t v, int k) const {
  for (int layer : vertex_points(v)) {
    if (layer == k) return true;
  }
  return false;
}

uint32_t Arrangement::reference_face() const {
  const auto& out = vertices_[reference_vertex_].out;
  return out.empty() ? 0 : half_[out[0]].face;
}

void Arrangement::build_with_bridges(std::span<const ArrangementArc> arcs,
                                     std::span<const ArrangementPoint> points,
                                     const ExactVec& reference) {
  Recorded recorded = build(arcs, points, reference);
  // Join the components that do not touch by bridges, then build again: bridges may
  // cross other arcs, which only adds connections.
  std::vector<ArrangementArc> with_bridges(arcs.begin(), arcs.end());
  for (auto [v, w] : bridges()) {
    const ExactVec& a = vertices_[v].p;
    const ExactVec& b = vertices_[w].p;
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
  if (with_bridges.size() != arcs.size()) recorded = build(with_bridges, points, reference);
  index_layers(std::move(recorded));
  link_half_edges();
}

// Borůvka's rounds on the components of the arc graph: each component is bridged to the
// nearest vertex (in unit estimates) of another, which at least halves their number per
// round. Short bridges overlap few boxes; bridging every component to one root component
// made bridges across the sphere when that component lay far from the rest (TR12J F234:
// hundreds of loops bridged to a pinwheel of arcs at the opposite pole, 8.5 M candidate
// pairs instead of 1.3 M). Which bridges are chosen never changes the result.
std::vector<std::pair<uint32_t, uint32_t>> Arrangement::bridges() const {
  UnionFind joined(vertices_.size());
  for (const Edge& e : edges_) joined.unite(e.v0, e.v1);
  std::vector<exact::UnitEstimate> est;
  est.reserve(vertices_.size());
  for (const Vertex& v : vertices_) est.push_back(exact::unit_estimate(v.p));
  // Every vertex but the reference point may be bridged to.
  std::vector<uint32_t> targets;
  std::vector<Box> target_boxes;
  for (uint32_t w = 0; w < vertices_.size(); ++w) {
    if (w == reference_vertex_) continue;
    targets.push_back(w);
    target_boxes.push_back(point_box(est[w]));
  }
  const BoxTree target_tree(target_boxes);
  // Targets per component (at its root), so that a component holding them all does not
  // search boxes up to the whole sphere to find none (four such searches per
  // arrangement: its reference point is a component of its own until bridged).
  std::vector<uint32_t> targets_in(vertices_.size(), 0);
  for (uint32_t w : targets) ++targets_in[joined.find(w)];
  // The nearest target outside v's component within the first box around v that holds
  // one (any one would do); none when every target is in v's component.
  auto nearest_outside = [&](uint32_t v) {
    const uint32_t own = joined.find(v);
    uint32_t best = UINT32_MAX;
    double best_d = 1e300;
    if (targets_in[own] == targets.size()) return std::pair{best_d, best};
    // A half-width over 2 covers the sphere: the last box holds every target, and the
    // search ends even for an estimate that is not a number (none should be: unit
    // estimates are certified at any magnitude).
    for (double h = 1e-3; best == UINT32_MAX; h *= 4) {
      Box query;
      for (int i = 0; i < 3; ++i) query.lo[i] = est[v].unit[i] - h, query.hi[i] = est[v].unit[i] + h;
      target_tree.visit_overlapping(query, [&](uint32_t t) {
        const uint32_t w = targets[t];
        if (joined.find(w) == own) return false;
        double d = 0;
        for (int i = 0; i < 3; ++i) d += (est[v].unit[i] - est[w].unit[i]) * (est[v].unit[i] - est[w].unit[i]);
        if (d < best_d || (d == best_d && w < best)) best_d = d, best = w;
        return false;
      });
      if (h > 2) break;
    }
    return std::pair{best_d, best};
  };
  std::vector<std::pair<uint32_t, uint32_t>> out;
  Interruptions interruptions;
  for (bool merged = true; merged;) {
    // One representative per component: its first vertex.
    std::vector<uint8_t> seen(vertices_.size(), 0);
    std::vector<std::tuple<double, uint32_t, uint32_t>> nearest;
    for (uint32_t v = 0; v < vertices_.size(); ++v) {
      interruptions.tick();
      const uint32_t c = joined.find(v);
      if (seen[c]) continue;
      seen[c] = 1;
      const auto [d, w] = nearest_outside(v);
      if (w != UINT32_MAX) nearest.emplace_back(d, v, w);
    }
    std::sort(nearest.begin(), nearest.end());
    merged = false;
    for (const auto& [d, v, w] : nearest) {
      const uint32_t rv = joined.find(v), rw = joined.find(w);
      if (rv == rw) continue;
      joined.unite(v, w);  // rw the root
      targets_in[rw] += targets_in[rv];
      out.emplace_back(v, w);
      merged = true;
    }
  }
  return out;
}

Arrangement::Recorded Arrangement::build(std::span<const ArrangementArc> input,
                                         std::span<const ArrangementPoint> points,
                                         const ExactVec& reference) {
  vertices_.clear();
  edges_.clear();
  // Arcs of zero length carry nothing.
  std::vector<const ArrangementArc*> arcs;
  for (const ArrangementArc& a : input) {
    if (!exact::same_direction(a.from, a.to)) arcs.push_back(&a);
  }
  arrangement_internal::Occurrences o = arrangement_internal::occurrences(arcs, points, reference);
  compared_pairs_ += o.compared_pairs;
  const std::vector<uint32_t> vertex_of = arrangement_internal::vertices_of(o.occ, vertices_, compared_pairs_);
  Recorded recorded;
  for (size_t k = 0; k < points.size(); ++k) {
    recorded.points.push_back({vertex_of[o.point_occ[k]], points[k].layer});
  }
  reference_vertex_ = vertex_of[o.reference_occ];

  const OccurrencesByArc by_arc(o.on_arc, arcs.size());
  std::vector<std::pair<uint32_t, uint32_t>>().swap(o.on_arc);  // the grouped copy is what is used
  // Split every arc at its vertices, in order along it, and merge coinciding pieces.
  Interruptions interruptions;
  absl::flat_hash_map<uint64_t, uint32_t> edge_index;
  std::vector<uint32_t> vs;
  for (size_t i = 0; i < arcs.size(); ++i) {
    interruptions.tick();
    const ArrangementArc& arc = *arcs[i];
    vs.clear();
    for (uint32_t k : by_arc.of(i)) vs.push_back(vertex_of[k]);
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
      if (arc.layer >= 0) {
        const bool along = edges_[it->second].v0 == a;
        recorded.on_edges.push_back({it->second, arc.layer, along ? arc.weight : -arc.weight});
      }
    }
  }
  return recorded;
}

void Arrangement::index_layers(Recorded recorded) {
  // Counting sort by edge, then one entry per layer with the weights summed.
  std::vector<uint32_t> begin(edges_.size() + 1, 0);
  for (const Contribution& c : recorded.on_edges) ++begin[c.edge + 1];
  for (size_t e = 0; e < edges_.size(); ++e) begin[e + 1] += begin[e];
  std::vector<LayerWeight> by_edge(recorded.on_edges.size());
  {
    std::vector<uint32_t> fill(begin.begin(), begin.end() - 1);
    for (const Contribution& c : recorded.on_edges) by_edge[fill[c.edge]++] = {c.layer, c.weight};
  }
  recorded.on_edges = {};
  edge_layer_begin_.assign(edges_.size() + 1, 0);
  edge_layer_.clear();
  edge_layer_.reserve(by_edge.size());
  for (size_t e = 0; e < edges_.size(); ++e) {
    auto first = by_edge.begin() + begin[e], last = by_edge.begin() + begin[e + 1];
    if (last - first > 1) {
      std::sort(first, last, [](const LayerWeight& x, const LayerWeight& y) { return x.layer < y.layer; });
    }
    for (auto it = first; it != last; ++it) {
      if (edge_layer_.size() > edge_layer_begin_[e] && edge_layer_.back().layer == it->layer) {
        edge_layer_.back().weight += it->weight;
      } else {
        edge_layer_.push_back(*it);
      }
    }
    edge_layer_begin_[e + 1] = static_cast<uint32_t>(edge_layer_.size());
  }
  // Point layers per vertex, sorted and distinct.
  std::sort(recorded.points.begin(), recorded.points.end());
  recorded.points.erase(std::unique(recorded.points.begin(), recorded.points.end()),
                        recorded.points.end());
  point_layer_begin_.assign(vertices_.size() + 1, 0);
  point_layer_.clear();
  for (auto [v, layer] : recorded.points) {
    ++point_layer_begin_[v + 1];
    point_layer_.push_back(layer);
  }
  for (size_t v = 0; v < vertices_.size(); ++v) point_layer_begin_[v + 1] += point_layer_begin_[v];
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
  // N' is the edge's normal, negated for a backward half-edge: its sign is carried apart
  // (negated nodes cost an allocation each).
  auto orientation = [&](uint32_t h) { return half_[h].forward ? Sign::kPositive : Sign::kNegative; };
  auto normal = [&](uint32_t h) -> const ExactVec& { return edges_[half_[h].edge].normal; };
  std::vector<std::pair<int, uint32_t>> keyed;
  Interruptions interruptions;
  for (Vertex& v : vertices_) {
    interruptions.tick();
    if (v.out.size() < 3) continue;  // two half-edges are in counter-clockwise order either way
    auto turn = [&](uint32_t a, uint32_t b) {
      return orientation(a) * orientation(b) * exact::sign_det(normal(a), normal(b), v.p);
    };
    const uint32_t h0 = v.out[0];
    auto group = [&](uint32_t h) {
      const Sign s = turn(h0, h);
      if (s == Sign::kPositive) return 1;
      if (s == Sign::kNegative) return 3;
      return orientation(h0) * orientation(h) * exact::sign_dot(normal(h0), normal(h)) == Sign::kPositive ? 0 : 2;
    };
    keyed.clear();
    for (uint32_t h : v.out) keyed.push_back({group(h), h});
    std::sort(keyed.begin(), keyed.end(), [&](const auto& a, const auto& b) {
      if (a.first != b.first) return a.first < b.first;
      return positive(turn(a.second, b.second));
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
    faces_.push_back({h});
    for (uint32_t g = h; !seen[g]; g = half_[g].next) {
      seen[g] = true;
      half_[g].face = f;
    }
  }
  if (faces_.empty()) faces_.push_back({UINT32_MAX});  // no arcs: the whole sphere
}

void Arrangement::label_faces(int layers, std::span<const int> reference_coverage) {
  layers_ = layers;
  coverage_.assign(faces_.size() * size_t(layers), 0);
  const uint32_t start = reference_face();
  std::copy_n(reference_coverage.begin(), layers, coverage_.begin() + size_t(start) * size_t(layers));
  std::vector<bool> known(faces_.size(), false);
  known[start] = true;
  std::vector<uint32_t> queue = {start};
  Interruptions interruptions;
  for (size_t qi = 0; qi < queue.size(); ++qi) {
    interruptions.tick();
    const uint32_t f = queue[qi];
    if (faces_[f].first_half_edge == UINT32_MAX) continue;
    uint32_t h = faces_[f].first_half_edge;
    do {
      const uint32_t g = half_[half_[h].twin].face;
      if (!known[g]) {
        known[g] = true;
        int* to = coverage_.data() + size_t(g) * size_t(layers);
        const int* from = coverage_.data() + size_t(f) * size_t(layers);
        std::copy_n(from, layers, to);
        // The face of h is on h's left: coverage(left) - coverage(right) = +-weight.
        for (const LayerWeight& lw : edge_layers(half_[h].edge)) {
          if (lw.layer < layers) to[lw.layer] -= half_[h].forward ? lw.weight : -lw.weight;
        }
        queue.push_back(g);
      }
      h = half_[h].next;
    } while (h != faces_[f].first_half_edge);
  }
}

}  // namespace gvm::sphere
