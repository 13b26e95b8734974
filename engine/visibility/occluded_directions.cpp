#include "visibility/occluded_directions.h"

#include <tbb/parallel_for.h>

#include <algorithm>

#include "exact/interrupt.h"

namespace gvm {
namespace {

constexpr size_t kGroupCells = 128;

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

// A group's arcs and its coverage at the reference, clipped to the window when the arcs
// meet its boundary generically (left whole otherwise: either gives the same GVM).
void clip_group(const OccludingCells& cells, std::span<const uint32_t> members,
                const exact::ExactVec& reference, std::vector<sphere::ArrangementArc>& arcs,
                int& covering) {
  const ClipWindow& w = *cells.window;
  const std::optional<int> corner = cells.coverage_at(members, w.corner(0));
  if (!corner) return;
  std::optional<std::vector<sphere::ArrangementArc>> clipped = w.clip(arcs, *corner);
  if (!clipped) return;
  arcs = std::move(*clipped);
  if (!w.contains_strictly(reference)) covering = 0;
}

}  // namespace

sphere::Region occluded_directions(const OccludingCells& cells, const exact::ExactVec& reference) {
  std::vector<std::pair<uint64_t, uint32_t>> order(cells.count);
  tbb::parallel_for(uint32_t{0}, static_cast<uint32_t>(cells.count),
                    [&](uint32_t i) { order[i] = {morton(cells.direction(i)), i}; });
  interruption_point();
  std::sort(order.begin(), order.end());
  std::vector<sphere::Region> groups((order.size() + kGroupCells - 1) / kGroupCells);
  tbb::parallel_for(size_t{0}, groups.size(), [&](size_t g) {
    std::vector<uint32_t> members;
    int covering = 0;
    for (size_t k = g * kGroupCells; k < std::min(order.size(), (g + 1) * kGroupCells); ++k) {
      members.push_back(order[k].second);
      covering += cells.covers_reference(order[k].second);
    }
    std::vector<sphere::ArrangementArc> arcs = cells.boundary(members);
    if (cells.window) clip_group(cells, members, reference, arcs, covering);
    groups[g] = sphere::positive_region(arcs, reference, covering);
  });
  interruption_point();  // groups left undone when cancelled
  return sphere::region_union(std::move(groups), reference);
}

}  // namespace gvm
