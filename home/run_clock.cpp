#include "home/run_clock.h"

namespace alplan::home {

WallClock::WallClock(double until) : start_(std::chrono::steady_clock::now()), until_(until) {}

bool WallClock::wait_until(double t) {
  // The loop's steps land on the run's end exactly; a hair above is float.
  if (t > until_ + 1e-6) return false;
  const auto when = start_ + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                 std::chrono::duration<double>(t));
  std::unique_lock lock(mutex_);
  woken_.wait_until(lock, when, [this] { return stopped_; });
  return !stopped_;
}

void WallClock::stop() {
  {
    const std::lock_guard lock(mutex_);
    stopped_ = true;
  }
  woken_.notify_all();
}

bool WallClock::stopped() const {
  const std::lock_guard lock(mutex_);
  return stopped_;
}

double WallClock::now() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

}  // namespace alplan::home
