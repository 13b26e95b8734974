// One part of a batch, from its bytes to its record: the resume decision, the analysis and
// the plan under the part's deadline, the outputs written before the record says done.
#include <spdlog/fmt/fmt.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>

#include "batch.h"
#include "common/files.h"
#include "gvm/analysis.h"
#include "gvm/analysis_proto.h"
#include "gvm/planner/plan.h"
#include "records.h"

namespace gvm::batch {
namespace {

namespace fs = std::filesystem;

// A part started this often that never finished took its process down each time (out of
// memory, a crash): it is recorded as failed rather than started again.
constexpr uint32_t kMaxAttempts = 3;

// Stops the part when the batch stops or its time is up, whichever comes first.
class PartDeadline {
 public:
  PartDeadline(std::stop_token batch, double seconds)
      : forward_(batch, [this] { stop_.request_stop(); }) {
    if (seconds <= 0) return;
    const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    timer_ = std::jthread([this, until](std::stop_token done) {
      std::mutex m;
      std::unique_lock lock(m);
      std::condition_variable_any cv;
      if (!cv.wait_until(lock, done, until, [] { return false; }) && !done.stop_requested()) {
        expired_ = true;
        stop_.request_stop();
      }
    });
  }
  std::stop_token token() const { return stop_.get_token(); }
  bool expired() const { return expired_; }

 private:
  std::stop_source stop_;
  std::stop_callback<std::function<void()>> forward_;
  std::atomic<bool> expired_ = false;
  std::jthread timer_;  // last: joined first, before what it touches goes
};

bool outputs_present(const fs::path& out, const v1::BatchResult& r, bool want_analysis) {
  if (!fs::exists(out / r.plan_file())) return false;
  return !want_analysis || (!r.analysis_file().empty() && fs::exists(out / r.analysis_file()));
}

// What --resume makes of the record a previous run left: the outcome when the part is not
// run again, else nothing (and `attempts` how often it was started before).
std::optional<PartOutcome> resumed(const v1::BatchResult& before, const std::string& hash, const BatchOptions& options,
                                   uint32_t& attempts) {
  if (before.input_hash() != hash) return std::nullopt;
  attempts = before.attempts();
  if (before.status() == v1::BATCH_STATUS_DONE && outputs_present(options.out, before, options.write_analysis)) {
    return PartOutcome{before, true};
  }
  // A bad part or bad options fail the same way every time.
  if (before.status() == v1::BATCH_STATUS_FAILED) return PartOutcome{before, true};
  if (before.status() == v1::BATCH_STATUS_RUNNING && attempts >= kMaxAttempts) {
    v1::BatchResult r = before;
    r.set_status(v1::BATCH_STATUS_FAILED);
    r.set_error("started " + std::to_string(attempts) +
                " times and never finished: the process running it was killed (out of memory?) or crashed");
    return PartOutcome{r, false};
  }
  return std::nullopt;
}

double unix_seconds() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

void fail(v1::BatchResult& r, v1::BatchStatus status, const std::string& error) {
  r.set_status(status);
  r.set_error(error);
}

// Analyses and plans the part, writes its outputs and fills the record's counts.
void compute(const BatchItem& item, const BatchOptions& options, v1::BatchResult& r, std::stop_token stop) {
  AnalyzeRequest request;
  request.part_path = item.part.string();
  request.groups_path = item.groups.string();
  request.options = item.analyze;
  request.options.set_threads(options.threads);
  request.stop = stop;
  StatusOr<Analysis> analysis = analyze(request);
  if (!analysis.ok()) return fail(r, v1::BATCH_STATUS_FAILED, analysis.status().message());
  v1::PlanOptions plan_options = item.plan;
  plan_options.set_threads(options.threads);
  planner::PlanControl control;
  control.stop = stop;
  StatusOr<planner::SetupPlan> plan = planner::plan(*analysis, plan_options, control);
  if (!plan.ok()) return fail(r, v1::BATCH_STATUS_FAILED, plan.status().message());

  r.set_plan_file(plan_file(item.name));
  if (!write_file_atomically(options.out / r.plan_file(), to_json(plan->message))) {
    return fail(r, v1::BATCH_STATUS_FAILED, "cannot write " + (options.out / r.plan_file()).string());
  }
  if (options.write_analysis) {
    r.set_analysis_file(analysis_file(item.name));
    if (!write_file_atomically(options.out / r.analysis_file(), to_json(to_proto(*analysis)))) {
      return fail(r, v1::BATCH_STATUS_FAILED, "cannot write " + (options.out / r.analysis_file()).string());
    }
  }
  r.set_faces(analysis->part().input_faces);
  r.set_features(static_cast<uint32_t>(analysis->features().size()));
  r.set_surfaces(static_cast<uint32_t>(plan->message.surfaces_size()));
  r.set_setups(static_cast<uint32_t>(plan->message.setups_size()));
  r.set_unreachable(plan->message.unreachable_count());
  r.set_optimal(plan->message.optimal());
  r.set_status(v1::BATCH_STATUS_DONE);
}

}  // namespace

PartOutcome run_part(const BatchItem& item, const BatchOptions& options, std::stop_token stop) {
  v1::BatchResult r;
  r.set_name(item.name);
  r.set_part(item.part.string());
  r.set_host(options.host);
  r.set_input_bytes(item.input_bytes);
  const std::optional<std::string> part = read_whole_file(item.part);
  const std::optional<std::string> groups = item.groups.empty() ? std::string() : read_whole_file(item.groups);
  if (!part || !groups) {
    const fs::path& missing = part ? item.groups : item.part;
    fail(r, v1::BATCH_STATUS_FAILED, std::string(part ? "groups" : "part") + " file '" + missing.string() + "' cannot be opened");
    r.set_attempts(1);
    write_record(options.out, r);
    return {r, false};
  }
  r.set_input_hash(input_hash(item, *part, *groups));
  uint32_t attempts = 0;
  if (options.resume) {
    if (auto before = read_record(options.out, item.name)) {
      if (auto outcome = resumed(*before, r.input_hash(), options, attempts)) {
        if (!outcome->skipped) write_record(options.out, outcome->result);
        return *outcome;
      }
    }
  }
  r.set_attempts(attempts + 1);
  r.set_status(v1::BATCH_STATUS_RUNNING);
  if (!write_record(options.out, r)) {
    fail(r, v1::BATCH_STATUS_FAILED, "cannot write " + (options.out / record_file(item.name)).string());
    return {r, false};
  }

  const auto start = std::chrono::steady_clock::now();
  r.set_started_at(unix_seconds());
  PartDeadline deadline(stop, options.part_timeout_seconds);
  compute(item, options, r, deadline.token());
  r.set_seconds(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  if (r.status() != v1::BATCH_STATUS_DONE && deadline.token().stop_requested()) {
    if (deadline.expired()) {
      fail(r, v1::BATCH_STATUS_TIMED_OUT, fmt::format("stopped at the part timeout ({:g} s)", options.part_timeout_seconds));
    } else {
      fail(r, v1::BATCH_STATUS_INTERRUPTED, "the batch was stopped while on this part");
    }
  }
  r.set_finished_at(unix_seconds());
  write_record(options.out, r);
  return {r, false};
}

}  // namespace gvm::batch
