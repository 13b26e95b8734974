// The STEP module loaded on the first call (step/step_module.h says why), looked for beside
// the running program first, so that programs copied elsewhere together with
// libgvm_step.so keep reading STEP, then where the build put it. A module that cannot be
// loaded is an error of that call, naming the module and the loader's reason.
#include "step_loader/step_module_loader.h"

#include <dlfcn.h>

#include <filesystem>

#include "step/step_module.h"

namespace gvm::step_internal {
namespace {

struct Loaded {
  const StepModule* module = nullptr;
  std::string path;
  std::string error;
};

// Loaded once per process, never unloaded (Open CASCADE keeps process-wide statics).
const Loaded& step_module() {
  static const Loaded loaded = [] {
    Loaded out;
    out.path = beside_program(GVM_STEP_MODULE);
    void* handle = dlopen(out.path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      out.error = dlerror();
      return out;
    }
    using Entry = const StepModule* (*)();
    auto entry = reinterpret_cast<Entry>(dlsym(handle, step_internal::kStepModuleEntry));
    if (!entry) {
      out.error = std::string("no entry ") + step_internal::kStepModuleEntry;
      return out;
    }
    out.module = entry();
    return out;
  }();
  return loaded;
}

}  // namespace

std::string beside_program(const std::string& built) {
  std::error_code ec;
  const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const std::filesystem::path beside = program.parent_path() / std::filesystem::path(built).filename();
    if (std::filesystem::exists(beside, ec)) return beside.string();
  }
  return built;
}

StatusOr<StepPart> read_step_in_process(std::string_view bytes, const StepOptions& options, const std::string& source) {
  const Loaded& loaded = step_module();
  if (!loaded.module) {
    return Internal(source + ": STEP input needs the module " + loaded.path +
                              ", which could not be loaded (" + loaded.error + ")");
  }
  return loaded.module->read_bytes(bytes, options, source);
}

}  // namespace gvm::step_internal
