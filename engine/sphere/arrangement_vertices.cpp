// The vertices of an arrangement: where its arcs meet (candidate pairs of boxes, decided
// exactly) and which of those occurrences are one direction.
#include "sphere/arrangement_vertices.h"

#include <absl/container/flat_hash_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "parallel/interrupt.h"
#include "sphere/box_tree.h"
#include "sphere/union_find.h"

namespace gvm::sphere::arrangement_internal {
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
// but at cell borders. A box tree of the same boxes, built and searched, cost about three
// times as much on the largest parts (docs/performance-history.md). Empty when some cells
// hold more pairs than `dense`: clusters the grid cannot part.
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

// Where the arcs of candidate pair (i, j) meet, as occurrences on each.
void add_meeting(const ArrangementArc& A, const ArrangementArc& B, size_t i, size_t j,
                 const std::array<exact::UnitEstimate, 3>& ea, const std::array<exact::UnitEstimate, 3>& eb,
                 Occurrences& o) {
  // Most pairs have one arc strictly on one side of the other's circle: two signs, and
  // none of the tests below. (Estimates: from, to, normal.)
  const Sign af = exact::sign_dot(A.from, B.normal, ea[0], eb[2]);
  const Sign at = exact::sign_dot(A.to, B.normal, ea[1], eb[2]);
  if (af == at && af != Sign::kZero) return;
  // Both ends of an arc shorter than 180 degrees on B's circle: the same circle.
  if (af == Sign::kZero && at == Sign::kZero && exact::parallel(A.normal, B.normal)) {
    // Same great circle: endpoints of one strictly inside the other split it.
    if (strictly_inside(A, B.from)) o.on(i, o.add(B.from));
    if (strictly_inside(A, B.to)) o.on(i, o.add(B.to));
    if (strictly_inside(B, A.from)) o.on(j, o.add(A.from));
    if (strictly_inside(B, A.to)) o.on(j, o.add(A.to));
    return;
  }
  const Sign bf = exact::sign_dot(B.from, A.normal, eb[0], ea[2]);
  const Sign bt = exact::sign_dot(B.to, A.normal, eb[1], ea[2]);
  if (bf == bt && bf != Sign::kZero) return;
  if (af != Sign::kZero && at != Sign::kZero && bf != Sign::kZero && bt != Sign::kZero) {
    // Proper crossing at X = s (N_A x N_B): inside A iff s = sign(A.from . N_B), inside B
    // iff -s = sign(B.from . N_A) (the two circles meet at +-X).
    if (af == -bf) {
      ExactVec x = af == Sign::kPositive ? exact::cross(A.normal, B.normal) : exact::cross(B.normal, A.normal);
      o.on(i, o.add(x));
      o.on(j, o.add(x));
    }
    return;
  }
  // An endpoint of one arc on the other's circle is the only meeting point there; an end
  // the arcs share (one node: neighbours along a chain) lies inside neither.
  auto shared = [](const ExactVec& x, const ArrangementArc& other) {
    return x.node() == other.from.node() || x.node() == other.to.node();
  };
  if (af == Sign::kZero && !shared(A.from, B) && strictly_inside(B, A.from)) o.on(j, o.add(A.from));
  if (at == Sign::kZero && !shared(A.to, B) && strictly_inside(B, A.to)) o.on(j, o.add(A.to));
  if (bf == Sign::kZero && !shared(B.from, A) && strictly_inside(A, B.from)) o.on(i, o.add(B.from));
  if (bt == Sign::kZero && !shared(B.to, A) && strictly_inside(A, B.to)) o.on(i, o.add(B.to));
}

}  // namespace

Occurrences occurrences(std::span<const ArrangementArc* const> arcs, std::span<const ArrangementPoint> points,
                        const ExactVec& reference) {
  Occurrences o;
  o.occ.reserve(2 * arcs.size() + points.size() + 1);
  o.on_arc.reserve(2 * arcs.size());
  for (size_t i = 0; i < arcs.size(); ++i) {
    o.on(i, o.add(arcs[i]->from));
    o.on(i, o.add(arcs[i]->to));
  }
  for (const ArrangementPoint& p : points) o.point_occ.push_back(o.add(p.p));
  o.reference_occ = o.add(reference);

  std::vector<std::array<exact::UnitEstimate, 3>> est(arcs.size());
  for (size_t i = 0; i < arcs.size(); ++i) {
    est[i] = {exact::unit_estimate(arcs[i]->from), exact::unit_estimate(arcs[i]->to),
              exact::unit_estimate(arcs[i]->normal)};
  }
  const CandidatePairs candidates = candidate_pairs(arcs.size(), [&](size_t i, bool exact) {
    return exact ? arc_box(exact_point_box(arcs[i]->from), exact_point_box(arcs[i]->to))
                 : arc_box(est[i][0], est[i][1]);
  });
  o.compared_pairs = candidates.pairs.size();
  // Long on big arrangements (one union of large regions takes seconds), cheap per pair.
  Interruptions interruptions;
  for (auto [i, j] : candidates.pairs) {
    interruptions.tick();
    add_meeting(*arcs[i], *arcs[j], i, j, est[i], est[j], o);
  }
  for (size_t k = 0; k <= points.size(); ++k) {
    interruptions.tick();
    const ExactVec& p = k < points.size() ? points[k].p : reference;
    const Box b = point_box(exact::unit_estimate(p));
    for (uint32_t i : candidates.tree.overlapping(b)) {
      if (exact::sign_dot(p, arcs[i]->normal) == Sign::kZero && strictly_inside(*arcs[i], p)) {
        o.on(i, k < points.size() ? o.point_occ[k] : o.reference_occ);
      }
    }
  }
  return o;
}

std::vector<uint32_t> vertices_of(std::span<const ExactVec> occ, std::vector<Arrangement::Vertex>& vertices,
                                  uint64_t& compared_pairs) {
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
  compared_pairs += unite_equal_directions(occ, distinct, same);
  std::vector<uint32_t> vertex_of(occ.size(), UINT32_MAX), vertex_of_root(occ.size(), UINT32_MAX);
  for (uint32_t k = 0; k < occ.size(); ++k) {
    const uint32_t r = same.find(k);
    if (vertex_of_root[r] == UINT32_MAX) {
      vertex_of_root[r] = static_cast<uint32_t>(vertices.size());
      vertices.push_back({occ[r], {}});
    }
    vertex_of[k] = vertex_of_root[r];
  }
  return vertex_of;
}

}  // namespace gvm::sphere::arrangement_internal
