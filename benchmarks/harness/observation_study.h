// What the monitor's sensors change (issue 32): the same repair study run
// under each observation model (repair/observation.h: full, the true state;
// iot, the paper's tags, wristbands and camera; camera, the robot's camera
// alone). The failures are drawn from each run's seed and its plan, which
// no observation model changes, so run (home, run, strategy) under one
// model meets the same failure as under another: the models are compared
// run by run. Per failure kind, one table: each strategy's success, delay
// and cost under each model, then the value of observation as paired
// differences: full against iot, and iot against camera (the tags). The kinds whose discovery depends on what is
// seen (an unavailable object found on arrival, foreseen by its tag, a
// substitute seen on the way) come first, apart from those the home is
// told of or that are timed (moves, emotion, overrun).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "stats/paired_comparison.h"
#include "benchmarks/harness/repair_study.h"

namespace alplan::bench {

// `by_model`: each model's runs (runs.json of bench repair); `strategies`
// in the order to report. Markdown.
std::string observation_tables(const std::map<std::string, std::vector<StudyRun>>& by_model,
                               const std::vector<std::string>& strategies, const stats::BootstrapOptions& bootstrap);

}  // namespace alplan::bench
