#include "progress.h"

#include <spdlog/fmt/fmt.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <vector>

#include "records.h"

namespace gvm::batch {
namespace {

std::string clock_time(double seconds) {
  const long s = std::lround(seconds);
  return s >= 3600 ? fmt::format("{}:{:02}:{:02}", s / 3600, s / 60 % 60, s % 60) : fmt::format("{}:{:02}", s / 60, s % 60);
}

std::string first_line(const std::string& text) { return text.substr(0, text.find('\n')); }

std::string part_line(const PartOutcome& o) {
  const v1::BatchResult& r = o.result;
  if (o.skipped) return fmt::format("{} (done before)", r.name());
  if (r.status() != v1::BATCH_STATUS_DONE) {
    return fmt::format("{} {}: {}", status_word(r.status()), r.name(), first_line(r.error()));
  }
  return fmt::format("done {}: {} setup{}, {} unreachable, {:.2f} s", r.name(), r.setups(), r.setups() == 1 ? "" : "s",
                     r.unreachable(), r.seconds());
}

bool failed(v1::BatchStatus s) { return s != v1::BATCH_STATUS_DONE; }

}  // namespace

Progress::Progress(size_t total, std::ostream& out, bool terminal, bool quiet)
    : out_(out), total_(total), terminal_(terminal), quiet_(quiet) {}

void Progress::draw_bar() {
  constexpr size_t kWidth = 30;
  const size_t filled = total_ ? finished_ * kWidth / total_ : kWidth;
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const size_t computed = finished_ - skipped_;
  std::string eta;
  if (computed > 0 && finished_ < total_) {
    eta = " · ~" + clock_time(elapsed / static_cast<double>(computed) * static_cast<double>(total_ - finished_)) + " left";
  }
  out_ << "\r\033[K[" << std::string(filled, '#') << std::string(kWidth - filled, '.') << "] "
       << fmt::format("{}/{} parts · {} failed · {}{}", finished_, total_, failed_, clock_time(elapsed), eta)
       << std::flush;
}

void Progress::finished(const PartOutcome& outcome) {
  std::lock_guard lock(mutex_);
  ++finished_;
  if (outcome.skipped) ++skipped_;
  if (failed(outcome.result.status())) ++failed_;
  if (quiet_) return;
  if (terminal_) return draw_bar();
  const int width = static_cast<int>(std::to_string(total_).size());
  out_ << fmt::format("[{:>{}}/{}] ", finished_, width, total_) << part_line(outcome) << '\n' << std::flush;
}

void Progress::summary(const v1::BatchSummary& s, const std::filesystem::path& out_dir) {
  std::lock_guard lock(mutex_);
  if (terminal_ && !quiet_) out_ << '\n';
  out_ << fmt::format("gvm batch: {} parts in {} ({} thread{}, {} job{} at once{})\n", s.parts_size(),
                      clock_time(s.seconds()), s.threads(), s.threads() == 1 ? "" : "s", s.jobs(),
                      s.jobs() == 1 ? "" : "s", s.ranks() > 1 ? fmt::format(", {} ranks", s.ranks()) : "");
  out_ << fmt::format("  done   {:>6}", s.done()) << (s.skipped() ? fmt::format("  ({} done before)", s.skipped()) : "")
       << '\n';
  out_ << fmt::format("  failed {:>6}\n", s.failed());
  const int not_run = s.parts_size() - static_cast<int>(s.done() + s.failed());
  if (not_run > 0) out_ << fmt::format("  not run{:>6}  (stopped: --resume goes on from here)\n", not_run);

  std::vector<const v1::BatchResult*> by_time, bad;
  for (const v1::BatchResult& r : s.parts()) {
    if (r.status() == v1::BATCH_STATUS_DONE && r.seconds() > 0) by_time.push_back(&r);
    if (r.status() != v1::BATCH_STATUS_DONE && r.status() != v1::BATCH_STATUS_UNSPECIFIED) bad.push_back(&r);
  }
  std::sort(by_time.begin(), by_time.end(), [](auto* a, auto* b) { return a->seconds() > b->seconds(); });
  if (!by_time.empty()) {
    out_ << "  slowest:";
    for (size_t i = 0; i < std::min<size_t>(3, by_time.size()); ++i) {
      out_ << fmt::format("{} {} {:.1f} s", i ? "," : "", by_time[i]->name(), by_time[i]->seconds());
    }
    out_ << '\n';
  }
  constexpr size_t kShown = 10;
  for (size_t i = 0; i < std::min(kShown, bad.size()); ++i) {
    out_ << fmt::format("  {} {}: {}\n", status_word(bad[i]->status()), bad[i]->name(), first_line(bad[i]->error()));
  }
  if (bad.size() > kShown) out_ << fmt::format("  ... and {} more failed\n", bad.size() - kShown);
  out_ << "  per part: " << (out_dir / "summary.csv").string() << ", " << (out_dir / "summary.json").string() << '\n'
       << std::flush;
}

v1::BatchSummary summarize(const std::vector<BatchItem>& items, const std::vector<std::optional<PartOutcome>>& outcomes,
                           const BatchOptions& options, double seconds, uint32_t ranks) {
  v1::BatchSummary s;
  for (size_t i = 0; i < items.size(); ++i) {
    v1::BatchResult* r = s.add_parts();
    if (!outcomes[i]) {
      r->set_name(items[i].name);
      r->set_part(items[i].part.string());
      r->set_input_bytes(items[i].input_bytes);
      continue;
    }
    *r = outcomes[i]->result;
    if (r->status() == v1::BATCH_STATUS_DONE) s.set_done(s.done() + 1);
    else s.set_failed(s.failed() + 1);
    if (outcomes[i]->skipped) s.set_skipped(s.skipped() + 1);
  }
  s.set_seconds(seconds);
  s.set_threads(options.threads);
  s.set_jobs(options.jobs);
  s.set_ranks(ranks);
  s.set_engine_version(GVM_VERSION);
  return s;
}

int exit_status(const v1::BatchSummary& s) { return s.done() == static_cast<uint32_t>(s.parts_size()) ? 0 : 1; }

}  // namespace gvm::batch
