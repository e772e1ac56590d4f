// A state of the temporal search: facts, numeric values, the actions that
// have started and not ended, and the next timed initial literal. Two states
// are the same (for duplicate detection) when all of these agree, whatever
// the schedules behind them.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "planner/ids.h"

namespace alplan {

// A running action's start step while the successor that started it is
// not yet in a plan (SearchSpace::schedule fills it in).
constexpr std::uint32_t kStepNotYetKnown = kNoId - 1;

struct RunningAction {
  ActionId action = 0;
  std::uint32_t start_step = kNoId;  // kNoId: running since before the plan began
  // Bounds on the end's time after the start (after the origin when the
  // action was running before the plan began).
  double min_duration = 0.0;
  double max_duration = 0.0;
};

class SearchState {
 public:
  SearchState() = default;
  SearchState(std::uint32_t facts, std::vector<double> values)
      : bits_((facts + 63) / 64, 0), values_(std::move(values)) {}

  bool fact(FactId f) const { return (bits_[f >> 6] >> (f & 63)) & 1u; }
  void set_fact(FactId f, bool on) {
    const std::uint64_t mask = std::uint64_t{1} << (f & 63);
    bits_[f >> 6] = on ? bits_[f >> 6] | mask : bits_[f >> 6] & ~mask;
  }
  double value(NumericVarId v) const { return values_[v]; }
  void set_value(NumericVarId v, double x) { values_[v] = x; }
  const std::vector<double>& values() const { return values_; }
  const std::vector<std::uint64_t>& bits() const { return bits_; }

  const std::vector<RunningAction>& running() const { return running_; }
  void start(const RunningAction& action);
  void finish(std::size_t index) { running_.erase(running_.begin() + static_cast<std::ptrdiff_t>(index)); }
  // Records which plan step started the instance of `action` just started
  // (the one whose step is kStepNotYetKnown).
  void set_start_step(ActionId action, std::uint32_t step);
  bool is_running(ActionId action) const;

  std::uint32_t next_timed_literal() const { return next_til_; }
  void set_next_timed_literal(std::uint32_t next) { next_til_ = next; }

  // An open happening (successor_generator.h): the plan step that opened
  // it, kStepNotYetKnown until the search schedules that step, kNoId when
  // none is open. Either a start whose over-all condition does not hold yet
  // opened it (starts and instantaneous actions may join and give it, as
  // VAL checks invariants after the whole happening), or an end that broke
  // the invariant of running actions (only their ends may join, VAL checks
  // no invariant at its action's end). `ends_open` says which.
  std::uint32_t open_happening() const { return open_from_; }
  bool ends_open() const { return ends_open_; }
  void open_happening(std::uint32_t step, bool by_end) {
    open_from_ = step;
    ends_open_ = by_end;
  }
  void close_happening() { open_happening(kNoId, false); }
  // The plan step that made this state, once scheduled: it names the open
  // happening this state's snap opened.
  void set_step(std::uint32_t step) {
    if (open_from_ == kStepNotYetKnown) open_from_ = step;
  }
  // Whether a running action started in the open happening (its invariant
  // is judged when the happening closes).
  bool joined_open_happening(const RunningAction& r) const {
    return open_from_ != kNoId && r.start_step != kNoId && r.start_step >= open_from_;
  }

  std::size_t hash() const;
  bool same_as(const SearchState& other) const;

 private:
  std::vector<std::uint64_t> bits_;
  std::vector<double> values_;
  // In order of action id; instances of one action (an action running twice
  // at once) in the order they started.
  std::vector<RunningAction> running_;
  std::uint32_t next_til_ = 0;
  std::uint32_t open_from_ = kNoId;
  bool ends_open_ = false;
};

struct SearchStateHash {
  std::size_t operator()(const SearchState* s) const { return s->hash(); }
};
struct SearchStateEqual {
  bool operator()(const SearchState* a, const SearchState* b) const { return a->same_as(*b); }
};

}  // namespace alplan
