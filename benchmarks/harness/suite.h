// A benchmark suite: domain+problem pairs from a folder laid out like
// ../shared/benchmarks/ipc (each domain folder has instances/instance-N.pddl
// and domain.pddl or domains/domain-N.pddl), or from a list file with one
// "DOMAIN PROBLEM" pair a line (paths relative to the list file's folder),
// or from a CSV with domain_file and problem_file columns whose paths are
// relative to the CSV folder's parent (shared/benchmarks/baseline/*.csv).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace alplan::bench {

struct SuiteProblem {
  std::string domain_file;
  std::string problem_file;
  std::string domain;    // the domain folder relative to the suite root, e.g. ipc-2002/zenotravel-...
  int number = 0;        // N of instance-N (0 in list files)
  std::uintmax_t bytes = 0;  // size of the problem file
};

// Sorted by domain, then problem number. Throws std::runtime_error when the
// path is neither a folder nor a readable list.
std::vector<SuiteProblem> load_suite(const std::string& folder_or_list);

// The first `count` problems of every domain (count 0: all).
std::vector<SuiteProblem> first_problems(const std::vector<SuiteProblem>& suite, int count);
// The problems at positions `from`..`to` (1-based, inclusive) of every
// domain, counted as first_problems counts them: instances 6-10 are a test
// set beside the first five. to 0: to the last.
std::vector<SuiteProblem> problems_in_range(const std::vector<SuiteProblem>& suite, int from, int to);
// The largest problem file of every domain.
std::vector<SuiteProblem> largest_problems(const std::vector<SuiteProblem>& suite);

}  // namespace alplan::bench
