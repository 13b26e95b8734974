// The two cheap bounds on a minimum set cover. The greedy cover is the solver's warm start
// and the upper bound; a packing (items no two of which share a candidate) is a lower bound
// anyone can check: each of its items needs a candidate of its own. When they meet, the
// greedy cover is optimal.
#pragma once

#include <cstdint>
#include <vector>

#include "cover_instance.h"

namespace gvm::planner {

// Greedy cover of every item (each must be in some candidate): repeatedly the candidate
// covering the most uncovered items, the lowest index among equals; then candidates all of
// whose items are covered twice are dropped, last picked first. Ascending candidate ids.
std::vector<uint32_t> greedy_cover(const CoverInstance& instance);

// Drops candidates all of whose items the others cover, the last in `order` first.
// Ascending candidate ids.
std::vector<uint32_t> drop_redundant(const CoverInstance& instance, const std::vector<uint32_t>& order);

// A maximal packing, items with the fewest candidates first (lowest index among equals),
// grown by swaps that trade one packed item for two. Ascending item ids.
std::vector<uint32_t> greedy_packing(const CoverInstance& instance);

// True when no two of the items share a candidate.
bool is_packing(const CoverInstance& instance, const std::vector<uint32_t>& items);

}  // namespace gvm::planner
