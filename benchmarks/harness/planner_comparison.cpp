#include "benchmarks/harness/planner_comparison.h"

#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>

#include "benchmarks/harness/table.h"

namespace alplan::bench {

bool maximises(const std::string& problem_file) {
  std::ifstream in(problem_file);
  std::ostringstream text;
  for (std::string line; std::getline(in, line);) text << line.substr(0, line.find(';')) << "\n";
  static const std::regex kMaximise(R"(\(\s*:metric\s+maximize\b)", std::regex::icase);
  return std::regex_search(text.str(), kMaximise);
}

Baseline compared_planners(const std::string& baseline_folder, const std::vector<ExternalPlanner>& others,
                           const std::vector<ProblemRuns>& runs) {
  Baseline compared = baseline_folder.empty() ? Baseline::none() : Baseline::load(baseline_folder);
  for (const ExternalPlanner& planner : others) {
    compared.planners.push_back(planner.name);
    compared.titles.push_back(planner.name);
  }
  for (const ProblemRuns& run : runs) {
    const std::string key = problem_key(run.problem_file);
    if (!compared.maximize.count(key)) compared.maximize[key] = maximises(run.problem_file);
    for (const auto& [name, r] : run.external) {
      const ReferenceRun reference{r.status, r.status == "solved", r.seconds, r.value};
      compared.runs[key][name] = reference;
      if (!reference.valid) continue;
      const auto best = compared.best.find(key);
      if (best == compared.best.end() || compared.better(key, r.value, best->second)) compared.best[key] = r.value;
    }
  }
  return compared;
}

std::vector<std::string> comparison_warnings(const Baseline& reference, double time_limit, int jobs) {
  std::vector<std::string> warnings;
  if (reference.time_limit > 0 && std::abs(reference.time_limit - time_limit) > 1e-9) {
    warnings.push_back("our runs have a " + fixed(time_limit, 0) + " s limit, the baseline's " +
                       fixed(reference.time_limit, 0) + " s: coverage and time scores are not like for like");
  }
  if (jobs > 1) {
    warnings.push_back(std::to_string(jobs) + " runs at once: timings are not comparable with one run at a time");
  }
  return warnings;
}

}  // namespace alplan::bench
