// The options of a plan on the command line (gvm plan, gvm batch, gvm-mpi batch).
#pragma once

#include <string>

#include "gvm/v1/plan.pb.h"

namespace CLI {
class App;
}  // namespace CLI

namespace gvm::cli {

// --mode, --surfaces, --concave-only, --planar-normal, --split, --time-limit,
// --min-clearance and the probe's --head, --part-up, --cone, read into `options`.
void add_plan_options(CLI::App& command, v1::PlanOptions& options);

// The planner's message about an option, with the flag named ("--cone (cone_degrees) ...").
std::string with_flag_names(const std::string& message);

}  // namespace gvm::cli
