// When a set-cover solve gives up: the caller's cancellation flag and the time limit,
// polled together on the solving thread (between components, while waiting for the solver,
// at Cbc's events and at Clp's iterations).
#pragma once

#include <chrono>
#include <functional>
#include <optional>
#include <utility>

namespace gvm::planner {

class CoverStop {
 public:
  using Clock = std::chrono::steady_clock;

  // time_limit_seconds <= 0: no limit. The clock starts now.
  CoverStop(std::function<bool()> cancelled, double time_limit_seconds)
      : cancelled_fn_(std::move(cancelled)), start_(Clock::now()) {
    if (time_limit_seconds > 0) {
      deadline_ = start_ + std::chrono::duration_cast<Clock::duration>(
                               std::chrono::duration<double>(time_limit_seconds));
    }
  }

  // True once cancelled or past the deadline; sticky, so every later part of the solve
  // sees the same answer.
  bool should_stop() {
    if (cancelled_ || timed_out_) return true;
    if (cancelled_fn_ && cancelled_fn_()) cancelled_ = true;
    else if (deadline_ && Clock::now() >= *deadline_) timed_out_ = true;
    return cancelled_ || timed_out_;
  }

  // The solver stopped on its own timer (set from seconds_left()).
  void note_time_limit() { timed_out_ = true; }

  bool cancelled() const { return cancelled_; }
  bool time_limit_reached() const { return timed_out_; }
  bool has_limit() const { return deadline_.has_value(); }

  // Seconds before the deadline (0 once past); only meaningful when has_limit().
  double seconds_left() const {
    if (!deadline_) return 0;
    const double left = std::chrono::duration<double>(*deadline_ - Clock::now()).count();
    return left > 0 ? left : 0;
  }

  // Seconds since the deadline passed (0 before it, or without a limit).
  double seconds_past_deadline() const {
    if (!deadline_) return 0;
    const double past = std::chrono::duration<double>(Clock::now() - *deadline_).count();
    return past > 0 ? past : 0;
  }

  double elapsed_seconds() const {
    return std::chrono::duration<double>(Clock::now() - start_).count();
  }

 private:
  std::function<bool()> cancelled_fn_;
  Clock::time_point start_;
  std::optional<Clock::time_point> deadline_;
  bool cancelled_ = false;
  bool timed_out_ = false;
};

}  // namespace gvm::planner
