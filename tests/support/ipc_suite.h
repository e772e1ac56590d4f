// The IPC temporal benchmarks of ../shared/benchmarks/ipc as domain+problem
// pairs: one domain.pddl per folder, or domains/domain-N.pddl per problem.
#pragma once

#include <string>
#include <vector>

namespace alplan::test {

struct IpcPair {
  std::string domain;   // absolute paths
  std::string problem;
  std::string folder;   // e.g. ipc-2002/zenotravel-time-simple-automatic
  int number = 0;       // N of instance-N
};

std::vector<IpcPair> ipc_pairs();

}  // namespace alplan::test
