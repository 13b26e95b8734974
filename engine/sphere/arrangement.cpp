#include "sphere/arrangement.h"

#include "exact/interrupt.h"
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

// X on the circle of `a`, strictly between its endpoints (the arc is < 180 degrees).
bool strictly_inside(const ArrangementArc& a, const ExactVec& x) {
  return positive(exact::sign_det(a.normal, a.from, x)) &&
         positive(exact::sign_det(a.normal, x, a.to));
}

// Pairs are dense when there are more than this many per box, and at least kManyPairs:
// below that, the exact directions would cost more than the pairs they save (fans of arcs
// at one vertex, which no box separates, make small dense groups all the time).
constexpr size_t kDensePairs = 16;
constexpr size_t kManyPairs = size_t{1} << 18;

struct CandidatePairs {
  BoxTree tree;
  std::vector<std::pair<uint32_t, uint32_t>> pairs;
};

// The overlapping pairs of n boxes, box_of(i, exact) built from unit estimates, or from
// exact directions when they overlap densely. CAD input packs directions closer together
// than any estimate can tell apart about its axes (a face and a copy of it 0.2 um away,
// seen along their normal: thousands of vertices within 1e-14 of -z), which makes every
// box of such a cluster overlap every other (10^8 pairs, each then decided exactly); the
// boxes of exact directions are tight in the coordinates near zero and part them.
template <class BoxOf>
CandidatePairs candidate_pairs(size_t n, const BoxOf& box_of) {
  std::vector<Box> boxes(n);
  for (size_t i = 0; i < n; ++i) boxes[i] = box_of(i, false);
  CandidatePairs out{BoxTree(boxes), {}};
  const size_t dense = std::max(kDensePairs * n, kManyPairs);
  out.pairs = out.tree.overlapping_pairs(dense);
  if (out.pairs.size() <= dense) return out;
  for (size_t i = 0; i < n; ++i) boxes[i] = box_of(i, true);
  out.tree = BoxTree(boxes);
  out.pairs = out.tree.overlapping_pairs();
  return out;
}

// Each occurrence j (in order) is compared exactly with the representatives, earlier
// occurrences of directions not seen before them, whose boxes overlap its own: every
// occurrence of a direction holds its exact unit vector in its box, so one representative
// per direction is enough, and m nodes of one direction cost m comparisons, where all
// pairs of their boxes cost m^2 / 2 (2,345 nodes of one direction in prusa_y-rod-holder
// F16 made 2.75 M pairs). `candidates(j, visit)` calls visit(i) for earlier occurrences i
// whose boxes overlap j's until it returns true.
template <class Candidates>
uint64_t unite_with_representatives(std::span<const ExactVec> occ, std::span<const uint32_t> distinct,
                                    UnionFind& same, const Candidates& candidates) {
  std::vector<uint8_t> representative(distinct.size(), 0);
  uint64_t compared = 0;
  Interruptions interruptions;
  for (uint32_t j = 0; j < distinct.size(); ++j) {
    interruptions.tick();
    const uint32_t b = distinct[j];
    const bool found = candidates(j, [&](uint32_t i) {
      if (!representative[i]) return false;
      ++compared;
      const uint32_t a = distinct[i];
      if (!exact::same_direction(occ[a], occ[b])) return false;
      same.unite(a, b);  // the later occurrence the root, as for pairs in sorted order
      return true;
    });
    representative[j] = !found;
  }
  return compared;
}

