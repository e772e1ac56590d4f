// What the test-set ledger keeps of a run's result (test_set_ledger.h): a
// few counts per strategy, enough to see what the run found without its
// folder; the README's tables come from the folders.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "benchmarks/harness/repair_study.h"
#include "benchmarks/harness/stability_bench.h"

namespace alplan::bench {

// Per observation model and strategy: runs, and runs that comforted the senior.
nlohmann::json repair_ledger_result(const std::map<std::string, std::vector<StudyRun>>& runs_by_model);

// Per strategy: runs, valid repairs and the mean distance over the valid
// ones; and how many problems or perturbations were skipped.
nlohmann::json stability_ledger_result(const StabilityBenchResult& result);

}  // namespace alplan::bench
