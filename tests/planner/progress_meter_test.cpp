#include "planner/progress_meter.h"

#include <catch2/catch.hpp>

#include <sstream>

namespace alplan {

TEST_CASE("a progress bar shows the share done, the rate and the time left", "[progress]") {
  CHECK(ProgressMeter::bar(5, 10, "problems", 10.0, 10) == "[=====>    ] 5/10 problems  0.5/s  ETA 0:10");
  CHECK(ProgressMeter::bar(0, 10, "problems", 0.0, 4) == "[>   ] 0/10 problems  0/s  ETA ?");
  CHECK(ProgressMeter::bar(3600, 7200, "simulated s", 36.0, 2) == "[=>] 3600/7200 simulated s  100/s  ETA 0:36");
  CHECK(ProgressMeter::bar(6995.0000001, 7200, "simulated s", 1.0, 2) == "[=>] 6995/7200 simulated s  6995/s  ETA 0:00");
  CHECK(ProgressMeter::bar(2.5, 4, "hours", 2.0, 2) == "[=>] 2.5/4 hours  1.25/s  ETA 0:01");
}

TEST_CASE("away from a terminal the meter writes plain lines only", "[progress]") {
  std::ostringstream out;
  {
    ProgressMeter meter(out, 3, "runs", false);
    meter.update(1, "first done");
    meter.update(2);
    meter.update(3, "third done");
  }
  CHECK(out.str() == "first done\nthird done\n");
}

TEST_CASE("on a terminal the bar is redrawn under the lines", "[progress]") {
  std::ostringstream out;
  ProgressMeter meter(out, 2, "runs", true);
  meter.update(1, "first done");
  meter.finish();
  const std::string text = out.str();
  CHECK(text.rfind("\r\033[Kfirst done\n[", 0) == 0);
  CHECK(text.find("1/2 runs") != std::string::npos);
  CHECK(text.back() == '\n');
}

TEST_CASE("the simulated-time meter prints a line each simulated hour", "[progress]") {
  std::ostringstream out;
  ProgressMeter meter(out, 3 * 3600, "simulated s", false);
  const auto on_time = simulated_time_meter(meter);
  for (double t = 0; t <= 3 * 3600; t += 5) on_time(t);
  CHECK(out.str() == "simulated 1 h\nsimulated 2 h\nsimulated 3 h\n");
}

}  // namespace alplan
