// The repair study in-process, small: the harness's numbers must be ones a
// run can produce (a cost is 0 or a sum of suggestion costs; it once read
// freed memory and printed 1e-312), and the paired analysis must tell a
// strategy that brings a substitute from one that cannot.
#include "benchmarks/harness/repair_bench.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "tests/support/test_paths.h"

using namespace alplan;

TEST_CASE("bench repair writes a paired study whose costs are real") {
  bench::RepairBenchOptions o;
  o.homes = 3;
  o.runs_per_home = 3;
  o.seed = 1;
  o.strategies = {"replan", "substitute"};
  o.events.kinds = {repair::RandomEventKind::SiblingPresent, repair::RandomEventKind::Overrun};
  o.paper_home = false;
  o.bootstrap.resamples = 200;
  o.assisted_living_dir = test::source_dir() + "/domains/assisted_living";
  o.out_dir = (std::filesystem::temp_directory_path() / "alplan-repair-bench-test").string();
  std::filesystem::remove_all(o.out_dir);
  std::ostringstream out, progress;
  REQUIRE(bench::run_repair_bench(o, out, progress) == 0);
  CHECK(out.str().find("## Where each strategy wins") != std::string::npos);
  std::ifstream runs_file(o.out_dir + "/runs.json");
  const nlohmann::json runs = nlohmann::json::parse(runs_file);
  REQUIRE(runs.size() == 18);
  for (const nlohmann::json& r : runs) {
    const double cost = r["cost"];
    CHECK(std::isfinite(cost));
    CHECK(std::fmod(cost, 500.0) == 0.0);  // suggestion_cost is 500 in every generated home
    CHECK(cost >= 0.0);
  }
  std::ifstream summary_file(o.out_dir + "/summary.json");
  const nlohmann::json summary = nlohmann::json::parse(summary_file);
  CHECK(summary["kinds"].contains("all"));
  CHECK(summary["kinds"]["all"]["against_replan"]["substitute"].contains("delay"));
  CHECK(std::filesystem::exists(o.out_dir + "/plots/delay-vs-replan.svg"));
  CHECK(std::filesystem::exists(o.out_dir + "/summary.md"));
}
