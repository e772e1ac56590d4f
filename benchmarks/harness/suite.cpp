#include "benchmarks/harness/suite.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

namespace alplan::bench {
namespace fs = std::filesystem;
namespace {

int instance_number(const fs::path& problem) {
  const std::string stem = problem.stem().string();
  const std::size_t dash = stem.rfind('-');
  if (dash == std::string::npos) return 0;
  try {
    return std::stoi(stem.substr(dash + 1));
  } catch (const std::exception&) {
    return 0;
  }
}

std::vector<SuiteProblem> from_folder(const fs::path& root) {
  std::vector<SuiteProblem> suite;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    const fs::path& p = entry.path();
    if (!entry.is_regular_file() || p.extension() != ".pddl" || p.parent_path().filename() != "instances") continue;
    const fs::path folder = p.parent_path().parent_path();
    const int number = instance_number(p);
    fs::path domain = folder / "domain.pddl";
    if (!fs::exists(domain)) domain = folder / "domains" / ("domain-" + std::to_string(number) + ".pddl");
    if (!fs::exists(domain)) continue;
    std::string name = fs::relative(folder, root).string();
    if (name == ".") name = folder.filename().string();
    suite.push_back({domain.string(), p.string(), name, number, fs::file_size(p)});
  }
  return suite;
}

// A CSV with domain_file and problem_file columns (the baseline results in
// shared/benchmarks/baseline), paths relative to the CSV folder's parent.
std::vector<SuiteProblem> from_csv(const fs::path& csv) {
  std::ifstream in(csv);
  std::string header;
  std::getline(in, header);
  std::vector<std::string> names;
  std::stringstream hs(header);
  for (std::string cell; std::getline(hs, cell, ',');) names.push_back(cell);
  const auto column = [&](const std::string& name) {
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end()) throw std::runtime_error(csv.string() + " has no column " + name);
    return static_cast<std::size_t>(it - names.begin());
  };
  const std::size_t d = column("domain_file"), p = column("problem_file");
  const fs::path base = csv.parent_path().parent_path();
  std::vector<SuiteProblem> suite;
  std::set<std::pair<std::string, std::string>> seen;
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::stringstream ls(line);
    for (std::string cell; std::getline(ls, cell, ',');) cells.push_back(cell);
    if (cells.size() <= std::max(d, p) || !seen.insert({cells[d], cells[p]}).second) continue;
    const fs::path problem = base / cells[p];
    const fs::path folder = fs::path(cells[p]).parent_path().parent_path();
    std::string name = folder.string();
    if (name.rfind("ipc/", 0) == 0) name = name.substr(4);
    suite.push_back({(base / cells[d]).string(), problem.string(), name, instance_number(problem),
                     fs::exists(problem) ? fs::file_size(problem) : 0});
  }
  return suite;
}

std::vector<SuiteProblem> from_list(const fs::path& list) {
  if (list.extension() == ".csv") return from_csv(list);
  std::ifstream in(list);
  if (!in) throw std::runtime_error("cannot read the suite list " + list.string());
  std::vector<SuiteProblem> suite;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string domain, problem;
    if (!(words >> domain) || domain[0] == '#') continue;
    if (!(words >> problem)) throw std::runtime_error("a suite list line needs DOMAIN PROBLEM: " + line);
    fs::path d = list.parent_path() / domain, p = list.parent_path() / problem;
    if (fs::path(domain).is_absolute()) d = domain;
    if (fs::path(problem).is_absolute()) p = problem;
    suite.push_back({d.string(), p.string(), fs::path(domain).parent_path().string(), instance_number(p),
                     fs::exists(p) ? fs::file_size(p) : 0});
  }
  return suite;
}

}  // namespace

std::vector<SuiteProblem> load_suite(const std::string& folder_or_list) {
  const fs::path path(folder_or_list);
  std::vector<SuiteProblem> suite;
  if (fs::is_directory(path)) {
    suite = from_folder(path);
  } else if (fs::is_regular_file(path)) {
    suite = from_list(path);
  } else {
    throw std::runtime_error(folder_or_list + " is neither a suite folder nor a list file");
  }
  std::sort(suite.begin(), suite.end(), [](const SuiteProblem& a, const SuiteProblem& b) {
    return a.domain != b.domain ? a.domain < b.domain : a.number != b.number ? a.number < b.number
                                                                             : a.problem_file < b.problem_file;
  });
  return suite;
}

std::vector<SuiteProblem> first_problems(const std::vector<SuiteProblem>& suite, int count) {
  if (count <= 0) return suite;
  std::map<std::string, int> taken;
  std::vector<SuiteProblem> result;
  for (const SuiteProblem& p : suite) {
    if (taken[p.domain]++ < count) result.push_back(p);
  }
  return result;
}

std::vector<SuiteProblem> problems_in_range(const std::vector<SuiteProblem>& suite, int from, int to) {
  std::map<std::string, int> position;
  std::vector<SuiteProblem> result;
  for (const SuiteProblem& p : suite) {
    const int n = ++position[p.domain];
    if (n >= from && (to <= 0 || n <= to)) result.push_back(p);
  }
  return result;
}

std::vector<SuiteProblem> largest_problems(const std::vector<SuiteProblem>& suite) {
  std::map<std::string, SuiteProblem> largest;
  for (const SuiteProblem& p : suite) {
    auto [it, inserted] = largest.emplace(p.domain, p);
    if (!inserted && p.bytes > it->second.bytes) it->second = p;
  }
  std::vector<SuiteProblem> result;
  for (auto& [name, p] : largest) result.push_back(std::move(p));
  return result;
}

}  // namespace alplan::bench
