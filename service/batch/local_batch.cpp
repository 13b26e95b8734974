#include "local_batch.h"

#include <spdlog/spdlog.h>
#include <tbb/global_control.h>
#include <unistd.h>

#include <chrono>
#include <condition_variable>
#include <iostream>
#include <mutex>
#include <thread>

#include "progress.h"
#include "signal_stop.h"

namespace gvm::batch {
namespace {

// Admits parts while their estimated memory fits the bound; one part always runs, however
// large, so that a batch never waits forever.
class MemoryBudget {
 public:
  // The process itself (libraries, Open CASCADE's tables) needs about this much.
  static constexpr uint64_t kProcess = 40ull << 20;

  explicit MemoryBudget(uint64_t bound) : bound_(bound == 0 ? 0 : bound > kProcess ? bound - kProcess : 1) {}

  // False when the wait ended by a stop request.
  bool acquire(uint64_t bytes, std::stop_token stop) {
    std::unique_lock lock(mutex_);
    if (!ready_.wait(lock, stop, [&] { return bound_ == 0 || used_ == 0 || used_ + bytes <= bound_; })) {
      return false;
    }
    used_ += bytes;
    return true;
  }
  void release(uint64_t bytes) {
    {
      std::lock_guard lock(mutex_);
      used_ -= bytes;
    }
    ready_.notify_all();
  }

 private:
  std::mutex mutex_;
  std::condition_variable_any ready_;
  const uint64_t bound_;
  uint64_t used_ = 0;
};

}  // namespace

uint64_t estimated_memory(const BatchItem& item) {
  // Peak resident memory of `gvm plan` on the shared parts is the process's 40 MB plus
  // at most 8 MB + 0.45 bytes per byte of the part's file (prusa_extruder-idler); flat
  // parts need far less (occt_brep_Bottom: 0.03), so this errs on the safe side.
  constexpr uint64_t kPerPart = 8ull << 20;
  return kPerPart + item.input_bytes / 2;
}

namespace {

v1::BatchSummary run_jobs(const std::vector<BatchItem>& items, const BatchOptions& options, std::stop_token stop,
                          Progress& progress) {
  const auto start = std::chrono::steady_clock::now();
  // Every part's arenas draw their workers from this one pool.
  tbb::global_control parallelism(tbb::global_control::max_allowed_parallelism, options.threads);
  const std::vector<size_t> order = largest_first(items);
  std::vector<std::optional<PartOutcome>> outcomes(items.size());
  MemoryBudget budget(options.max_memory);
  std::mutex next_mutex;
  size_t next = 0;
  auto job = [&] {
    for (;;) {
      size_t i = 0;
      uint64_t bytes = 0;
      {
        // Taken and admitted under one lock: parts start in order even when they wait.
        std::lock_guard lock(next_mutex);
        if (next == order.size() || stop.stop_requested()) return;
        i = order[next++];
        bytes = estimated_memory(items[i]);
        if (!budget.acquire(bytes, stop)) return;
      }
      outcomes[i] = run_part(items[i], options, stop);
      budget.release(bytes);
      progress.finished(*outcomes[i]);
    }
  };
  {
    std::vector<std::jthread> jobs;
    for (unsigned j = 0; j < std::max(1u, options.jobs); ++j) jobs.emplace_back(job);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return summarize(items, outcomes, options, seconds, 1);
}

}  // namespace

int run_local(const std::vector<BatchItem>& items, const BatchOptions& given, bool quiet) {
  BatchOptions options = given;
  // Two parts at once by default: one part's serial phases (reading, validation, planning)
  // leave cores idle that the other fills (11% faster on the shared parts with 2 threads,
  // benchmarks/results/batch.json).
  if (options.jobs == 0) options.jobs = 2;
  const SignalStop signals;  // before any thread starts
  Progress progress(items.size(), std::cout, isatty(STDOUT_FILENO) == 1, quiet);
  const v1::BatchSummary summary = run_jobs(items, options, signals.token(), progress);
  if (Status s = write_summary(options, summary); !s.ok()) spdlog::error("{}", s.message());
  progress.summary(summary, options.out);
  return signals.signal() ? 128 + signals.signal() : exit_status(summary);
}

}  // namespace gvm::batch
