#include "job_slots.h"

#include <algorithm>
#include <chrono>
#include <string>

namespace gvm::daemon {

StatusOr<JobSlots::Slot> JobSlots::acquire(const std::function<bool()>& gave_up) {
  std::unique_lock lock(mutex_);
  if (draining_) return Status(StatusCode::kUnavailable, "the daemon is shutting down");
  if (queue_.empty() && running_ < max_jobs_) {
    ++running_;
    return Slot(this);
  }
  if (queue_.size() >= max_queue_) {
    return ResourceExhausted("the daemon is busy: " + std::to_string(running_) + " request(s) running and " +
                             std::to_string(queue_.size()) + " waiting (gvmd --max-jobs " + std::to_string(max_jobs_) +
                             ", --max-queue " + std::to_string(max_queue_) + "); try again later");
  }
  const uint64_t ticket = next_ticket_++;
  queue_.push_back(ticket);
  while (!(queue_.front() == ticket && running_ < max_jobs_)) {
    if (draining_ || gave_up()) {
      queue_.erase(std::find(queue_.begin(), queue_.end(), ticket));
      freed_.notify_all();  // the next in line may now be at the front
      if (draining_) return Status(StatusCode::kUnavailable, "the daemon is shutting down");
      return Status(StatusCode::kCancelled, "the client gave up while the request was queued");
    }
    freed_.wait_for(lock, std::chrono::milliseconds(50));
  }
  queue_.pop_front();
  ++running_;
  freed_.notify_all();
  return Slot(this);
}

void JobSlots::release() {
  std::lock_guard lock(mutex_);
  --running_;
  freed_.notify_all();
}

void JobSlots::drain() {
  std::lock_guard lock(mutex_);
  draining_ = true;
  freed_.notify_all();
}

unsigned JobSlots::running() const {
  std::lock_guard lock(mutex_);
  return running_;
}

unsigned JobSlots::waiting() const {
  std::lock_guard lock(mutex_);
  return static_cast<unsigned>(queue_.size());
}

}  // namespace gvm::daemon
