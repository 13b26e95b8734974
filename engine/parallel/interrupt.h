// Cancellation inside long computations. The entry points run their parallel work under
// a tbb::task_group_context (gvm/cancellable_run.h) and cancel that context on a stop
// request; nested TBB algorithms inherit the cancellation and stop scheduling, and the
// long serial loops call interruption_point(), which throws Interrupted once the task
// group they run in is being cancelled. The entry points catch Interrupted and answer
// kCancelled; code between them holds no locks or raw resources across the throw (RAII
// only).
//
// A parallel algorithm of a cancelled group returns early without an exception, with
// part of its work undone: every engine parallel loop is followed by an
// interruption_point() so that a partial result is never used.
//
// Outside any cancelled task group (a plain call, a test) interruption_point() never
// throws. One check costs a thread-local lookup and a load (a few ns): loops whose
// iterations are cheaper than a microsecond check every few hundred iterations
// (Interruptions).
#pragma once

#include <tbb/task_group.h>

#include <cstdint>

namespace gvm {

// Thrown by interruption_point(); never leaves the engine's public API.
struct Interrupted {};

inline void interruption_point() {
  if (tbb::is_current_task_group_canceling()) throw Interrupted{};
}

// interruption_point() every `period` calls of tick(), for loops of very cheap iterations.
class Interruptions {
 public:
  explicit Interruptions(uint32_t period = 256) : period_(period) {}
  void tick() {
    if (++count_ >= period_) {
      count_ = 0;
      interruption_point();
    }
  }

 private:
  uint32_t period_;
  uint32_t count_ = 0;
};

}  // namespace gvm
