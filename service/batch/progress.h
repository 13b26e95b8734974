// What a batch shows while it runs and when it ends: on a terminal one progress line
// rewritten in place, elsewhere one line a finished part (for logs); then a one-screen
// summary. Called from every job's thread.
#pragma once

#include <chrono>
#include <filesystem>
#include <iosfwd>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "batch.h"

namespace gvm::batch {

class Progress {
 public:
  // quiet: nothing while running (the summary is still printed).
  Progress(size_t total, std::ostream& out, bool terminal, bool quiet);

  void finished(const PartOutcome& outcome);
  // Ends the progress line and prints the summary of the run.
  void summary(const v1::BatchSummary& summary, const std::filesystem::path& out_dir);

 private:
  void draw_bar();

  std::mutex mutex_;
  std::ostream& out_;
  const size_t total_;
  const bool terminal_, quiet_;
  size_t finished_ = 0, failed_ = 0, skipped_ = 0;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// The summary of a run from the outcomes of its parts (null: not run), in manifest order.
v1::BatchSummary summarize(const std::vector<BatchItem>& items, const std::vector<std::optional<PartOutcome>>& outcomes,
                           const BatchOptions& options, double seconds, uint32_t ranks);

// The exit status of a batch: 0 when every part is done, 1 otherwise.
int exit_status(const v1::BatchSummary& summary);

}  // namespace gvm::batch
