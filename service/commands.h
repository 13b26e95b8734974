// The commands of the `gvm` command line.
#pragma once

#include <functional>
#include <vector>

#include "batch/batch.h"

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

// How a batch runs once its manifest is read and its options checked: here (gvm batch) or
// across MPI ranks (gvm-mpi batch). Returns the exit status.
using BatchRunner = std::function<int(const std::vector<batch::BatchItem>& items,
                                      const batch::BatchOptions& options, bool quiet)>;
Run add_batch(CLI::App& app, BatchRunner runner);

}  // namespace gvm::cli
