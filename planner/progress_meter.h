// Progress of a long run for the person waiting on it (bench planners,
// bench repair, a home over simulated hours): on a terminal, a bar with the
// rate and the time left, redrawn in place under the lines of what
// finished; elsewhere (a log, CI) the plain lines only, so files stay
// readable. Counts may be runs or simulated seconds: the unit is a word.
#pragma once

#include <chrono>
#include <functional>
#include <ostream>
#include <string>

namespace alplan {

class ProgressMeter {
 public:
  // `terminal`: draw the bar (the caller knows whether `out` is a tty).
  ProgressMeter(std::ostream& out, double total, std::string unit, bool terminal);
  ~ProgressMeter();
  ProgressMeter(const ProgressMeter&) = delete;
  ProgressMeter& operator=(const ProgressMeter&) = delete;

  // `done` so far (not more than total), and what just finished, printed
  // as a line of its own when not empty.
  void update(double done, const std::string& line = {});
  // Leaves the last bar on screen and goes to a new line.
  void finish();

  // "[=======>      ] 12/65 problems  0.8/s  ETA 1:06", `width` marks wide.
  static std::string bar(double done, double total, const std::string& unit, double elapsed_s, int width = 30);

 private:
  std::ostream& out_;
  double total_;
  std::string unit_;
  bool terminal_;
  bool drawn_ = false;
  double done_ = 0.0;
  std::chrono::steady_clock::time_point began_ = std::chrono::steady_clock::now();
};

// For runs that count simulated seconds: redraws the bar at most once a
// simulated minute and prints a line each simulated hour. `meter` must
// outlive the callback.
std::function<void(double)> simulated_time_meter(ProgressMeter& meter);

}  // namespace alplan
