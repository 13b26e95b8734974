#include "mpi_batch.h"

#include <mpi.h>

#include <tbb/global_control.h>

#include <chrono>
#include <iostream>
#include <mutex>
#include <optional>
#include <spdlog/spdlog.h>
#include <thread>

#include "batch/progress.h"

namespace gvm::mpi {
namespace {

using batch::BatchItem;
using batch::BatchOptions;
using batch::PartOutcome;

// Worker -> rank 0: a finished part (BatchPartDone), or nothing yet (empty).
constexpr int kDone = 1;
// Rank 0 -> worker: the index of the next part, or -1: no more.
constexpr int kWork = 2;

// The parts not yet handed out, largest first; shared by rank 0's dispatcher and its own
// worker thread.
class Dispatch {
 public:
  Dispatch(const std::vector<BatchItem>& items, std::stop_token stop) : order_(batch::largest_first(items)), stop_(stop) {}
  int64_t next() {
    std::lock_guard lock(mutex_);
    if (next_ == order_.size() || stop_.stop_requested()) return -1;
    return static_cast<int64_t>(order_[next_++]);
  }

 private:
  std::mutex mutex_;
  const std::vector<size_t> order_;
  size_t next_ = 0;
  std::stop_token stop_;
};

void send_done(const std::optional<v1::BatchPartDone>& done) {
  std::string bytes;
  if (done) done->SerializeToString(&bytes);
  MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, 0, kDone, MPI_COMM_WORLD);
}

// A worker rank: asks for a part, runs it, reports it, until rank 0 says no more.
void work(const std::vector<BatchItem>& items, const BatchOptions& options, std::stop_token stop) {
  send_done(std::nullopt);
  for (;;) {
    int64_t index = -1;
    MPI_Recv(&index, 1, MPI_INT64_T, 0, kWork, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (index < 0) return;
    const PartOutcome outcome = batch::run_part(items[static_cast<size_t>(index)], options, stop);
    v1::BatchPartDone done;
    done.set_index(static_cast<uint32_t>(index));
    done.set_skipped(outcome.skipped);
    *done.mutable_result() = outcome.result;
    send_done(done);
  }
}

// Rank 0's main thread: answers every worker's report with its next part, until every
// worker has been told there is none. Polls (MPI_Iprobe) rather than blocking in
// MPI_Recv, whose busy wait would take a core from the parts.
void dispatch(Dispatch& parts, int workers, std::vector<std::optional<PartOutcome>>& outcomes, std::mutex& outcomes_mutex,
              batch::Progress& progress) {
  while (workers > 0) {
    int ready = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, kDone, MPI_COMM_WORLD, &ready, &status);
    if (!ready) {
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
      continue;
    }
    int size = 0;
    MPI_Get_count(&status, MPI_BYTE, &size);
    std::string bytes(static_cast<size_t>(size), '\0');
    MPI_Recv(bytes.data(), size, MPI_BYTE, status.MPI_SOURCE, kDone, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    v1::BatchPartDone done;
    if (size > 0 && done.ParseFromString(bytes) && done.index() < outcomes.size()) {
      const PartOutcome outcome{done.result(), done.skipped()};
      {
        std::lock_guard lock(outcomes_mutex);
        outcomes[done.index()] = outcome;
      }
      progress.finished(outcome);
    }
    const int64_t next = parts.next();
    MPI_Send(&next, 1, MPI_INT64_T, status.MPI_SOURCE, kWork, MPI_COMM_WORLD);
    if (next < 0) --workers;
  }
}

int run_rank0(const std::vector<BatchItem>& items, const BatchOptions& options, bool quiet, int ranks,
              const batch::SignalStop& signals) {
  const auto start = std::chrono::steady_clock::now();
  // One line a part: under mpirun standard output is a pseudo-terminal of Open MPI's, not
  // the terminal or the log file it ends up in.
  batch::Progress progress(items.size(), std::cout, false, quiet);
  Dispatch parts(items, signals.token());
  std::vector<std::optional<PartOutcome>> outcomes(items.size());
  std::mutex outcomes_mutex;
  {
    std::jthread own([&] {
      for (int64_t i; (i = parts.next()) >= 0;) {
        PartOutcome outcome = batch::run_part(items[static_cast<size_t>(i)], options, signals.token());
        {
          std::lock_guard lock(outcomes_mutex);
          outcomes[static_cast<size_t>(i)] = outcome;
        }
        progress.finished(outcome);
      }
    });
    dispatch(parts, ranks - 1, outcomes, outcomes_mutex, progress);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const v1::BatchSummary summary = batch::summarize(items, outcomes, options, seconds, static_cast<uint32_t>(ranks));
  if (Status s = batch::write_summary(options, summary); !s.ok()) spdlog::error("{}", s.message());
  progress.summary(summary, options.out);
  return signals.signal() ? 128 + signals.signal() : batch::exit_status(summary);
}

}  // namespace

int run_mpi_batch(const std::vector<BatchItem>& items, const BatchOptions& given, bool quiet,
                  const batch::SignalStop& signals) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  BatchOptions options = given;
  options.host += "/rank " + std::to_string(rank);
  options.jobs = 1;
  tbb::global_control parallelism(tbb::global_control::max_allowed_parallelism, options.threads);
  if (rank != 0) {
    work(items, options, signals.token());
    return 0;
  }
  return run_rank0(items, options, quiet, ranks, signals);
}

}  // namespace gvm::mpi
