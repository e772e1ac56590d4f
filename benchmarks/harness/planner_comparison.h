// The planners `bench planners` sets ours beside: a baseline's recorded runs
// (baseline.h) and other planners run here by their command lines
// (external_planner.h), merged into one set of references, and what a
// reader must be warned of before comparing them.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "benchmarks/harness/baseline.h"
#include "benchmarks/harness/external_planner.h"

namespace alplan::bench {

// The other planners' runs on one problem of the suite, by planner name.
struct ProblemRuns {
  std::string problem_file;
  std::map<std::string, ExternalRun> external;
};

// The baseline in `baseline_folder` ("" for none: no reference columns) with
// each other planner a column, its valid plans competing for the best value
// the quality score divides by. A problem no baseline knows takes its
// metric's direction from its file.
Baseline compared_planners(const std::string& baseline_folder, const std::vector<ExternalPlanner>& others,
                           const std::vector<ProblemRuns>& runs);

// Whether the problem file's metric is maximised (comments skipped; false
// without a metric or a readable file).
bool maximises(const std::string& problem_file);

// What differs between our runs and the references' conditions: a time
// limit unlike the baseline's, several runs at once.
std::vector<std::string> comparison_warnings(const Baseline& reference, double time_limit, int jobs);

}  // namespace alplan::bench
