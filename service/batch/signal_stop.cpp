#include "signal_stop.h"

#include <spdlog/spdlog.h>

#include <csignal>
#include <ctime>

namespace gvm::batch {
namespace {

sigset_t stop_signals() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  return set;
}

}  // namespace

SignalStop::SignalStop() {
  const sigset_t set = stop_signals();
  pthread_sigmask(SIG_BLOCK, &set, nullptr);
  waiter_ = std::jthread([this, set](std::stop_token done) {
    const timespec tick{0, 200'000'000};  // how soon the destructor's join returns
    while (!done.stop_requested()) {
      const int s = sigtimedwait(&set, nullptr, &tick);
      if (s <= 0) continue;
      if (signal_.exchange(s) == 0) {
        spdlog::warn("{}: stopping; the parts running are interrupted, --resume goes on from here", strsignal(s));
      }
      stop_.request_stop();
    }
  });
}

SignalStop::~SignalStop() {
  waiter_.request_stop();
  waiter_.join();
  const sigset_t set = stop_signals();
  pthread_sigmask(SIG_UNBLOCK, &set, nullptr);
}

}  // namespace gvm::batch
