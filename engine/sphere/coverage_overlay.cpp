#include "sphere/coverage_overlay.h"

#include <algorithm>
#include <iterator>
#include <unordered_map>

#include "parallel/interrupt.h"
#include "sphere/arrangement.h"
#include "sphere/cell_witness.h"
#include "sphere/image_overlay.h"

namespace gvm::sphere {
namespace {

using exact::ExactVec;

Arrangement overlay(std::span<const SphericalImage> sets, ExactVec& reference,
                    std::vector<int>& reference_count) {
  std::vector<ArrangementArc> arcs;
  std::vector<ArrangementPoint> points;
  for (size_t k = 0; k < sets.size(); ++k) add_image(sets[k], static_cast<int>(k), arcs, points);
  reference = generic_direction(arcs, points);
  reference_count.resize(sets.size());
  for (size_t k = 0; k < sets.size(); ++k) reference_count[k] = face_winding(sets[k], reference);
  return Arrangement(arcs, points, reference);
}

// The running coverage counts of every set during the walk over the faces, with the sets
// of positive count as a bit set (listed in ascending order by a scan of N / 64 words).
class RunningCoverage {
 public:
  explicit RunningCoverage(const std::vector<int>& counts)
      : count_(counts), bits_((counts.size() + 63) / 64, 0) {
    for (size_t k = 0; k < count_.size(); ++k) update(k);
  }
  // Add s times the weights of `layers`.
  void apply(std::span<const LayerWeight> layers, int s) {
    for (const LayerWeight& lw : layers) {
      count_[size_t(lw.layer)] += s * lw.weight;
      update(size_t(lw.layer));
    }
  }
  void list(std::vector<uint32_t>& out) const {
    out.clear();
    for (size_t w = 0; w < bits_.size(); ++w) {
      for (uint64_t b = bits_[w]; b; b &= b - 1) {
        out.push_back(static_cast<uint32_t>(64 * w + size_t(__builtin_ctzll(b))));
      }
    }
  }

 private:
  void update(size_t k) {
    const uint64_t bit = uint64_t{1} << (k % 64);
    bits_[k / 64] = count_[k] > 0 ? bits_[k / 64] | bit : bits_[k / 64] & ~bit;
  }
  std::vector<int> count_;
  std::vector<uint64_t> bits_;
};

// Sorted union of a sorted list and some extra set indices (any order), into `out`.
void merged(const std::vector<uint32_t>& sorted, std::vector<uint32_t>& extra, std::vector<uint32_t>& out) {
  std::sort(extra.begin(), extra.end());
  out.clear();
  std::set_union(sorted.begin(), sorted.end(), extra.begin(), extra.end(), std::back_inserter(out));
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

struct SetHash {
  size_t operator()(const std::vector<uint32_t>& s) const {
    uint64_t h = 1469598103934665603ull;
    for (uint32_t x : s) h = (h ^ x) * 1099511628211ull;
    return static_cast<size_t>(h);
  }
};

}  // namespace

struct CoverageOverlay::Impl {
  Impl(std::span<const SphericalImage> sets) : count(sets.size()), arr(overlay(sets, reference, reference_count)) {}

  size_t count;
  ExactVec reference;
  std::vector<int> reference_count;
  Arrangement arr;

