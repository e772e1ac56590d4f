// What this binary was built from: the commit of the source tree at build
// time and whether its tracked files differed from it
// (cmake/write_build_stamp.cmake, run at every build). A run on a test set
// records it, and is refused where it cannot name its code
// (test_set_ledger.h).
#pragma once

#include <string>

namespace alplan::bench {

struct BuildInfo {
  std::string commit;  // 40 hex digits, or "unknown" where git could not say
  bool dirty = true;   // tracked files differed from the commit
};

BuildInfo build_info();

// The source tree the binary was configured from (where the ledger lives).
std::string source_dir();

}  // namespace alplan::bench
