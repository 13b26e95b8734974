// A stop request cancels plan(): before it starts, and while it works (the --split maps
// of unreachable features, the exact cover's overlay, Cbc).
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "gvm/analysis.h"
#include "gvm/planner/plan.h"

namespace gvm {
namespace {

using Clock = std::chrono::steady_clock;

const Analysis& y_motor_holder() {
  static const Analysis analysis = [] {
    AnalyzeRequest request;
    request.part_path = std::string(GVM_SHARED_DIR) + "/data/parts/prusa_y-motor-holder.stl";
    auto a = analyze(request);
    EXPECT_TRUE(a.ok()) << a.status().message();
    return std::move(*a);
  }();
  return analysis;
}

TEST(PlannerCancel, StopBeforeStart) {
  std::stop_source stop;
  stop.request_stop();
  planner::PlanControl control;
  control.stop = stop.get_token();
  auto p = planner::plan(y_motor_holder(), v1::PlanOptions(), control);
  EXPECT_EQ(p.status().code(), StatusCode::kCancelled);
}

// prusa_y-motor-holder with --split --no-split (every unreachable feature in its planar
// pieces) takes more than a minute (78 s on 2 threads when measured): a stop after 0.5 s ends it
// with kCancelled, well before.
TEST(PlannerCancel, StopWhilePlanning) {
  const Analysis& analysis = y_motor_holder();
  v1::PlanOptions options;
  options.set_split(true);
  options.set_no_split(true);
  options.set_threads(2);
  std::stop_source stop;
  planner::PlanControl control;
  control.stop = stop.get_token();
  Clock::time_point stopped_at;
  std::thread stopper([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    stopped_at = Clock::now();
    stop.request_stop();
  });
  auto p = planner::plan(analysis, options, control);
  [[maybe_unused]] const auto returned_at = Clock::now();  // read outside the sanitizers only
  stopper.join();
  ASSERT_EQ(p.status().code(), StatusCode::kCancelled) << (p.ok() ? "finished" : p.status().message());
  EXPECT_EQ(p.status().message(), "planning cancelled");
#if !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
  EXPECT_LT(std::chrono::duration<double>(returned_at - stopped_at).count(), 10.0);
#endif
}

}  // namespace
}  // namespace gvm
