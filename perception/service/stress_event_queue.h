// Stress events on their way from the signal service to the deliberation
// loop, in the same process: the service pushes one whenever a senior's
// stress decision flips; the deliberation pops them (blocking with a timeout,
// or polling) and wakes its layers (emotion recognition, goals, planning).
//
// Bounded, so a deliberation that stops consuming cannot make the service
// grow without limit: when full, a push drops the oldest event and counts it.
// Every event is also in the database (reading_store.h), so a dropped one can
// be read back. Thread-safe: any number of producers and consumers.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <mutex>
#include <optional>
#include <string>

namespace alplan::perception::service {

struct StressEvent {
  std::string senior;
  std::string device;     // whose reading flipped the decision
  bool stressed = false;  // true: became stressed; false: calm again
  std::uint64_t t_ms = 0;  // the end of that reading's window (Unix ms)
  double stressed_fraction = 0.0;  // of the votes in the smoothing window
  std::size_t votes = 0;
};

class StressEventQueue {
 public:
  // Precondition: capacity > 0.
  explicit StressEventQueue(std::size_t capacity);

  // False when the queue is closed (the event is not kept).
  bool push(const StressEvent& event);
  std::optional<StressEvent> try_pop();
  // Waits up to `timeout` for an event; nothing on timeout or once closed
  // and empty.
  std::optional<StressEvent> pop_wait(std::chrono::milliseconds timeout);
  // Wakes every waiter; later pushes are refused, queued events can still be
  // popped.
  void close();

  bool closed() const;
  std::size_t size() const;
  std::uint64_t dropped() const;
  std::size_t capacity() const { return capacity_; }

 private:
  const std::size_t capacity_;
  mutable std::mutex mutex_;
  std::condition_variable available_;
  std::deque<StressEvent> events_;
  std::uint64_t dropped_ = 0;
  bool closed_ = false;
};

}  // namespace alplan::perception::service
