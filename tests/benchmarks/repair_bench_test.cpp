// The repair study in-process, small: the harness's numbers must be ones a
// run can produce (a cost is 0 or a sum of suggestion costs; it once read
// freed memory and printed 1e-312). And the paired analysis the study uses
// (analyse_repair_study) must tell a strategy that brings a substitute from
// one that cannot, on runs made by hand whose answer is known.
#include "benchmarks/harness/repair_bench.h"
#include "benchmarks/harness/repair_study.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

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

namespace {

bench::StudyRun sibling_run(int home, int run, const std::string& strategy) {
  bench::StudyRun r;
  r.home = "home-" + std::to_string(home);
  r.run = run;
  r.strategy = strategy;
  r.kind = "sibling";
  r.latencies_ms = {3.0};
  r.stability = 2.0;
  r.planner_calls = 1;
  r.repairs = 1;
  return r;
}

// Substitute fetches the object of a sibling type the camera saw: the
// senior is comforted at cost 0, a little later. Replan knows only the
// problem's objects: it falls back on a suggestion (cost 500), or, in the
// second run of every third home, fails.
std::vector<bench::StudyRun> substitute_against_replan(int homes, int runs_per_home) {
  std::vector<bench::StudyRun> runs;
  for (int h = 0; h < homes; ++h) {
    for (int k = 0; k < runs_per_home; ++k) {
      bench::StudyRun replan = sibling_run(h, k, "replan");
      replan.comforted = !(k == 1 && h % 3 == 0);
      if (replan.comforted) {
        replan.delay = 0.0;
        replan.makespan = 80.0 + 2.0 * h;
        replan.cost = 500.0;
      }
      bench::StudyRun substitute = sibling_run(h, k, "substitute");
      substitute.comforted = true;
      substitute.delay = 20.0;
      substitute.makespan = 100.0 + h;
      substitute.cost = 0.0;
      runs.push_back(replan);
      runs.push_back(substitute);
    }
  }
  return runs;
}

std::string verdict(const bench::StudyAnalysis& a, const std::string& kind, const std::string& metric) {
  return a.json.at("kinds").at(kind).at("against_replan").at("substitute").at(metric).at("verdict");
}

}  // namespace

TEST_CASE("the study's analysis tells a strategy that brings a substitute from one that cannot") {
  // 10 homes, not the 6 one might first try: the signed-rank test is on
  // the homes' means, whose smallest exact two-sided p is 2 / 2^homes, and
  // Holm multiplies it by up to the family's 8 metrics: 6 homes give
  // 8 * 2/64 = 0.25, 10 homes 8 * 2/1024 = 0.016.
  stats::BootstrapOptions bootstrap;
  bootstrap.resamples = 500;
  const std::vector<std::string> strategies{"replan", "substitute"};
  const bench::StudyAnalysis a =
      bench::analyse_repair_study(substitute_against_replan(10, 2), strategies, "replan", bootstrap);
  for (const std::string kind : {"sibling", "all"}) {
    CHECK(verdict(a, kind, "cost") == "better");
    CHECK(verdict(a, kind, "metric") == "better");  // makespan + cost: -480 - h in home h
    // Every run counted: replan is sooner where it comforts (16 runs), but
    // fails 4 runs that substitute comforts; in the four homes with a
    // failure the two cancel, and 6 homes are too few for a verdict.
    CHECK(verdict(a, kind, "delay") == "tie");
    CHECK(verdict(a, kind, "latency_ms") == "tie");
    CHECK(a.json.at("wins").at(kind).at("cost").at("substitute") == "better");
    // On the runs both comforted, the secondary table, a substitute is
    // fetched and a suggestion is not: later.
    CHECK(a.json.at("kinds").at(kind).at("against_replan_common_set").at("substitute").at("delay").at("verdict") ==
          "worse");
  }
  const nlohmann::json& delay = a.json.at("kinds").at("sibling").at("against_replan").at("substitute").at("delay");
  CHECK(delay.at("pairs") == 20);
  CHECK(delay.at("wins") == 4);
  CHECK(delay.at("losses") == 16);
  CHECK(delay.at("mean_difference").get<double>() == Approx(-0.6));
  const nlohmann::json& cost = a.json.at("kinds").at("sibling").at("against_replan").at("substitute").at("cost");
  CHECK(cost.at("homes") == 10);
  CHECK(cost.at("pairs") == 20);  // every run: replan's 4 failures count as losses for replan
  CHECK(cost.at("wins") == 20);
  CHECK(cost.at("mean_difference") == 1.0);  // the net benefit
  CHECK(cost.at("rank_biserial") == 1.0);
  CHECK(cost.at("wilcoxon_p").get<double>() == Approx(2.0 / 1024.0));
  CHECK(cost.at("wilcoxon_p_holm").get<double>() > cost.at("wilcoxon_p").get<double>());
  CHECK(cost.at("wilcoxon_p_holm").get<double>() < 0.05);
  const nlohmann::json& common =
      a.json.at("kinds").at("sibling").at("against_replan_common_set").at("substitute").at("cost");
  CHECK(common.at("pairs") == 16);  // 20 runs; replan failed the second run of homes 0, 3, 6 and 9
  CHECK(common.at("mean_difference") == -500.0);
  CHECK(a.markdown.find("Holm p") != std::string::npos);

  SECTION("the same runs duplicated in fewer homes are not evidence: a tie") {
    // 3 homes of 6 identical runs each: 18 runs, but 3 independent values,
    // and an exact p of at least 2/8.
    std::vector<bench::StudyRun> copies;
    for (const bench::StudyRun& r : substitute_against_replan(3, 1)) {
      for (int k = 0; k < 6; ++k) {
        bench::StudyRun c = r;
        c.run = k;
        copies.push_back(c);
      }
    }
    const bench::StudyAnalysis few = bench::analyse_repair_study(copies, strategies, "replan", bootstrap);
    CHECK(few.json.at("kinds").at("sibling").at("against_replan").at("substitute").at("cost").at("pairs") == 18);
    CHECK(few.json.at("kinds").at("sibling").at("against_replan").at("substitute").at("cost").at("wins") == 18);
    CHECK(verdict(few, "sibling", "cost") == "tie");
  }

  SECTION("a strategy that does what replan does ties on every metric") {
    std::vector<bench::StudyRun> same;
    for (const bench::StudyRun& r : substitute_against_replan(10, 2)) {
      if (r.strategy != "replan") continue;
      same.push_back(r);
      same.push_back(r);
      same.back().strategy = "substitute";
    }
    const bench::StudyAnalysis tie = bench::analyse_repair_study(same, strategies, "replan", bootstrap);
    const nlohmann::json& against = tie.json.at("kinds").at("sibling").at("against_replan").at("substitute");
    CHECK(against.size() == 8);
    for (auto it = against.begin(); it != against.end(); ++it) {
      INFO(it.key());
      CHECK(it.value().at("verdict") == "tie");
    }
  }
}

