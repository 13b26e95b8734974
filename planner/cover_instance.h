// A set-cover instance held both ways round (the items of each candidate and the candidates
// of each item), on local ids 0..n-1: the form the reductions, the bounds and the solver use.
#pragma once

#include <cstdint>
#include <vector>

namespace gvm::planner {

struct CoverInstance {
  std::vector<std::vector<uint32_t>> items_of;       // per candidate: the items it covers, ascending
  std::vector<std::vector<uint32_t>> candidates_of;  // per item: the candidates covering it, ascending

  uint32_t item_count() const { return static_cast<uint32_t>(candidates_of.size()); }
  uint32_t candidate_count() const { return static_cast<uint32_t>(items_of.size()); }
};

// Builds the item side from the candidate side (each list ascending, every id < items).
CoverInstance make_cover_instance(uint32_t items, std::vector<std::vector<uint32_t>> items_of);

// True when the chosen candidates (any order) together cover every item of the instance.
bool covers_all(const CoverInstance& instance, const std::vector<uint32_t>& chosen);

}  // namespace gvm::planner
