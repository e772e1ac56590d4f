// Where tests find the shared benchmarks and the project's test data.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace alplan::test {

// ../shared beside the checkout (set at configure time).
std::string shared_dir();
std::string benchmarks_dir();  // shared_dir() + "/benchmarks"
std::string source_dir();
std::string data_dir();  // tests/data
std::string read_text(const std::string& path);
// Every regular file below `root` whose name ends in `suffix`, sorted.
std::vector<std::string> files_below(const std::string& root, const std::string& suffix);

// The benchmark set's own index (benchmarks_dir()/INDEX.csv), read without
// the harness, so that what a loader finds is checked against what the set
// says it holds; a domain added to the set moves both.
struct IndexedDomain {
  int domain_files = 0;
  int problems = 0;
};
std::map<std::string, IndexedDomain> benchmark_index();  // "ipc-2004/airport-..." -> counts

}  // namespace alplan::test
