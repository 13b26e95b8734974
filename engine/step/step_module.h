// The STEP reader is a module of its own (libgvm_step.so, Open CASCADE behind it), loaded
// the first time a STEP file is read (step_loader/step_loader.cpp). Why: Open CASCADE's
// libraries are most of the dynamic linker's work when a process starts (every `gvm`
// command paid about 40 ms before main for them, mesh input included), and the daemon
// and mesh-only runs never need them. The module's only visible symbol is the entry
// below; the loader and the module are built from one tree by one compiler, so the
// table passes C++ types.
#pragma once

#include <string>
#include <string_view>

#include "gvm/step.h"

namespace gvm::step_internal {

struct StepModule {
  // read_step on bytes in memory (gvm/step.h); never throws.
  StatusOr<StepPart> (*read_bytes)(std::string_view bytes, const StepOptions& options, const std::string& source);
};

inline constexpr const char* kStepModuleEntry = "gvm_step_module";

}  // namespace gvm::step_internal

extern "C" const gvm::step_internal::StepModule* gvm_step_module();
