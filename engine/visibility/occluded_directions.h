// The closure of the directions occluded by a set of cells on the sphere (projected
// envelope faces, or pairwise occlusion maps), as one closed region.
//
// Cells are put in groups of nearby directions; each group's coverage is described by
// arcs (its border chain) and turned into a region (sphere::positive_region), and the
// regions are merged pairwise up a balanced tree (sphere::region_union). Only the closed
// region matters for Int(GOM), and the closure of a union is the union of the closures.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "sphere/region_union.h"
#include "visibility/clip_window.h"

namespace gvm {

struct OccludingCells {
  size_t count = 0;
  // A direction in or near cell i: cells with nearby directions go in one group.
  std::function<std::array<double, 3>(uint32_t)> direction;
  // Arcs whose coverage is, everywhere, the number of the given cells over a direction
  // (up to a constant): their boundaries, or their border chain.
  std::function<std::vector<sphere::ArrangementArc>(std::span<const uint32_t>)> boundary;
  // Whether cell i covers the reference direction (which lies on none of their arcs).
  std::function<bool(uint32_t)> covers_reference;
  // Optional: each group clipped to windows whose interiors together hold the LVM
  // (clip_window.h), which then needs whether cell i meets window k in positive area, and
  // the coverage of a group at a direction (none when it lies on a cell's boundary).
  std::span<const ClipWindow> windows;
  std::function<bool(uint32_t, size_t)> meets_window;
  std::function<std::optional<int>(std::span<const uint32_t>, const exact::ExactVec&)> coverage_at;
};

sphere::Region occluded_directions(const OccludingCells& cells, const exact::ExactVec& reference);

}  // namespace gvm
