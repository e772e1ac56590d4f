// When facts are usable in the temporal relaxation. A fact true now, or
// given by a timed initial literal, may be usable only for a while: until a
// timed literal deletes it, or until a running action ends and deletes it
// (no later than the latest time that end can come). An action that achieves
// the fact again makes it usable for good from then on. This is how POPF's
// relaxed planning graph respects deadlines (Coles et al. 2010, Section 5).
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "planner/ground_task.h"
#include "planner/partial_plan.h"
#include "planner/search_state.h"

namespace alplan {

class FactWindows {
 public:
  explicit FactWindows(const GroundTask& task);

  // Recomputes the windows for a state and the partial plan behind it.
  void reset(const SearchState& state, const PartialPlan& plan);

  bool restricted(FactId fact) const { return restricted_[fact]; }
  // An action achieves the fact at `time`: usable from then on. True if this
  // opens the fact earlier than before.
  bool open_from(FactId fact, double time);

  struct Fit {
    bool ok = true;
    double start = 0.0;
    FactId blocking = kNoId;  // the fact no window fits, when !ok
  };
  // The earliest start at or after `start` at which every restricted fact
  // of `at_start` holds at the start, of `over_all` over [start, start +
  // duration], and of `at_end` at the end.
  Fit fit(double start, double duration, const std::vector<FactId>& at_start, const std::vector<FactId>& over_all,
          const std::vector<FactId>& at_end) const;

 private:
  using Window = std::pair<double, double>;  // [open, close)
  bool covers(FactId fact, double from, double to, double& moved) const;

  const GroundTask& task_;
  std::vector<std::vector<std::uint32_t>> literals_of_;  // fact -> timed literals on it, in time order
  std::vector<char> restricted_;
  std::vector<std::vector<Window>> windows_;
  std::vector<FactId> touched_;
};

}  // namespace alplan
