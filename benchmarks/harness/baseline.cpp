#include "benchmarks/harness/baseline.h"

#include <fstream>
#include <sstream>
#include <vector>

namespace alplan::bench {
namespace {

std::vector<std::string> cells_of(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream s(line);
  for (std::string cell; std::getline(s, cell, ',');) cells.push_back(cell);
  return cells;
}

double number_or(const std::string& text, double fallback) {
  try {
    return text.empty() ? fallback : std::stod(text);
  } catch (const std::exception&) {
    return fallback;
  }
}

}  // namespace

std::string problem_key(const std::string& path) {
  const std::size_t at = path.find("ipc/ipc-");
  return at == std::string::npos ? path : path.substr(at);
}

Baseline Baseline::load(const std::string& folder) {
  Baseline baseline;
  std::ifstream runs(folder + "/optic_popf_60s.csv");
  std::string line;
  std::getline(runs, line);  // planner,domain_file,problem_file,status,wall_s,max_rss_kb,makespan,n_actions,val_status,val_value
  while (std::getline(runs, line)) {
    const std::vector<std::string> c = cells_of(line);
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
    const std::vector<std::string> c = cells_of(line);
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
