// The reference results in shared/benchmarks/baseline: OPTIC's and POPF's
// runs (optic_popf_60s.csv) and the best values they reached
// (quality_ref.csv), keyed by the problem file relative to
// shared/benchmarks ("ipc/ipc-2004/.../instance-1.pddl").
#pragma once

#include <map>
#include <optional>
#include <string>

namespace alplan::bench {

struct ReferenceRun {
  std::string status;   // solved, timeout, failed, memout_or_abort
  bool valid = false;   // solved and VAL accepted the plan
  double seconds = 0.0;
  double value = 0.0;   // VAL's value (makespan for umts, per the baseline README)
};

struct Baseline {
  std::map<std::string, std::map<std::string, ReferenceRun>> runs;  // problem -> planner -> run
  std::map<std::string, double> best;                                 // problem -> best reference value

  // Empty when the folder has no baseline files.
  static Baseline load(const std::string& baseline_folder);
};

// "ipc/ipc-YYYY/..." from any path that contains it, or the path itself.
std::string problem_key(const std::string& path);

}  // namespace alplan::bench