// Candidates from a hash grid of cells 2^-19 wide: each box in the cell of its centre.
// Boxes that overlap have centres at most the widest box's width apart, so j looks in the
// cells within twice that of its own centre (margin for the centres' rounding): one cell,
// but at cell borders. A box tree of the same boxes, built and searched, was 7.4% of the
// profile of the largest parts; this is 2.6%, with the estimates it needs. Empty when
// some cells hold more pairs than `dense`: clusters the grid cannot part.
std::optional<uint64_t> unite_by_grid(std::span<const ExactVec> occ, std::span<const uint32_t> distinct,
                                      std::span<const Box> boxes, size_t dense, UnionFind& same) {
  constexpr double kCell = 0x1p-19;
  constexpr int64_t kOffset = int64_t{1} << 20;  // cells of [-2, 2] in 21 bits each
  const size_t n = distinct.size();
  double reach = 0;
  for (const Box& b : boxes) {
    for (int k = 0; k < 3; ++k) reach = std::max(reach, b.hi[k] - b.lo[k]);
  }
  reach = 2 * reach + 0x1p-40;
  if (!(reach < kCell)) return std::nullopt;
  auto index = [&](double x) { return std::clamp<int64_t>(int64_t(std::floor(x / kCell)), -kOffset, kOffset - 1) + kOffset; };
  auto key = [](const std::array<int64_t, 3>& c) { return uint64_t(c[0]) << 42 | uint64_t(c[1]) << 21 | uint64_t(c[2]); };
  auto centre_cell = [&](const Box& b) {
    std::array<int64_t, 3> c;
    for (int k = 0; k < 3; ++k) c[k] = index((b.lo[k] + b.hi[k]) / 2);
    return c;
  };
  absl::flat_hash_map<uint64_t, uint32_t> cells;  // first a count of boxes, then a list's head + 1
  cells.reserve(n);
  size_t pairs = 0;
  for (const Box& b : boxes) pairs += cells[key(centre_cell(b))]++;
  if (pairs > dense) return std::nullopt;
  for (auto& [k, head] : cells) head = 0;
  std::vector<std::pair<uint32_t, uint32_t>> entries;  // (representative, next entry + 1)
  return unite_with_representatives(occ, distinct, same, [&](uint32_t j, const auto& visit) {
    const Box& b = boxes[j];
    std::array<int64_t, 3> lo, hi;
    for (int k = 0; k < 3; ++k) {
      const double c = (b.lo[k] + b.hi[k]) / 2;
      lo[k] = index(c - reach), hi[k] = index(c + reach);
    }
    for (int64_t x = lo[0]; x <= hi[0]; ++x)
      for (int64_t y = lo[1]; y <= hi[1]; ++y)
        for (int64_t z = lo[2]; z <= hi[2]; ++z) {
          const auto it = cells.find(key({x, y, z}));
          if (it == cells.end()) continue;
          for (uint32_t e = it->second; e != 0; e = entries[e - 1].second) {
            const uint32_t i = entries[e - 1].first;
            if (overlap(boxes[i], b) && visit(i)) return true;
          }
        }
    uint32_t& head = cells[key(centre_cell(b))];
    entries.push_back({j, head});
    head = static_cast<uint32_t>(entries.size());
    return false;
  });
}

