#include "tests/support/test_paths.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace alplan::test {

std::string shared_dir() { return ALPLAN_SHARED_DIR; }
std::string benchmarks_dir() { return shared_dir() + "/benchmarks"; }
std::string source_dir() { return ALPLAN_SOURCE_DIR; }
std::string data_dir() { return source_dir() + "/tests/data"; }

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open " + path);
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

std::vector<std::string> files_below(const std::string& root, const std::string& suffix) {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
    const std::string path = entry.path().string();
    if (entry.is_regular_file() && path.size() >= suffix.size() &&
        path.compare(path.size() - suffix.size(), suffix.size(), suffix) == 0) {
      files.push_back(path);
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::map<std::string, IndexedDomain> benchmark_index() {
  std::ifstream in(benchmarks_dir() + "/INDEX.csv");
  std::map<std::string, IndexedDomain> index;
  std::string line;
  std::getline(in, line);  // year,domain,n_domain_files,n_problems,...
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::istringstream fields(line);
    for (std::string cell; cells.size() < 4 && std::getline(fields, cell, ',');) cells.push_back(cell);
    if (cells.size() < 4) continue;
    index[cells[0] + "/" + cells[1]] = {std::stoi(cells[2]), std::stoi(cells[3])};
  }
  return index;
}

}  // namespace alplan::test
