// The exact search: the 0-1 program min sum x_c, sum_{c covers i} x_c >= 1 solved by
// COIN-OR Cbc (branch and cut over Clp), warm-started with a known cover.
#pragma once

#include <cstdint>
#include <vector>

#include "cover_instance.h"
#include "cover_stop.h"
#include "gvm/status.h"

namespace gvm::planner {

struct CbcCoverResult {
  std::vector<uint32_t> chosen;  // ascending; a cover, never larger than the start
  uint32_t lower_bound = 0;      // proven; at least the bound passed in, at most chosen.size()
  double lp_bound = 0;           // root LP relaxation, or the bound passed in when not reached
  uint64_t nodes = 0;
  bool ran = false;              // false when stopped while waiting for the solver
};

// `start` is a cover of the instance (the incumbent to beat), `lower_bound` a proven bound
// (the packing). Polls `stop` while waiting for the solver and during the search; on a stop
// the best cover found is returned. kInternal when Cbc fails or returns a non-cover.
//
// Cbc and Clp are not safe to run concurrently in one process (see cbc_cover.cpp): calls
// are serialised process-wide. Deterministic for a given instance and start when the
// search is not stopped.
StatusOr<CbcCoverResult> solve_cover_with_cbc(const CoverInstance& instance,
                                              const std::vector<uint32_t>& start,
                                              uint32_t lower_bound, CoverStop& stop);

}  // namespace gvm::planner
