// `alplan bench grounding`: grounds the largest problem of every domain of a
// suite, each in its own process under the time and memory limits, and
// reports wall time, peak memory and sizes.
#pragma once

#include <iosfwd>
#include <string>

#include "benchmarks/harness/process_runner.h"

namespace alplan::bench {

struct GroundingBenchOptions {
  std::string suite;       // folder or list
  std::string out_dir;     // grounding.csv, grounding.json, grounding.md
  std::string alplan;      // the executable that grounds (`alplan ground --json`)
  RunLimits limits;
  bool largest_only = true;
};

// Returns the number of problems that did not ground within the limits.
int run_grounding_bench(const GroundingBenchOptions& options, std::ostream& out, std::ostream& progress);

}  // namespace alplan::bench
