// SIGINT and SIGTERM as a stop request: a batch stops starting parts, interrupts those
// running (their records say so) and writes its summary, so that --resume goes on.
#pragma once

#include <atomic>
#include <stop_token>
#include <thread>

namespace gvm::batch {

class SignalStop {
 public:
  // Blocks both signals in this thread and every thread it starts afterwards (construct it
  // before any other thread), and waits for them in its own thread.
  SignalStop();
  ~SignalStop();
  SignalStop(const SignalStop&) = delete;
  SignalStop& operator=(const SignalStop&) = delete;

  std::stop_token token() const { return stop_.get_token(); }
  // The signal that stopped the batch, or 0.
  int signal() const { return signal_; }

 private:
  std::stop_source stop_;
  std::atomic<int> signal_ = 0;
  std::jthread waiter_;
};

}  // namespace gvm::batch
