// The flags `alplan home` and `alplan bench home` share: how the simulated
// seniors behave and how the home plans (home/home_settings.h).
#pragma once

#include <CLI/CLI.hpp>

#include "home/home_settings.h"

namespace alplan::cli {

void add_home_run_options(CLI::App& cmd, home::HomeSettings& s);
// --battery and the battery's values (domains/battery_home.h); part of the above.
void add_battery_options(CLI::App& cmd, home::HomeSettings& s);

}  // namespace alplan::cli
