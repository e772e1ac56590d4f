#include "perception/service/stress_event_queue.h"

#include <stdexcept>

namespace alplan::perception::service {

StressEventQueue::StressEventQueue(std::size_t capacity) : capacity_(capacity) {
  if (capacity == 0) throw std::invalid_argument("a stress event queue needs room for at least one event");
}

bool StressEventQueue::push(const StressEvent& event) {
  {
    const std::lock_guard lock(mutex_);
    if (closed_) return false;
    if (events_.size() == capacity_) {
      events_.pop_front();
      ++dropped_;
    }
    events_.push_back(event);
  }
  available_.notify_one();
  return true;
}

std::optional<StressEvent> StressEventQueue::try_pop() {
  const std::lock_guard lock(mutex_);
  if (events_.empty()) return std::nullopt;
  StressEvent event = std::move(events_.front());
  events_.pop_front();
  return event;
}

std::optional<StressEvent> StressEventQueue::pop_wait(std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex_);
  available_.wait_for(lock, timeout, [this] { return !events_.empty() || closed_; });
  if (events_.empty()) return std::nullopt;
  StressEvent event = std::move(events_.front());
  events_.pop_front();
  return event;
}

void StressEventQueue::close() {
  {
    const std::lock_guard lock(mutex_);
    closed_ = true;
  }
  available_.notify_all();
}

bool StressEventQueue::closed() const {
  const std::lock_guard lock(mutex_);
  return closed_;
}

std::size_t StressEventQueue::size() const {
  const std::lock_guard lock(mutex_);
  return events_.size();
}

std::uint64_t StressEventQueue::dropped() const {
  const std::lock_guard lock(mutex_);
  return dropped_;
}

}  // namespace alplan::perception::service
