// Minimum set cover, solved exactly: which fewest candidates (setup directions, rotary
// axes, head orientations) cover every item (feature) that some candidate covers.
//
// Greedy gives the warm start and the upper bound; a packing (items no two of which share
// a candidate) gives a lower bound anyone can check; when they meet, no solver is needed.
// Otherwise COIN-OR Cbc solves the 0-1 program min sum x_c, sum_{c covers i} x_c >= 1,
// and its proven bound is reported with the best cover found (within a time limit).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "gvm/status.h"

namespace gvm::planner {

struct CoverProblem {
  uint32_t items = 0;
  // Item ids each candidate covers (ascending, each < items). An item in no candidate is
  // uncoverable: it is reported and left out of the cover.
  std::vector<std::vector<uint32_t>> candidates;
};

struct CoverOptions {
  double time_limit_seconds = 0;       // 0: no limit
  // Polled during the search; returning true stops it: the best cover found so far is
  // returned (not proven optimal unless it meets the bound), with `cancelled` set.
  std::function<bool()> cancelled;
};

struct CoverSolution {
  std::vector<uint32_t> chosen;        // candidate indices, ascending; covers every coverable item
  uint32_t lower_bound = 0;            // proven: no cover of the coverable items is smaller
  bool optimal = false;                // chosen.size() == lower_bound
  uint32_t greedy = 0;                 // size of the greedy cover
  // Coverable items no two of which are in one candidate (so any cover needs at least
  // this many candidates), as large as found.
  std::vector<uint32_t> packing;
  std::vector<uint32_t> uncoverable;   // items in no candidate, ascending

  // What the solver did.
  uint32_t reduced_candidates = 0;     // candidates left after removing duplicates and dominated ones
  uint32_t reduced_items = 0;          // items left after removing those implied by others
  bool solver_ran = false;             // false when greedy met the packing bound (or trivial)
  double lp_bound = 0;                 // LP relaxation bound at the root (when the solver ran)
  uint64_t nodes = 0;                  // branch-and-bound nodes
  bool time_limit_reached = false;
  bool cancelled = false;
  double seconds = 0;
};

// Deterministic (the same problem gives the same solution) and safe to call from several
// threads at once. Fails only with kInternal when the solver itself fails.
StatusOr<CoverSolution> solve_set_cover(const CoverProblem& problem, const CoverOptions& options);

}  // namespace gvm::planner
