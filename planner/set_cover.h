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
  // 0: no limit. Counted from the call, including any wait for the solver (one search runs
  // at a time in the process). The search stops at its next check of the clock; LPs still
  // running half a second past the limit are cut short.
  double time_limit_seconds = 0;
  // Polled during the search; returning true stops it: the best cover found so far is
  // returned (not proven optimal unless it meets the bound), with `cancelled` set.
  // Called from the solving thread: every 20 ms while it waits for the solver, then at each
  // simplex iteration and each of the solver's events (so it should be cheap).
  std::function<bool()> cancelled;
};

struct CoverSolution {
  std::vector<uint32_t> chosen;        // candidate indices, ascending; covers every coverable item
  uint32_t lower_bound = 0;            // proven: no cover of the coverable items is smaller
  bool optimal = false;                // chosen.size() == lower_bound
  uint32_t greedy = 0;                 // size of the greedy cover (on the reduced problem, plus forced)
  // Coverable items no two of which are in one candidate (so any cover needs at least
  // this many candidates), as large as found; ascending.
  std::vector<uint32_t> packing;
  std::vector<uint32_t> uncoverable;   // items in no candidate, ascending

  // What the solver did.
  uint32_t reduced_candidates = 0;     // candidates left after removing duplicates and dominated ones
  uint32_t reduced_items = 0;          // items left after removing those implied by others
  // Candidates taken before any search because an item had no other (after the reductions);
  // they are in `chosen` and counted in the sizes and bounds, not in reduced_*.
  uint32_t forced = 0;
  uint32_t components = 0;             // independent parts of the reduced problem, solved apart
  bool solver_ran = false;             // false when greedy met the packing bound (or trivial)
  // LP relaxation bound of the whole problem: the root LP of the components searched, the
  // packing size elsewhere (there it equals the LP), plus `forced`. Where a stop came
  // before a root LP was solved, that component counts its packing size.
  double lp_bound = 0;
  uint64_t nodes = 0;                  // branch-and-bound nodes
  bool time_limit_reached = false;
  bool cancelled = false;
  double seconds = 0;
};

// Deterministic (the same problem gives the same solution, unless stopped by the time
// limit or a cancel) and safe to call from several threads at once. Candidate lists need not
// be sorted. Fails with kInvalidArgument when a candidate names an item >= items, and with
// kInternal when the solver itself fails.
StatusOr<CoverSolution> solve_set_cover(const CoverProblem& problem, const CoverOptions& options);

}  // namespace gvm::planner
