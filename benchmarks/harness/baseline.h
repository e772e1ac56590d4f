// The reference results beside which `bench planners` reports ours, keyed by
// the problem file relative to shared/benchmarks
// ("ipc/ipc-2004/.../instance-1.pddl", "pddl3/ipc-2006/.../instance-1.pddl"):
// - shared/benchmarks/baseline: OPTIC's and POPF's runs
//   (optic_popf_60s.csv) and the best values they reached (quality_ref.csv);
// - shared/benchmarks/pddl3/baseline: OPTIC's first-plan and anytime runs on
//   the PDDL 3 domains (optic_60s.csv), each plan with VAL's verdict and
//   value, and OPTIC counted as solving a problem when either run gave a
//   plan VAL accepts (the better of the two, "optic-either").
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace alplan::bench {

struct ReferenceRun {
  std::string status;   // solved, timeout, failed, memout_or_abort
  bool valid = false;   // solved and VAL accepted the plan
  double seconds = 0.0;
  double value = 0.0;   // VAL's value (makespan for umts, per the baseline README)
};

struct Baseline {
  // The reference planners, in the order the summary shows them, and their titles.
  std::vector<std::string> planners{"optic", "popf"};
  std::vector<std::string> titles{"OPTIC", "POPF"};
  std::map<std::string, std::map<std::string, ReferenceRun>> runs;  // problem -> planner -> run
  std::map<std::string, double> best;                                 // problem -> best reference value
  // Problems whose metric is maximised (a larger value is better).
  std::map<std::string, bool> maximize;
  // The time limit of the reference runs in seconds (0: unknown): both
  // baselines in shared/benchmarks were run at 60 s (their READMEs).
  double time_limit = 0.0;

  bool maximized(const std::string& problem) const {
    const auto it = maximize.find(problem);
    return it != maximize.end() && it->second;
  }
  // Whether value a is better than b for this problem's metric.
  bool better(const std::string& problem, double a, double b) const { return maximized(problem) ? a > b : a < b; }

  // Empty when the folder has no baseline files.
  static Baseline load(const std::string& baseline_folder);
  // No reference planner at all (what `bench planners` compares with when
  // given no --baseline): no columns for planners that did not run.
  static Baseline none();
};

// "ipc/ipc-YYYY/..." or "pddl3/ipc-YYYY/..." from any path that contains
// it, or the path itself.
std::string problem_key(const std::string& path);

// The IPC quality score of a value against the best reference: best / ours
// for a minimised metric, ours / best for a maximised one; where the best
// is 0, a plan of value 0 scores 1 and any other 0.
double quality_score(double ours, double best, bool maximize);

}  // namespace alplan::bench
