// When facts are usable in the temporal relaxation. A fact true now, or
// given by a timed initial literal, may be usable only for a while: until a
// timed literal deletes it, or until a running action ends and deletes it
// (no later than the latest time that end can come). An action that achieves
// the fact again makes it usable for good from then on. This is how POPF's
// relaxed planning graph respects deadlines (Coles et al. 2010, Section 5).
//
// Beyond POPF: a fact that only durative actions give, each at its start,
// taking it back at its end (a kiln's `ready`, a lit match's `light`), is
// "windowed". Achieved again in the relaxation, it is usable not for good but
// for spans as long as the achiever lasts, from its earliest start on: an
// action holding the fact over all fits only if its duration fits inside
// such a span (required concurrency, temporal-machine-shop's bakes inside a
// firing long enough for them, benchmarks/README.md). The achiever may start
// at any time after its earliest, so any later span of that length counts.
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

  bool windowed(FactId fact) const { return windowed_[fact]; }
  // How long the fact an action gives at its start lasts when the action's
  // end takes it back: the action's longest duration (0 if not a provider).
  double provider_span(ActionId action) const { return provider_span_[action]; }
  // A windowed fact becomes usable, from `time` on, for spans of `length`.
  // True if no span known before was at least as long from as early.
  bool open_span(FactId fact, double time, double length, ActionId provider);
  // The provider of the earliest span at least `length` long (kNoId: none).
  ActionId span_provider(FactId fact, double length) const;

  // Recomputes the windows for a state and the partial plan behind it.
  // `running_ends`: facts running actions' ends delete close at the latest
  // time those ends can come with every other step at its earliest (a
  // guess: the steps may move later); without it only timed literals close
  // windows, which is a bound.
  // `gap`: how long after its achiever (a timed literal, the last writer) a
  // fact is usable.
  void reset(const SearchState& state, const PartialPlan& plan, bool running_ends, double gap);

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
  // The least delay after `from` at which a span holds [from, from + length]
  // (infinity when none is long enough).
  double span_delay(FactId fact, double from, double length) const;
  void find_windowed_facts();

  struct Span {
    double from = 0.0, length = 0.0;
    ActionId provider = kNoId;
  };

  const GroundTask& task_;
  std::vector<std::vector<std::uint32_t>> literals_of_;  // fact -> timed literals on it, in time order
  std::vector<char> restricted_;
  std::vector<std::vector<Window>> windows_;
  std::vector<FactId> touched_;
  std::vector<char> windowed_;
  std::vector<FactId> windowed_facts_;
  std::vector<double> provider_span_;  // by action
  std::vector<std::vector<Span>> spans_;  // by windowed fact; cleared by reset
};

}  // namespace alplan
