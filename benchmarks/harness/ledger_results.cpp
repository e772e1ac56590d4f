#include "benchmarks/harness/ledger_results.h"

namespace alplan::bench {
namespace {

// counts[key] += add, the key absent counting as 0 (counts an object).
void add_to(nlohmann::json& counts, const char* key, int add) {
  counts[key] = (counts.contains(key) ? counts[key].get<int>() : 0) + add;
}

}  // namespace

nlohmann::json repair_ledger_result(const std::map<std::string, std::vector<StudyRun>>& runs_by_model) {
  nlohmann::json result = nlohmann::json::object();
  for (const auto& [model, runs] : runs_by_model) {
    nlohmann::json strategies = nlohmann::json::object();
    for (const StudyRun& r : runs) {
      if (!strategies.contains(r.strategy)) strategies[r.strategy] = nlohmann::json::object();
      add_to(strategies[r.strategy], "runs", 1);
      add_to(strategies[r.strategy], "comforted", r.comforted ? 1 : 0);
    }
    result[model] = std::move(strategies);
  }
  return result;
}

nlohmann::json stability_ledger_result(const StabilityBenchResult& result) {
  nlohmann::json strategies = nlohmann::json::object();
  std::map<std::string, std::pair<double, int>> distances;
  for (const StabilityRun& r : result.runs) {
    if (!strategies.contains(r.strategy)) strategies[r.strategy] = nlohmann::json::object();
    add_to(strategies[r.strategy], "runs", 1);
    add_to(strategies[r.strategy], "valid", r.valid ? 1 : 0);
    if (r.valid) {
      distances[r.strategy].first += static_cast<double>(r.distance);
      ++distances[r.strategy].second;
    }
  }
  for (const auto& [name, sum] : distances) strategies[name]["mean_distance_valid"] = sum.first / sum.second;
  return {{"strategies", strategies}, {"skipped", result.skipped.size()}};
}

}  // namespace alplan::bench