// Unites the occurrences (distinct nodes) that are one direction, and returns how many
// exact comparisons that took: with the grid on the estimates' boxes, or where clusters
// are too dense for it, a box tree on the boxes candidate_pairs would choose.
uint64_t unite_equal_directions(std::span<const ExactVec> occ, std::span<const uint32_t> distinct,
                                UnionFind& same) {
  const size_t n = distinct.size();
  const size_t dense = std::max(kDensePairs * n, kManyPairs);
  std::vector<Box> boxes(n);
  for (size_t i = 0; i < n; ++i) boxes[i] = point_box(exact::unit_estimate(occ[distinct[i]]));
  if (const std::optional<uint64_t> compared = unite_by_grid(occ, distinct, boxes, dense, same)) return *compared;
  BoxTree tree(boxes);
  if (tree.overlapping_pairs_exceed(dense)) {
    for (size_t i = 0; i < n; ++i) boxes[i] = exact_point_box(occ[distinct[i]]);
    tree = BoxTree(boxes);
  }
  return unite_with_representatives(occ, distinct, same, [&](uint32_t j, const auto& visit) {
    return tree.visit_overlapping(boxes[j], visit);
  });
}

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

  // Point occurrences: arc endpoints, split points, input points, the reference. Which
  // arc each lies on is one flat list of (arc, occurrence), grouped by arc below: a vector
  // per arc cost two or three allocations per arc of every arrangement.
  std::vector<ExactVec> occ;
  std::vector<std::pair<uint32_t, uint32_t>> on_arc;
  auto add_occ = [&](const ExactVec& p) {
    occ.push_back(p);
    return static_cast<uint32_t>(occ.size() - 1);
  };
  auto add_on = [&](size_t arc, uint32_t k) { on_arc.push_back({static_cast<uint32_t>(arc), k}); };
  occ.reserve(2 * arcs.size() + points.size() + 1);
  on_arc.reserve(2 * arcs.size());
  for (size_t i = 0; i < arcs.size(); ++i) {
    add_on(i, add_occ(arcs[i]->from));
    add_on(i, add_occ(arcs[i]->to));
  }
  std::vector<uint32_t> point_occ;
  for (const ArrangementPoint& p : points) point_occ.push_back(add_occ(p.p));
  const uint32_t reference_occ = add_occ(reference);

  // Candidate pairs from a tree of boxes.
  struct Estimates {
    exact::UnitEstimate from, to, normal;
  };
  std::vector<Estimates> est(arcs.size());
  for (size_t i = 0; i < arcs.size(); ++i) {
    est[i] = {exact::unit_estimate(arcs[i]->from), exact::unit_estimate(arcs[i]->to),
              exact::unit_estimate(arcs[i]->normal)};
  }
  const auto [tree, pairs] = candidate_pairs(arcs.size(), [&](size_t i, bool exact) {
    return exact ? arc_box(exact_point_box(arcs[i]->from), exact_point_box(arcs[i]->to))
                 : arc_box(est[i].from, est[i].to);
  });
  compared_pairs_ += pairs.size();

  // The loops below run over every candidate pair, occurrence and arc: long on big
  // arrangements (one union of large regions takes seconds), cheap per iteration.
  Interruptions interruptions;
  for (auto [i, j] : pairs) {
    interruptions.tick();
    const ArrangementArc& A = *arcs[i];
    const ArrangementArc& B = *arcs[j];
    // Most pairs have one arc strictly on one side of the other's circle: two signs, and
    // none of the tests below.
    const Sign af = exact::sign_dot(A.from, B.normal, est[i].from, est[j].normal);
    const Sign at = exact::sign_dot(A.to, B.normal, est[i].to, est[j].normal);
    if (af == at && af != Sign::kZero) continue;
    // Both ends of an arc shorter than 180 degrees on B's circle: the same circle.
    if (af == Sign::kZero && at == Sign::kZero && exact::parallel(A.normal, B.normal)) {
      // Same great circle: endpoints of one strictly inside the other split it.
      if (strictly_inside(A, B.from)) add_on(i, add_occ(B.from));
      if (strictly_inside(A, B.to)) add_on(i, add_occ(B.to));
      if (strictly_inside(B, A.from)) add_on(j, add_occ(A.from));
      if (strictly_inside(B, A.to)) add_on(j, add_occ(A.to));
      continue;
    }
    const Sign bf = exact::sign_dot(B.from, A.normal, est[j].from, est[i].normal);
    const Sign bt = exact::sign_dot(B.to, A.normal, est[j].to, est[i].normal);
    if (bf == bt && bf != Sign::kZero) continue;
    if (af != Sign::kZero && at != Sign::kZero && bf != Sign::kZero && bt != Sign::kZero) {
      // Proper crossing at X = s (N_A x N_B): inside A iff s = sign(A.from . N_B), inside B
      // iff -s = sign(B.from . N_A) (the two circles meet at +-X).
      if (af == -bf) {
        ExactVec x = af == Sign::kPositive ? exact::cross(A.normal, B.normal)
                                           : exact::cross(B.normal, A.normal);
        add_on(i, add_occ(x));
        add_on(j, add_occ(x));
      }
      continue;
    }
    // An endpoint of one arc on the other's circle is the only meeting point there; an end
    // the arcs share (one node: neighbours along a chain) lies inside neither.
    auto shared = [](const ExactVec& x, const ArrangementArc& other) {
      return x.node() == other.from.node() || x.node() == other.to.node();
    };
    if (af == Sign::kZero && !shared(A.from, B) && strictly_inside(B, A.from)) add_on(j, add_occ(A.from));
    if (at == Sign::kZero && !shared(A.to, B) && strictly_inside(B, A.to)) add_on(j, add_occ(A.to));
    if (bf == Sign::kZero && !shared(B.from, A) && strictly_inside(A, B.from)) add_on(i, add_occ(B.from));
    if (bt == Sign::kZero && !shared(B.to, A) && strictly_inside(A, B.to)) add_on(i, add_occ(B.to));
  }
  // Input points (and the reference) lying inside arcs split them.
  for (size_t k = 0; k <= points.size(); ++k) {
    interruptions.tick();
    const ExactVec& p = k < points.size() ? points[k].p : reference;
    Box b = point_box(exact::unit_estimate(p));
    for (uint32_t i : tree.overlapping(b)) {
      if (exact::sign_dot(p, arcs[i]->normal) == Sign::kZero && strictly_inside(*arcs[i], p)) {
        add_on(i, k < points.size() ? point_occ[k] : reference_occ);
      }
    }
  }

  // Identify equal directions. Occurrences of one shared node are one direction (arcs
  // that meet share their endpoint's node, often dozens of times); the distinct nodes
  // are compared exactly when their boxes overlap.
  UnionFind same(occ.size());
  absl::flat_hash_map<const void*, uint32_t> first_of_node;
  first_of_node.reserve(occ.size());
  std::vector<uint32_t> distinct;
  for (uint32_t k = 0; k < occ.size(); ++k) {
    auto [it, inserted] = first_of_node.try_emplace(occ[k].node(), k);
    if (!inserted) {
      same.unite(k, it->second);
      continue;
    }
    distinct.push_back(k);
  }
  compared_pairs_ += unite_equal_directions(occ, distinct, same);
  std::vector<uint32_t> vertex_of(occ.size(), UINT32_MAX), vertex_of_root(occ.size(), UINT32_MAX);
  for (uint32_t k = 0; k < occ.size(); ++k) {
    uint32_t r = same.find(k);
    if (vertex_of_root[r] == UINT32_MAX) {
      vertex_of_root[r] = static_cast<uint32_t>(vertices_.size());
      vertices_.push_back({occ[r], {}});
    }
    vertex_of[k] = vertex_of_root[r];
  }
  Recorded recorded;
  for (size_t k = 0; k < points.size(); ++k) {
    recorded.points.push_back({vertex_of[point_occ[k]], points[k].layer});
  }
  reference_vertex_ = vertex_of[reference_occ];

  const OccurrencesByArc by_arc(on_arc, arcs.size());
  std::vector<std::pair<uint32_t, uint32_t>>().swap(on_arc);  // the grouped copy is what is used

  // Split every arc at its vertices, in order along it, and merge coinciding pieces.
  absl::flat_hash_map<uint64_t, uint32_t> edge_index;
  edge_index.reserve(on_arc.size());
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
