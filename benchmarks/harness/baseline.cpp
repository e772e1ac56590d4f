#include "benchmarks/harness/baseline.h"

#include <filesystem>
#include <fstream>
#include <vector>

#include "benchmarks/harness/table.h"
#include "pddl_parser/parser.h"

namespace alplan::bench {
namespace {

double number_or(const std::string& text, double fallback) { return csv_number(text).value_or(fallback); }

}  // namespace

std::string problem_key(const std::string& path) {
  for (const char* prefix : {"pddl3/ipc-", "ipc/ipc-"}) {
    const std::size_t at = path.find(prefix);
    if (at != std::string::npos) return path.substr(at);
  }
  return path;
}

double quality_score(double ours, double best, bool maximize) {
  if (best == 0.0) return ours == 0.0 ? 1.0 : 0.0;
  if (maximize) return ours / best;
  return ours > 0.0 ? best / ours : 1.0;
}

namespace {

bool metric_maximized(const std::string& problem_file) {
  std::string text;
  std::vector<pddl::Diagnostic> diagnostics;
  if (!pddl::read_file(problem_file, text, diagnostics)) return false;
  const pddl::ProblemParseResult parsed = pddl::parse_problem(text, problem_file);
  return parsed.ast && parsed.ast->metric && !parsed.ast->metric->minimize;
}

// optic_60s.csv: domain,problem,first_valid,first_invalid,first_value,
// first_empty_plan,first_s,anytime_valid,anytime_invalid,anytime_value,anytime_s
// with the domain relative to the pddl3 folder, the folder's parent.
Baseline load_pddl3(const std::string& folder, std::ifstream& csv) {
  Baseline baseline;
  baseline.planners = {"optic-first", "optic-anytime", "optic-either"};
  baseline.titles = {"OPTIC first", "OPTIC anytime", "OPTIC either"};
  std::string line;
  std::getline(csv, line);
  while (std::getline(csv, line)) {
    const std::vector<std::string> c = csv_cells(line);
    if (c.size() < 11) continue;
    const std::string file = folder + "/../" + c[0] + "/instances/instance-" + c[1] + ".pddl";
    const std::string key = problem_key(std::filesystem::weakly_canonical(file).string());
    const bool maximize = metric_maximized(file);
    baseline.maximize[key] = maximize;
    auto run_of = [&](std::size_t valid, std::size_t value, std::size_t seconds) {
      ReferenceRun r;
      r.valid = c[valid] == "1";
      r.status = r.valid ? "solved" : c[valid + 1] == "1" ? "invalid" : "unsolved";
      r.value = number_or(c[value], 0.0);
      r.seconds = number_or(c[seconds], 0.0);
      return r;
    };
    const ReferenceRun first = run_of(2, 4, 6), anytime = run_of(7, 9, 10);
    ReferenceRun either = first.valid ? first : anytime;
    if (first.valid && anytime.valid && baseline.better(key, anytime.value, first.value)) either.value = anytime.value;
    baseline.runs[key] = {{"optic-first", first}, {"optic-anytime", anytime}, {"optic-either", either}};
    if (either.valid) baseline.best[key] = either.value;
  }
  return baseline;
}

}  // namespace

Baseline Baseline::none() {
  Baseline baseline;
  baseline.planners.clear();
  baseline.titles.clear();
  return baseline;
}

Baseline Baseline::load(const std::string& folder) {
  if (std::ifstream pddl3(folder + "/optic_60s.csv"); pddl3) {
    Baseline baseline = load_pddl3(folder, pddl3);
    baseline.time_limit = 60.0;
    return baseline;
  }
  Baseline baseline;
  std::ifstream runs(folder + "/optic_popf_60s.csv");
  if (runs) baseline.time_limit = 60.0;
  std::string line;
  std::getline(runs, line);  // planner,domain_file,problem_file,status,wall_s,max_rss_kb,makespan,n_actions,val_status,val_value
  while (std::getline(runs, line)) {
    const std::vector<std::string> c = csv_cells(line);
    if (c.size() < 10) continue;
    ReferenceRun r;
    r.status = c[3];
    r.seconds = number_or(c[4], 0.0);
    r.valid = c[3] == "solved" && c[8] == "valid";
    r.value = number_or(c[9], 0.0);
    baseline.runs[problem_key(c[2])][c[0]] = r;
  }
  std::ifstream quality(folder + "/quality_ref.csv");
  std::getline(quality, line);  // domain_file,problem_file,optic_first,optic_anytime_60s,popf,best
  while (std::getline(quality, line)) {
    const std::vector<std::string> c = csv_cells(line);
    if (c.size() < 6) continue;
    const std::string key = problem_key(c[1]);
    baseline.best[key] = number_or(c[5], 0.0);
    // For umts VAL's value is a step count; the reference records makespans.
    if (c[2].size() && baseline.runs[key].count("optic")) baseline.runs[key]["optic"].value = number_or(c[2], 0.0);
    if (c[4].size() && baseline.runs[key].count("popf")) baseline.runs[key]["popf"].value = number_or(c[4], 0.0);
  }
  return baseline;
}

}  // namespace alplan::bench
