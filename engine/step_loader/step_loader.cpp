// read_step (gvm/step.h): the file read here, the bytes handed to the STEP module, which is
// loaded on the first call (step/step_module.h says why). The module is looked for beside
// the running program first, so that gvm and gvmd copied elsewhere together with
// libgvm_step.so keep reading STEP, then where the build put it. A module that cannot be
// loaded is an error of that call, naming the module and the loader's reason; mesh input
// never needs it.
#include <dlfcn.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "step/step_module.h"

namespace gvm {
namespace {

using step_internal::StepModule;

struct Loaded {
  const StepModule* module = nullptr;
  std::string path;
  std::string error;
};

std::string module_path() {
  std::error_code ec;
  const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const std::filesystem::path beside = program.parent_path() / std::filesystem::path(GVM_STEP_MODULE).filename();
    if (std::filesystem::exists(beside, ec)) return beside.string();
  }
  return GVM_STEP_MODULE;
}

// Loaded once per process, never unloaded (Open CASCADE keeps process-wide statics).
const Loaded& step_module() {
  static const Loaded loaded = [] {
    Loaded out;
    out.path = module_path();
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

StatusOr<StepPart> read_step(std::string_view bytes, const StepOptions& options, const std::string& source) {
  const Loaded& loaded = step_module();
  if (!loaded.module) {
    return Internal(source + ": STEP input needs the module " + loaded.path +
                              ", which could not be loaded (" + loaded.error + ")");
  }
  return loaded.module->read_bytes(bytes, options, source);
}

StatusOr<StepPart> read_step(const std::string& path, const StepOptions& options) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return NotFound(path + ": no such file");
  if (std::filesystem::is_directory(path, ec))
    return InvalidArgument(path + ": is a directory, not a STEP file");
  std::ifstream in(path, std::ios::binary);
  if (!in) return NotFound(path + ": cannot be opened for reading");
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (in.bad()) return InvalidArgument(path + ": read error");
  return read_step(std::string_view(bytes.view()), options, path);
}

}  // namespace gvm
