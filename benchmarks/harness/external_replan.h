// The paper's way of repairing: write the reformulated problem to disk and
// call a planner in another process (the paper called OPTIC; here our own
// `alplan plan`, so that the comparison isolates the cost of the process
// boundary). Used by `bench repair` to measure what planning in process
// saves. Times in the written problem start at 0 (shifted by `now`); the
// plan read back is shifted forward again.
#pragma once

#include <string>

#include "repair/repair_strategy.h"

namespace alplan::bench {

struct ExternalPlannerOptions {
  std::string alplan;     // the executable
  std::string work_dir;   // where the files go
  double epsilon = 0.001;
  double time_limit = 10.0;
};

class ExternalReplan : public repair::RepairStrategy {
 public:
  explicit ExternalReplan(ExternalPlannerOptions options) : options_(std::move(options)) {}
  std::string name() const override { return "replan-external"; }
  repair::RepairResult repair(const repair::RepairRequest& request) override;

 private:
  ExternalPlannerOptions options_;
  int calls_ = 0;
};

}  // namespace alplan::bench
