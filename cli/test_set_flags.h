// The flags of a run that may touch a test set (`bench planners`, `bench
// stability`, `bench repair`, `bench home`): why it is run and why again (benchmarks/harness/
// test_set_ledger.h). The ledger is always the source tree's: a flag for
// another file would let a run skip it.
#pragma once

#include "benchmarks/harness/test_set_ledger.h"

namespace CLI {
class App;
}

namespace alplan::cli {

// Adds --reason and --repeat to `command`, filling `options`; the
// tree and the binary's commit are this build's (build_info.h).
void add_test_set_flags(CLI::App* command, bench::TestSetRunOptions& options);

}  // namespace alplan::cli
