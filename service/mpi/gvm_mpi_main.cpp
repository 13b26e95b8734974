// gvm-mpi: `gvm batch` across the ranks of an MPI job (mpirun, srun).
#include <mpi.h>

#include <CLI/CLI.hpp>
#include <iostream>
#include <optional>
#include <string>

#include "cli_app.h"
#include "cli_common.h"
#include "commands.h"
#include "mpi_batch.h"

namespace {

constexpr const char* kUsage = R"(gvm-mpi - gvm batch across the ranks of an MPI job

Usage:
  mpirun -n R gvm-mpi batch MANIFEST --out DIR [options]
  srun gvm-mpi batch MANIFEST --out DIR [options]        (see service/slurm/)

Rank 0 hands out the parts of MANIFEST one at a time, largest first, to every rank
(itself included); each rank plans its parts on --threads threads and writes the same
files as `gvm batch` to DIR, which every rank must see (a shared filesystem). Rank 0
prints the progress and the summary and writes summary.csv and summary.json.

The options are gvm batch's (see gvm batch --help), except --jobs and --max-memory:
each rank runs one part at a time, so choose ranks per node (and Slurm's --mem-per-cpu)
instead. --resume makes a requeued job go on where it stopped.

Exit status (rank 0): 0 every part done, 1 a part not done, 2 usage error, 128+N
stopped by signal N.
)";

// What every rank must agree on before any part runs: the manifest read, the options
// checked, the same number of parts (the manifest on a filesystem all ranks share).
bool all_ranks_agree(bool ok, size_t parts) {
  const long mine[3] = {ok ? 1 : 0, static_cast<long>(parts), -static_cast<long>(parts)};
  long all[3] = {};
  MPI_Allreduce(mine, all, 3, MPI_LONG, MPI_MIN, MPI_COMM_WORLD);
  return all[0] == 1 && all[1] == -all[2];
}

}  // namespace

int main(int argc, char** argv) {
  const gvm::batch::SignalStop signals;  // before MPI starts threads of its own
  int provided = 0, rank = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  gvm::cli::set_up_logging("gvm-mpi");
  // Every rank parses the same arguments; only rank 0 says what is wrong with them.
  std::streambuf* const cout = std::cout.rdbuf();
  std::streambuf* const cerr = std::cerr.rdbuf();
  if (rank != 0) {
    std::cout.rdbuf(nullptr);
    std::cerr.rdbuf(nullptr);
  }

  CLI::App app{"gvm-mpi - gvm batch across the ranks of an MPI job", "gvm-mpi"};
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  app.allow_extras();
  app.require_subcommand(0, 1);
  app.set_version_flag("--version", std::string("gvm-mpi ") + GVM_VERSION, "show the version");
  // The batch command checks everything and hands the parts over here.
  std::optional<std::vector<gvm::batch::BatchItem>> items;
  gvm::batch::BatchOptions options;
  bool quiet = false;
  const gvm::cli::Run batch = gvm::cli::add_batch(app, [&](const auto& i, const auto& o, bool q) {
    items = i;
    options = o;
    quiet = q;
    return 0;
  });
  gvm::cli::add_help_flag(app);
  gvm::cli::add_help_flag(*app.get_subcommand("batch"));

  std::optional<int> exit = gvm::cli::parse(app, argc, argv, kUsage);
  if (!exit) {
    const std::vector<std::string> extra = app.remaining(true);
    if (!extra.empty()) exit = gvm::cli::unknown(extra.front());
    else if (app.get_subcommands().empty()) exit = gvm::cli::usage_error("no command given (gvm-mpi batch ...)");
    else exit = batch();
  }
  if (exit == 0 && items && options.jobs > 1) {
    exit = gvm::cli::usage_error("--jobs: each rank runs one part at a time; start more ranks instead");
  }
  if (exit == 0 && items && options.max_memory != 0) {
    exit = gvm::cli::usage_error("--max-memory: each rank runs one part at a time; bound memory by ranks per node");
  }
  const bool ready = exit == 0 && items.has_value();
  if (!all_ranks_agree(ready, ready ? items->size() : 0)) {
    if (ready) exit = gvm::cli::failure("another rank could not read the manifest or the options (do all ranks see it?)");
  } else if (ready) {
    exit = gvm::mpi::run_mpi_batch(*items, options, quiet, signals);
  }
  std::cout.rdbuf(cout);
  std::cerr.rdbuf(cerr);
  MPI_Finalize();
  return rank == 0 ? exit.value_or(0) : 0;
}
