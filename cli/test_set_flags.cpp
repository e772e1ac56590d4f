#include "cli/test_set_flags.h"

#include <CLI/CLI.hpp>

namespace alplan::cli {

void add_test_set_flags(CLI::App* command, bench::TestSetRunOptions& options) {
  options.source_dir = bench::source_dir();
  options.build = bench::build_info();
  command->add_option("--reason", options.reason,
                      "The change a run on a test set (instances 6-10, held-out homes: seeds 1001-2000) measures; such a run without one is refused, "
                      "and it is recorded in the test-set ledger");
  command->add_option("--repeat", options.repeat,
                      "Why a test set is run again at a commit that has a run of it (both stay in the ledger)");
}

}  // namespace alplan::cli
