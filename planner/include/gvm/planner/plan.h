// The planner: the fewest setup directions (3-axis), rotary axes (4-axis indexer) or
// probe head orientations (CMM) that reach every planned surface of an analysed part,
// decided on the engine's exact maps, with a proof of optimality (a lower bound equal to
// the number of setups) or the gap to it.
#pragma once

#include <cstddef>
#include <functional>
#include <stop_token>
#include <string_view>
#include <vector>

#include "gvm/analysis.h"
#include "gvm/direction.h"
#include "gvm/status.h"
#include "gvm/v1/plan.pb.h"

namespace gvm::planner {

// Checks the options; the error names the offending field and value.
Status validate(const v1::PlanOptions& options);
// The options with every default filled in (what a plan reports as applied).
v1::PlanOptions with_defaults(const v1::PlanOptions& options);

struct PlanControl {
  // Called now and then with (phase, done, total); returning false cancels (kCancelled).
  std::function<bool(std::string_view phase, size_t done, size_t total)> progress;
  // A stop request cancels the plan within about a second (kCancelled), also inside the
  // exact cover's overlay, the Cbc search and the maps of --split pieces.
  std::stop_token stop;
};

struct SetupPlan {
  v1::Plan message;                 // the plan as written (doubles rounded once, here)
  // The exact direction (rotary: axis) of each setup, in the order of message.setups:
  // it lies in the reach set of every surface the setup is assigned, decided exactly.
  std::vector<Direction> directions;
};

// Plans from an analysis (only read; the plan keeps copies of what it needs).
// Fails with kInvalidArgument for bad options, kCancelled when the control says so (a
// stop request, or progress returning false).
StatusOr<SetupPlan> plan(const Analysis& analysis, const v1::PlanOptions& options,
                         const PlanControl& control = {});

}  // namespace gvm::planner
