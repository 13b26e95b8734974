// Reductions of a set-cover problem that keep its optimum, then its split into independent
// components (items connected through shared candidates), each solved on its own.
//
// Repeated until nothing changes:
//  - a candidate whose items (among those left) are all in another candidate is dropped
//    (of two equal ones the lower index stays): some optimal cover avoids it;
//  - an item whose candidates include all the candidates of another item is dropped
//    (of two equal ones the lower index stays): covering the other covers it;
//  - an item left with one candidate forces that candidate, which is chosen and removed
//    with every item it covers.
// Every alive item keeps at least one candidate throughout. A packing of the reduced
// problem is a packing of the original one (two items sharing a dropped candidate share the
// candidate that dominated it), and so are the items that forced their candidates, together
// with any packing of what is left.
#pragma once

#include <cstdint>
#include <vector>

#include "cover_instance.h"
#include "set_cover.h"

namespace gvm::planner {

struct CoverComponent {
  CoverInstance instance;               // on local ids
  std::vector<uint32_t> item_ids;       // local item -> problem item, ascending
  std::vector<uint32_t> candidate_ids;  // local candidate -> problem candidate, ascending
};

struct ReducedCover {
  std::vector<uint32_t> uncoverable;       // problem items in no candidate, ascending
  std::vector<uint32_t> forced;            // problem candidates every minimum cover can take
  std::vector<uint32_t> forced_items;      // per forced candidate, the item only it covered
  std::vector<CoverComponent> components;  // ordered by their first item
};

// Precondition: every candidate lists item ids < problem.items, ascending without repeats.
ReducedCover reduce_cover(const CoverProblem& problem);

}  // namespace gvm::planner
