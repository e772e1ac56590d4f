// The running home's clock. Simulated, the loop runs as fast as it can:
// time is what the loop says. In real time (`alplan home --live`) the run's
// time t is wall-clock seconds since the run began: the loop (and the
// monitor executing a plan) waits until the wall clock reaches t, so the
// robots' actions take as long as their durations, and time spent
// planning is time that passed (the loop catches up after it).
#pragma once

#include <chrono>
#include <condition_variable>
#include <mutex>

namespace alplan::home {

class RunClock {
 public:
  virtual ~RunClock() = default;
  // Returns once the run may be at time t: true to go on, false when the
  // run must end instead (stopped, or t past its end).
  virtual bool wait_until(double t) = 0;
};

class SimulatedClock final : public RunClock {
 public:
  bool wait_until(double) override { return true; }
};

class WallClock final : public RunClock {
 public:
  // Time 0 is now; the run ends at `until` seconds.
  explicit WallClock(double until);
  bool wait_until(double t) override;
  // Ends the run: a wait returns false at once, and so does every later
  // one. Thread-safe (a signal watcher calls it).
  void stop();
  bool stopped() const;
  // Seconds since time 0.
  double now() const;

 private:
  const std::chrono::steady_clock::time_point start_;
  const double until_;
  mutable std::mutex mutex_;
  std::condition_variable woken_;
  bool stopped_ = false;
};

}  // namespace alplan::home
