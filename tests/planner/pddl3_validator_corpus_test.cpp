// The 164 plans of ../shared/benchmarks/pddl3/plans (OPTIC's plans for the
// IPC 2006 PDDL 3 domains, and each last plan with one step left out), with
// VAL's verdict and value: ours must give the same verdict and, for valid
// plans, the same value within 1e-3. All 164 agree (94 valid).
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <set>

#include "planner/validator.h"
#include "tests/support/task_loader.h"
#include "tests/support/test_paths.h"

using namespace alplan;

namespace {

struct Row {
  std::string domain, problem, plan, valid, value;
};

std::vector<Row> read_index(const std::string& dir) {
  std::ifstream in(dir + "/plans/index.csv");
  std::string line;
  std::getline(in, line);
  std::vector<Row> rows;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::string cell;
    for (char c : line) {
      if (c == ',') cells.push_back(std::move(cell)), cell.clear();
      else if (c != '\r') cell += c;
    }
    cells.push_back(cell);
    rows.push_back({cells.at(0), cells.at(1), cells.at(2), cells.at(3), cells.at(4)});
  }
  return rows;
}

}  // namespace

TEST_CASE("the validator agrees with VAL on every PDDL 3 plan") {
  const std::string dir = test::benchmarks_dir() + "/pddl3";
  const std::vector<Row> rows = read_index(dir);
  REQUIRE(rows.size() == 164);
  std::map<std::string, std::unique_ptr<PlanValidator>> validators;
  int agree = 0, valid = 0;
  std::string disagreements;
  for (const Row& row : rows) {
    auto& validator = validators[row.domain + "|" + row.problem];
    if (!validator) {
      const test::LoadedTask task = test::load_task(dir + "/" + row.domain + "/domain.pddl",
                                                    dir + "/" + row.domain + "/instances/instance-" + row.problem + ".pddl");
      validator = std::make_unique<PlanValidator>(task.normalized);
    }
    const std::string path = dir + "/plans/" + row.plan;
    const PlanReadResult plan = read_plan(test::read_text(path), path);
    REQUIRE(plan.ok());
    const ValidationResult result = validator->validate(plan.plan);
    const bool val_valid = row.valid == "1";
    bool same = result.valid == val_valid;
    if (same && val_valid) same = std::fabs(result.value - std::stod(row.value)) <= 1e-3;
    valid += result.valid ? 1 : 0;
    if (same) {
      ++agree;
      continue;
    }
    disagreements += row.plan + ": VAL " + (val_valid ? "valid " + row.value : "invalid") + ", ours " +
                     (result.valid ? "valid " + std::to_string(result.value) : result.violation->message()) + "\n";
  }
  INFO(disagreements);
  CHECK(agree == 164);
  CHECK(valid == 94);
}
