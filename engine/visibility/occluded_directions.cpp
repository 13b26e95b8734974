#include "visibility/occluded_directions.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <iterator>
#include <numeric>

#include "parallel/interrupt.h"
#include "sphere/box_tree.h"

namespace gvm {
namespace {

constexpr size_t kGroupCells = 128;
// A group whose border arcs overlap densely is split in halves down to this size, their
// regions merged like the groups': deep in a union, arcs cross many others, and an
// arrangement of all of them holds every crossing, most of which no merged region keeps.
// 16 and 32 were the best measured on the slowest surfaces of four shared parts
// (docs/performance-history.md).
constexpr size_t kSmallestGroup = 16;
constexpr size_t kDensePairs = 32;  // overlapping boxes per arc

// Morton order of a unit vector on a 1024^3 grid: nearby directions, nearby codes.
uint64_t morton(const std::array<double, 3>& u) {
  uint64_t code = 0;
  for (int bit = 9; bit >= 0; --bit) {
    for (int i = 0; i < 3; ++i) {
      const auto cell = static_cast<uint64_t>(std::clamp((u[i] + 1) * 512, 0.0, 1023.0));
      code = code << 1 | ((cell >> bit) & 1);
    }
  }
  return code;
}

// A group's arcs clipped to one window with its coverage at the reference, or none when
// they meet the window's boundary degenerately.
std::optional<sphere::Region> clipped_region(const OccludingCells& cells, const ClipWindow& w,
                                             std::span<const uint32_t> members,
                                             std::span<const sphere::ArrangementArc> arcs,
                                             const exact::ExactVec& reference, int covering) {
  const std::optional<int> corner = cells.coverage_at(members, w.corner(0));
  if (!corner) return std::nullopt;
  const std::optional<std::vector<sphere::ArrangementArc>> clipped = w.clip(arcs, *corner);
  if (!clipped) return std::nullopt;
  return sphere::positive_region(*clipped, reference, w.contains_strictly(reference) ? covering : 0);
}

// Whether more than kDensePairs boxes around other arcs overlap the box of an arc, on average.
bool dense(std::span<const sphere::ArrangementArc> arcs) {
  std::vector<sphere::Box> boxes;
  boxes.reserve(arcs.size());
  for (const sphere::ArrangementArc& a : arcs) {
    boxes.push_back(sphere::arc_box(exact::unit_estimate(a.from), exact::unit_estimate(a.to)));
  }
  return sphere::BoxTree(boxes).overlapping_pairs_exceed(kDensePairs * arcs.size());
}

// The regions of one group: its coverage clipped to each window it meets, or the whole
// group when it has no windows or meets one degenerately (either gives the same GVM); a
// dense group as the regions of its halves.
std::vector<sphere::Region> group_regions(const OccludingCells& cells, std::span<const uint32_t> members,
                                          const exact::ExactVec& reference) {
  const std::vector<sphere::ArrangementArc> arcs = cells.boundary(members);
  if (members.size() > kSmallestGroup && dense(arcs)) {
    const size_t half = members.size() / 2;
    std::vector<sphere::Region> first, second;
    tbb::parallel_invoke([&] { first = group_regions(cells, members.first(half), reference); },
                         [&] { second = group_regions(cells, members.subspan(half), reference); });
    std::move(second.begin(), second.end(), std::back_inserter(first));
    return first;
  }
  int covering = 0;
  for (uint32_t i : members) covering += cells.covers_reference(i);
  std::vector<sphere::Region> regions(cells.windows.size());
  bool clipped = !cells.windows.empty();
  for (size_t k = 0; k < cells.windows.size() && clipped; ++k) {
    std::vector<uint32_t> meeting;
    for (uint32_t i : members) {
      if (cells.meets_window(i, k)) meeting.push_back(i);
    }
    if (meeting.empty()) continue;
    const bool all = meeting.size() == members.size();
    const std::vector<sphere::ArrangementArc> own = all ? std::vector<sphere::ArrangementArc>{} : cells.boundary(meeting);
    int own_covering = covering;
    if (!all) {
      own_covering = 0;
      for (uint32_t i : meeting) own_covering += cells.covers_reference(i);
    }
    std::optional<sphere::Region> r =
        clipped_region(cells, cells.windows[k], meeting, all ? arcs : own, reference, own_covering);
    clipped = r.has_value();
    if (r) regions[k] = std::move(*r);
  }
  if (!clipped) return {sphere::positive_region(arcs, reference, covering)};
  return regions;
}

}  // namespace

sphere::Region occluded_directions(const OccludingCells& cells, const exact::ExactVec& reference) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::pair<uint64_t, uint32_t>> order(cells.count);
  tbb::parallel_for(uint32_t{0}, static_cast<uint32_t>(cells.count),
                    [&](uint32_t i) { order[i] = {morton(cells.direction(i)), i}; });
  interruption_point();
  std::sort(order.begin(), order.end());
  const size_t group_count = (order.size() + kGroupCells - 1) / kGroupCells;
  std::vector<std::vector<sphere::Region>> groups(group_count);
  tbb::parallel_for(size_t{0}, group_count, [&](size_t g) {
    std::vector<uint32_t> members;
    for (size_t k = g * kGroupCells; k < std::min(order.size(), (g + 1) * kGroupCells); ++k) {
      members.push_back(order[k].second);
    }
    groups[g] = group_regions(cells, members, reference);
  });
  interruption_point();  // groups left undone when cancelled
  // Window by window, so that the first unions merge regions clipped to one window (split
  // groups have more regions: the windows of each half in turn).
  std::vector<sphere::Region> regions;
  size_t windows = 0;
  for (const std::vector<sphere::Region>& group : groups) windows = std::max(windows, group.size());
  for (size_t k = 0; k < windows; ++k) {
    for (std::vector<sphere::Region>& group : groups) {
      if (k >= group.size()) continue;
      sphere::Region& r = group[k];
      if (!r.boundary.empty() || r.contains_reference) regions.push_back(std::move(r));
    }
  }
  const auto union_start = std::chrono::steady_clock::now();
  spdlog::debug("occluded directions: {} cells in {} groups, {} regions, {:.2f} s; {} group arrangement vertices",
                cells.count, group_count, regions.size(),
                std::chrono::duration<double>(union_start - start).count(),
                std::accumulate(regions.begin(), regions.end(), uint64_t{0},
                                [](uint64_t n, const sphere::Region& r) { return n + r.arrangement_vertices; }));
  sphere::Region out = sphere::region_union(std::move(regions), reference);
  spdlog::debug("occluded directions: union {:.2f} s, {} arrangement vertices in all",
                std::chrono::duration<double>(std::chrono::steady_clock::now() - union_start).count(),
                out.arrangement_vertices);
  return out;
}

}  // namespace gvm
