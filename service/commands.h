// The commands of the `gvm` command line; each returns the process exit status.
#pragma once

#include <string>
#include <vector>

namespace gvm::cli {

int run_analyze(const std::vector<std::string>& argv);
int run_plan(const std::vector<std::string>& argv);

}  // namespace gvm::cli
