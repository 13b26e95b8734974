// Watches one running request from a thread of its own: when the client cancels, its
// deadline passes or it disconnects, the request's stop source is triggered (the engine
// and the planner stop within milliseconds and the cores go back to the other requests);
// and now and then it reports progress, so that a stream's writes all come from one
// thread while the work runs.
#pragma once

#include <grpcpp/server_context.h>

#include <chrono>
#include <functional>
#include <stop_token>
#include <thread>

namespace gvm::daemon {

class RequestWatch {
 public:
  // `tick` (may be empty) is called about twice a second until the watch ends.
  RequestWatch(grpc::ServerContext* context, std::stop_source stop, std::function<void()> tick = {});
  ~RequestWatch();  // ends the watch: `tick` is not called after it returns
  RequestWatch(const RequestWatch&) = delete;
  RequestWatch& operator=(const RequestWatch&) = delete;

 private:
  std::jthread thread_;
};

// The request's deadline has passed: an abort is DEADLINE_EXCEEDED rather than CANCELLED.
bool deadline_passed(const grpc::ServerContext& context);

}  // namespace gvm::daemon
