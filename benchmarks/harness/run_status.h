// What a run of `alplan plan --json` in a child process came to, as the
// planner harness counts it: solved, unsolvable, exhausted, limit or error.
// A limit is a limit whichever phase reached it and whoever noticed: the
// runner's wall clock, the planner (status limit_reached), the CLI before
// the planner ran (exit 11), or an allocation the address-space limit
// refused that escaped the CLI (an abort reporting std::bad_alloc).
#pragma once

#include <nlohmann/json.hpp>

#include <string>

#include "benchmarks/harness/process_runner.h"

namespace alplan::bench {

// `output` is the child's standard output parsed as JSON (discarded if not).
std::string planner_run_status(const RunResult& run, const nlohmann::json& output);

}  // namespace alplan::bench
