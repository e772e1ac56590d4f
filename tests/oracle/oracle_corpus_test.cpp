// The reference semantics against VAL on every shared plan: the 1,068 plans
// of ../shared/benchmarks/plans (IPC temporal domains, originals and broken
// variants) and the 164 of ../shared/benchmarks/pddl3/plans (IPC 2006's
// PDDL 3 tracks). The verdict must be VAL's, and the value of a valid plan
// VAL's within 1e-3. Where VAL cannot judge a plan the test names it.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <map>
#include <memory>

#include "oracle/judge.h"
#include "oracle/load.h"
#include "tests/support/test_paths.h"

using namespace alplan;

namespace {

std::vector<std::vector<std::string>> read_csv(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  std::vector<std::vector<std::string>> rows;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::string cell;
    bool quoted = false;
    for (char c : line) {
      if (c == '"') quoted = !quoted;
      else if (c == ',' && !quoted) cells.push_back(std::move(cell)), cell.clear();
      else if (c != '\r') cell += c;
    }
    cells.push_back(cell);
    rows.push_back(std::move(cells));
  }
  return rows;
}

class Judges {
 public:
  oracle::Judge& get(const std::string& domain, const std::string& problem) {
    auto& judge = judges_[domain + "|" + problem];
    if (!judge) {
      const oracle::LoadedTask task = oracle::load_task_files(domain, problem);
      INFO(task.error);
      REQUIRE(task.ok());
      judge = std::make_unique<oracle::Judge>(task.domain, task.problem);
    }
    return *judge;
  }

 private:
  std::map<std::string, std::unique_ptr<oracle::Judge>> judges_;
};

struct Tally {
  int agree = 0, valid = 0;
  std::string disagreements;
  void add(const std::string& plan, bool val_valid, const std::string& val_value, const oracle::Verdict& v) {
    bool same = v.valid() == val_valid;
    if (same && val_valid) same = std::fabs(v.value - std::stod(val_value)) <= 1e-3;
    valid += v.valid() ? 1 : 0;
    if (same) {
      ++agree;
      return;
    }
    disagreements += plan + ": VAL " + (val_valid ? "valid " + val_value : "invalid") + ", oracle " +
                     (v.valid() ? "valid " + std::to_string(v.value) : std::string(oracle::to_string(v.failure)) +
                                                                           ": " + v.reason) + "\n";
  }
};

// The kind of failure VAL's first reason line names (plans/README.md).
std::string val_failure(const std::string& reason) {
  if (reason.rfind("Bad plan description", 0) == 0) return "bad_plan";
  if (reason.find("Failed duration constraint") != std::string::npos) return "duration";
  if (reason.rfind("Invariant for", 0) == 0) return "invariant";
  if (reason.find("has an unsatisfied precondition") != std::string::npos) return "precondition";
  if (reason.find("goal is not satisfied") != std::string::npos) return "goal";
  if (reason.find("Mutex") != std::string::npos) return "mutex";
  return "other: " + reason;
}

}  // namespace

TEST_CASE("the reference semantics agrees with VAL on every plan of the IPC corpus") {
  const std::string dir = test::benchmarks_dir();
  const auto rows = read_csv(dir + "/plans/index.csv");
  REQUIRE(rows.size() == 1068);
  Judges judges;
  Tally tally;
  int kinds_differ = 0;
  for (const auto& row : rows) {
    oracle::Judge& judge = judges.get(dir + "/" + row[0], dir + "/" + row[1]);
    const oracle::TimedPlanRead plan = oracle::read_timed_plan(test::read_text(dir + "/" + row[2]));
    REQUIRE(plan.ok());
    const oracle::Verdict verdict = judge.judge(plan.plan);
    tally.add(row[2], row[3] == "valid", row[4], verdict);
    if (row[3] == "invalid" && !verdict.valid() &&
        std::string(oracle::to_string(verdict.failure)) != val_failure(row[6])) {
      tally.disagreements += row[2] + ": VAL fails it for " + val_failure(row[6]) + ", the oracle for " +
                             oracle::to_string(verdict.failure) + ": " + verdict.reason + "\n";
      ++kinds_differ;
    }
  }
  INFO(tally.disagreements);
  CHECK(kinds_differ == 0);
  CHECK(tally.agree == 1068);
  CHECK(tally.valid == 148);
}

TEST_CASE("the reference semantics agrees with VAL on every PDDL 3 plan") {
  const std::string dir = test::benchmarks_dir() + "/pddl3";
  const auto rows = read_csv(dir + "/plans/index.csv");
  REQUIRE(rows.size() == 164);
  Judges judges;
  Tally tally;
  for (const auto& row : rows) {
    oracle::Judge& judge = judges.get(dir + "/" + row[0] + "/domain.pddl",
                                      dir + "/" + row[0] + "/instances/instance-" + row[1] + ".pddl");
    const oracle::TimedPlanRead plan = oracle::read_timed_plan(test::read_text(dir + "/plans/" + row[2]));
    REQUIRE(plan.ok());
    tally.add(row[2], row[3] == "1", row[4], judge.judge(plan.plan));
  }
  INFO(tally.disagreements);
  CHECK(tally.agree == 164);
  CHECK(tally.valid == 94);
}
