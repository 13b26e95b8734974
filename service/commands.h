// The commands of the `gvm` command line.
#pragma once

#include <functional>

namespace CLI {
class App;
}  // namespace CLI

namespace gvm::cli {

// Runs a command once the command line has been parsed into its options; returns the
// process exit status.
using Run = std::function<int()>;

// Each adds its subcommand with its options to the `gvm` app.
Run add_analyze(CLI::App& gvm);
Run add_plan(CLI::App& gvm);

}  // namespace gvm::cli
