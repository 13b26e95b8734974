// The one way the entry points (gvm::analyze(), gvm::planner::plan()) run their work: in a
// task arena of `threads` threads, as one task of a fresh task_group_context that a stop
// request cancels. Nested TBB algorithms inherit the cancellation, and the engine's serial
// interruption points (engine/parallel/interrupt.h) see it because they run inside that
// task. Public (and so with oneTBB in its includes) because the planner, which uses the
// engine's public API only, runs the same way.
#pragma once

#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <optional>
#include <stop_token>
#include <string>
#include <utility>

#include "gvm/status.h"

namespace gvm {

// `threads` <= 0: every core.
inline int arena_threads(int threads) {
  return threads > 0 ? threads : tbb::this_task_arena::max_concurrency();
}

// work(ctx) returns a StatusOr<T>; a stop (before or during the run) answers kCancelled
// with `cancelled_message`, whatever work left behind: a result a late cancel may have cut
// short is never returned. An exception of a run that was not cancelled propagates.
template <class T, class Work>
StatusOr<T> cancellable_run(int threads, const std::stop_token& stop, const std::string& cancelled_message,
                            Work&& work) {
  tbb::task_arena arena(arena_threads(threads));
  tbb::task_group_context ctx;
  const std::stop_callback on_stop(stop, [&ctx] { ctx.cancel_group_execution(); });
  std::optional<StatusOr<T>> out;
  arena.execute([&] {
    tbb::task_group group(ctx);
    group.run_and_wait([&] {
      try {
        out.emplace(work(ctx));
      } catch (...) {
        // Interrupted, or anything a cancelled computation left behind.
        if (!ctx.is_group_execution_cancelled()) throw;
      }
    });
  });
  if (!out || ctx.is_group_execution_cancelled()) return Status(StatusCode::kCancelled, cancelled_message);
  return std::move(*out);
}

}  // namespace gvm
