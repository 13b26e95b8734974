// Admission: at most max_jobs requests compute at once, at most max_queue wait behind
// them in arrival order, and the rest are refused at once (RESOURCE_EXHAUSTED), so that a
// burst never piles up unbounded work. While draining every new request is refused
// (UNAVAILABLE).
#pragma once

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <utility>

#include "gvm/status.h"

namespace gvm::daemon {

class JobSlots {
 public:
  JobSlots(unsigned max_jobs, unsigned max_queue) : max_jobs_(max_jobs), max_queue_(max_queue) {}

  // Holds a slot until destroyed.
  class Slot {
   public:
    explicit Slot(JobSlots* owner) : owner_(owner) {}
    Slot(Slot&& o) noexcept : owner_(std::exchange(o.owner_, nullptr)) {}
    Slot& operator=(Slot&&) = delete;
    ~Slot() {
      if (owner_) owner_->release();
    }

   private:
    JobSlots* owner_;
  };

  // Waits for a slot; `gave_up` is polled while waiting (the client cancelled or its
  // deadline passed: CANCELLED).
  StatusOr<Slot> acquire(const std::function<bool()>& gave_up);
  void drain();  // refuse from now on
  unsigned running() const;
  unsigned waiting() const;

 private:
  void release();

  const unsigned max_jobs_, max_queue_;
  mutable std::mutex mutex_;
  std::condition_variable freed_;
  std::deque<uint64_t> queue_;  // tickets waiting, oldest first
  uint64_t next_ticket_ = 0;
  unsigned running_ = 0;
  bool draining_ = false;
};

}  // namespace gvm::daemon
