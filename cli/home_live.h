// `alplan home --live`: the running home fed by the signal service in the
// same process, in real time. The wristbands POST readings to the service
// (as to `alplan serve`); its stress events become the home's goals
// (home/live_goal_source.h); every event of the run also goes into the
// service's database (perception/service/home_event_store.h).
#pragma once

#include <string>

#include "cli/service_flags.h"
#include "home/event_log.h"
#include "home/home_run.h"
#include "home/home_settings.h"

namespace CLI {
class App;
}

namespace alplan::cli {

struct LiveFlags {
  bool live = false;
  ServiceFlags service;
  std::string face, emotion;  // the seniors' face: there is no camera
};

// --live, the service's flags, --face, --emotion.
void add_live_flags(CLI::App& command, LiveFlags& flags);

// Throws CommandInputError when live flags come without --live, or --live
// lacks what it needs (--db, --tokens, a face or an emotion).
void check_live_flags(const LiveFlags& flags);

// Runs until settings.until seconds of wall time or SIGINT/SIGTERM. Prints
// "serving on URL ..." as the first line on stdout once the wristbands can
// post. `log_file`: also written there when not empty. Throws
// CommandInputError (or the service's errors) before it listens.
home::HomeSummary run_live_home(const home::HomeSettings& settings, const LiveFlags& flags, const std::string& log_file,
                                const home::EventLog::Echo& narrate);

}  // namespace alplan::cli
