// `alplan bench home`: the running home at scale (issue 16: 50 rooms, 40
// seniors, 4 robots, 400 objects, 8 simulated hours), measured: planning
// latency by why the plan was made (a new mission, a goal merged, a
// repair), the share of goals comforted within their windows, and the
// wall-clock speed of the simulation. A table on stdout, JSON beside it.
#pragma once

#include <functional>
#include <ostream>
#include <string>

#include <nlohmann/json.hpp>

#include "home/home_run.h"
#include "home/home_settings.h"

namespace alplan::home {

struct HomeBenchResult {
  HomeSummary summary;
  double wall_seconds = 0.0;
  std::size_t events = 0;
  nlohmann::json json(const HomeSettings& settings) const;
};

HomeBenchResult run_home_bench(const HomeSettings& settings, const std::function<void(double)>& on_time = {});
void print_home_bench(std::ostream& out, const HomeSettings& settings, const HomeBenchResult& result);

}  // namespace alplan::home