TEST_CASE("a strategy that fails on the hard runs wins on the common set and loses when every run counts") {
  // In each of 10 homes, one easy run, where both comfort and the fragile
  // strategy is 5 s sooner, and two hard runs, where replan comforts and the
  // fragile one fails. Compared only where both comforted it is sooner in
  // every home; counted on every run it loses two pairs of three.
  std::vector<bench::StudyRun> runs;
  for (int h = 0; h < 10; ++h) {
    for (int k = 0; k < 3; ++k) {
      bench::StudyRun replan = sibling_run(h, k, "replan");
      replan.comforted = true;
      replan.delay = k == 0 ? 10.0 : 100.0;
      replan.makespan = 200.0;
      replan.cost = 0.0;
      bench::StudyRun fragile = sibling_run(h, k, "fragile");
      fragile.comforted = k == 0;
      if (fragile.comforted) {
        fragile.delay = 5.0;
        fragile.makespan = 195.0;
        fragile.cost = 0.0;
      }
      runs.push_back(replan);
      runs.push_back(fragile);
    }
  }
  stats::BootstrapOptions bootstrap;
  bootstrap.resamples = 500;
  const bench::StudyAnalysis a = bench::analyse_repair_study(runs, {"replan", "fragile"}, "replan", bootstrap);
  const nlohmann::json& kind = a.json.at("kinds").at("sibling");
  CHECK(kind.at("against_replan_common_set").at("fragile").at("delay").at("pairs") == 10);
  CHECK(kind.at("against_replan_common_set").at("fragile").at("delay").at("verdict") == "better");
  const nlohmann::json& delay = kind.at("against_replan").at("fragile").at("delay");
  CHECK(delay.at("pairs") == 30);
  CHECK(delay.at("wins") == 10);
  CHECK(delay.at("losses") == 20);
  CHECK(delay.at("mean_difference").get<double>() == Approx(-1.0 / 3.0));
  CHECK(delay.at("verdict") == "worse");
  CHECK(a.json.at("wins").at("sibling").at("delay").at("fragile") == "worse");
  CHECK(a.markdown.find("intention to treat") != std::string::npos);
  CHECK(a.markdown.find("Secondary") != std::string::npos);
}
