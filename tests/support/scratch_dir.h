// A directory for the files a test process writes, removed when the process ends (each
// test runs in its own process under ctest, so a fixed name per process would pile up).
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

namespace gvm::test {

inline const std::filesystem::path& scratch_dir() {
  static const struct Dir {
    std::filesystem::path path = std::filesystem::temp_directory_path() /
                                 ("gvm_test_" + std::to_string(::getpid()));
    Dir() { std::filesystem::create_directories(path); }
    ~Dir() {
      std::error_code ignored;
      std::filesystem::remove_all(path, ignored);
    }
  } dir;
  return dir.path;
}

}  // namespace gvm::test
