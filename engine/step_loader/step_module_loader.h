// The STEP module (libgvm_step.so, step/step_module.h) loaded into this process and asked
// to read: what the STEP worker does (engine/step_worker/), and nothing else should --
// read_step (gvm/step.h) runs it in a worker process, where a crash or a loop of Open
// CASCADE's costs that part only.
#pragma once

#include <string>
#include <string_view>

#include "gvm/step.h"

namespace gvm::step_internal {

// read_step on bytes, here. The module is loaded on the first call, beside the program
// first, then where the build put it; one that cannot be loaded fails the call, naming it.
StatusOr<StepPart> read_step_in_process(std::string_view bytes, const StepOptions& options, const std::string& source);

// Where a program's companion file is: beside the running program when it is there, else
// `built` (the build tree's path).
std::string beside_program(const std::string& built);

}  // namespace gvm::step_internal