  struct Scratch {
    std::vector<uint32_t> face_cov, extra, cov;
  };
  void walk(bool all_kinds, const std::function<void(const Cell&)>& visit) const;
  void visit_face(uint32_t f, const RunningCoverage& running, bool all_kinds, Scratch& scratch,
                  const std::function<void(const Cell&)>& visit) const;
};

// Depth first over the faces across edges, from the reference face, with one running count
// per set: crossing half-edge h into the face on its right subtracts h's layer weights,
// and backtracking adds them back. Memory: the counts and the path.
void CoverageOverlay::Impl::walk(bool all_kinds, const std::function<void(const Cell&)>& visit) const {
  const auto& half = arr.half_edges();
  const auto& faces = arr.faces();
  RunningCoverage running(reference_count);
  Scratch scratch;
  std::vector<bool> seen(faces.size(), false);
  struct Frame {
    uint32_t face, cursor, entry;  // cursor: next half-edge to cross; entry: how we came
  };
  constexpr uint32_t kNone = UINT32_MAX;
  const uint32_t start = arr.reference_face();
  seen[start] = true;
  visit_face(start, running, all_kinds, scratch, visit);
  std::vector<Frame> path = {{start, faces[start].first_half_edge, kNone}};
  Interruptions interruptions;
  while (!path.empty()) {
    interruptions.tick();
    Frame& top = path.back();
    if (top.cursor == kNone) {
      const uint32_t entry = top.entry;
      path.pop_back();
      if (entry != kNone) running.apply(arr.edge_layers(half[entry].edge), half[entry].forward ? 1 : -1);
      continue;
    }
    const uint32_t h = top.cursor;
    top.cursor = half[h].next == faces[top.face].first_half_edge ? kNone : half[h].next;
    const uint32_t g = half[half[h].twin].face;
    if (seen[g]) continue;
    seen[g] = true;
    running.apply(arr.edge_layers(half[h].edge), half[h].forward ? -1 : 1);
    visit_face(g, running, all_kinds, scratch, visit);
    path.push_back({g, faces[g].first_half_edge, h});
  }
}

// The face, and the edges and vertices it owns: edge e belongs to the face on the left
// of its forward half-edge 2e, vertex v to the face of its first outgoing half-edge (a
// vertex with no edges, only possible alone on the sphere, to the one face).
void CoverageOverlay::Impl::visit_face(uint32_t f, const RunningCoverage& running, bool all_kinds,
                                       Scratch& scratch,
                                       const std::function<void(const Cell&)>& visit) const {
  const auto& half = arr.half_edges();
  // Plain references, not a structured binding: lambdas may not capture those before
  // clang 16 (the fuzz preset builds with Debian's clang 14).
  auto &face_cov = scratch.face_cov, &extra = scratch.extra, &cov = scratch.cov;
  running.list(face_cov);
  if (all_kinds) visit({CellKind::kFace, f, direction_inside_face(arr, f), face_cov});
  auto visit_vertex = [&](uint32_t v) {
    extra.assign(arr.vertex_points(v).begin(), arr.vertex_points(v).end());
    for (uint32_t h : arr.vertices()[v].out) {
      for (const LayerWeight& lw : arr.edge_layers(half[h].edge)) extra.push_back(uint32_t(lw.layer));
    }
    merged(face_cov, extra, cov);
    visit({CellKind::kVertex, v, arr.vertices()[v].p, cov});
  };
  const uint32_t h0 = arr.faces()[f].first_half_edge;
  if (h0 == UINT32_MAX) {
    for (uint32_t v = 0; v < arr.vertices().size(); ++v) visit_vertex(v);
    return;
  }
  uint32_t h = h0;
  do {
    const uint32_t e = half[h].edge;
    if (all_kinds && h == 2 * e) {
      extra.clear();
      for (const LayerWeight& lw : arr.edge_layers(e)) extra.push_back(uint32_t(lw.layer));
      merged(face_cov, extra, cov);
      visit({CellKind::kEdge, e, direction_inside_edge(arr, e), cov});
    }
    if (arr.vertices()[half[h].origin].out[0] == h) visit_vertex(half[h].origin);
    h = half[h].next;
  } while (h != h0);
}

CoverageOverlay::CoverageOverlay(std::span<const SphericalImage> sets)
    : impl_(std::make_unique<Impl>(sets)) {}
CoverageOverlay::CoverageOverlay(CoverageOverlay&&) noexcept = default;
CoverageOverlay& CoverageOverlay::operator=(CoverageOverlay&&) noexcept = default;
CoverageOverlay::~CoverageOverlay() = default;

size_t CoverageOverlay::set_count() const { return impl_->count; }
size_t CoverageOverlay::vertex_count() const { return impl_->arr.vertices().size(); }
size_t CoverageOverlay::edge_count() const { return impl_->arr.edges().size(); }
size_t CoverageOverlay::face_count() const { return impl_->arr.faces().size(); }

void CoverageOverlay::for_each_cell(const std::function<void(const Cell&)>& visit) const {
  impl_->walk(true, visit);
}

// Distinct vertex coverages (the first vertex met as witness), then, by decreasing size,
// each kept unless a kept one contains it. A kept superset has at least one more element,
// so it is met first; candidates are the kept sets containing the candidate's rarest
// element.
std::vector<CoverageOverlay::MaximalCoverage> CoverageOverlay::maximal_coverage() const {
  std::vector<MaximalCoverage> distinct;
  std::unordered_map<std::vector<uint32_t>, uint32_t, SetHash> index;
  impl_->walk(false, [&](const Cell& c) {
    if (c.coverage.empty()) return;
    std::vector<uint32_t> key(c.coverage.begin(), c.coverage.end());
    if (index.try_emplace(key, static_cast<uint32_t>(distinct.size())).second) {
      distinct.push_back({c.witness, std::move(key)});
    }
  });
  std::stable_sort(distinct.begin(), distinct.end(), [](const MaximalCoverage& a, const MaximalCoverage& b) {
    return a.coverage.size() > b.coverage.size();
  });
  std::vector<MaximalCoverage> kept;
  std::vector<std::vector<uint32_t>> containing(impl_->count);  // set -> kept sets with it
  Interruptions interruptions(64);
  for (MaximalCoverage& candidate : distinct) {
    interruptions.tick();
    const std::vector<uint32_t>& s = candidate.coverage;
    uint32_t rarest = s[0];
    for (uint32_t k : s) {
      if (containing[k].size() < containing[rarest].size()) rarest = k;
    }
    bool dominated = false;
    for (uint32_t t : containing[rarest]) {
      const std::vector<uint32_t>& big = kept[t].coverage;
      if (std::includes(big.begin(), big.end(), s.begin(), s.end())) {
        dominated = true;
        break;
      }
    }
    if (dominated) continue;
    for (uint32_t k : s) containing[k].push_back(static_cast<uint32_t>(kept.size()));
    kept.push_back(std::move(candidate));
  }
  return kept;
}

}  // namespace gvm::sphere
