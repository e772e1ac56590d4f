// What the ledger keeps of a run's result (benchmarks/harness/
// ledger_results.h), counted by hand on constructed runs. Both summaries
// once threw on their first run (a count read from a key not yet there),
// after the run itself had ended: the ledger then held a start with no end.
#include "benchmarks/harness/ledger_results.h"

#include <catch2/catch.hpp>

using namespace alplan::bench;

TEST_CASE("the repair study's ledger result counts runs and comforted runs per model and strategy") {
  auto run = [](const std::string& strategy, bool comforted) {
    StudyRun r;
    r.strategy = strategy;
    r.comforted = comforted;
    return r;
  };
  const std::map<std::string, std::vector<StudyRun>> by_model{
      {"iot", {run("replan", true), run("replan", false), run("suggest", false)}},
      {"full", {run("replan", true)}}};
  const nlohmann::json result = repair_ledger_result(by_model);
  CHECK(result["iot"]["replan"]["runs"] == 2);
  CHECK(result["iot"]["replan"]["comforted"] == 1);
  CHECK(result["iot"]["suggest"]["runs"] == 1);
  CHECK(result["iot"]["suggest"]["comforted"] == 0);
  CHECK(result["full"]["replan"]["comforted"] == 1);
  CHECK(repair_ledger_result({}).is_object());
}

TEST_CASE("the stability study's ledger result counts valid repairs and their mean distance") {
  StabilityBenchResult runs;
  for (const auto& [strategy, valid, distance] :
       {std::tuple{"replan", true, 4}, std::tuple{"replan", true, 6}, std::tuple{"replan", false, 0},
        std::tuple{"adapt", false, 0}}) {
    StabilityRun r;
    r.strategy = strategy;
    r.valid = valid;
    r.distance = static_cast<std::size_t>(distance);
    runs.runs.push_back(r);
  }
  runs.skipped = {"rovers 7: no perturbation breaks the plan"};
  const nlohmann::json result = stability_ledger_result(runs);
  CHECK(result["strategies"]["replan"]["runs"] == 3);
  CHECK(result["strategies"]["replan"]["valid"] == 2);
  CHECK(result["strategies"]["replan"]["mean_distance_valid"].get<double>() == Approx(5.0));
  CHECK(result["strategies"]["adapt"]["valid"] == 0);
  CHECK_FALSE(result["strategies"]["adapt"].contains("mean_distance_valid"));
  CHECK(result["skipped"] == 1);
}
