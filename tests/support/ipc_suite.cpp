#include "tests/support/ipc_suite.h"

#include <algorithm>
#include <filesystem>

#include "tests/support/test_paths.h"

namespace alplan::test {

std::vector<IpcPair> ipc_pairs() {
  namespace fs = std::filesystem;
  const fs::path root = benchmarks_dir() + "/ipc";
  std::vector<IpcPair> pairs;
  for (const std::string& problem : files_below(root.string(), ".pddl")) {
    const fs::path p(problem);
    if (p.parent_path().filename() != "instances") continue;
    const fs::path folder = p.parent_path().parent_path();
    const std::string stem = p.stem().string();  // instance-N
    const int number = std::stoi(stem.substr(stem.find('-') + 1));
    fs::path domain = folder / "domain.pddl";
    if (!fs::exists(domain)) domain = folder / "domains" / ("domain-" + std::to_string(number) + ".pddl");
    pairs.push_back({domain.string(), problem, fs::relative(folder, root).string(), number});
  }
  std::sort(pairs.begin(), pairs.end(), [](const IpcPair& a, const IpcPair& b) {
    return a.folder != b.folder ? a.folder < b.folder : a.number < b.number;
  });
  return pairs;
}

}  // namespace alplan::test
