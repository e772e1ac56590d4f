#include "benchmarks/harness/build_info.h"

#include "alplan/build_stamp.h"

namespace alplan::bench {

BuildInfo build_info() { return {ALPLAN_BUILD_COMMIT, ALPLAN_BUILD_DIRTY}; }

std::string source_dir() { return ALPLAN_SOURCE_DIR; }

}  // namespace alplan::bench
