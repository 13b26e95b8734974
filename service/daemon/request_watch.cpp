#include "request_watch.h"

#include <condition_variable>
#include <mutex>

namespace gvm::daemon {

RequestWatch::RequestWatch(grpc::ServerContext* context, std::stop_source stop, std::function<void()> tick)
    : thread_([context, stop, tick = std::move(tick)](std::stop_token end) mutable {
        using namespace std::chrono_literals;
        std::mutex m;
        std::condition_variable_any wake;
        auto last_tick = std::chrono::steady_clock::now();
        std::unique_lock lock(m);
        while (!end.stop_requested()) {
          if (context->IsCancelled()) stop.request_stop();
          if (tick && std::chrono::steady_clock::now() - last_tick >= 500ms) {
            tick();
            last_tick = std::chrono::steady_clock::now();
          }
          wake.wait_for(lock, end, 50ms, [] { return false; });
        }
      }) {}

RequestWatch::~RequestWatch() {
  thread_.request_stop();
  thread_.join();
}

bool deadline_passed(const grpc::ServerContext& context) {
  // gRPC fires its deadline timer on its own clock and converts the deadline to the system
  // clock for us, so a request cancelled by its deadline can look a few milliseconds
  // early here (measured: cancelled at 3.993 s of a 4 s deadline). A client that cancels
  // itself within this margin of its own deadline is told about the deadline.
  constexpr auto kClockSkew = std::chrono::milliseconds(250);
  return context.deadline() <= std::chrono::system_clock::now() + kClockSkew;
}

}  // namespace gvm::daemon
