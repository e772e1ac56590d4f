// The partial plan behind a search state (POPF, Coles et al. 2010): the
// snaps applied so far, in order, the ordering constraints between them and
// a simple temporal network that schedules each at its earliest time.
//
// Ordering rules: a snap that reads a fact or numeric variable comes at least
// epsilon after its last writer; a snap that writes one comes at least
// epsilon after its last writer and after every reader since. An end comes
// within [min, max] duration of its start; a timed initial literal sits at
// its time. So interfering snaps are never simultaneous (VAL's mutex rule)
// and any schedule the network allows gives the same final state.
//
// As in POPF, the end of every running action is in the network from the
// moment it starts (a pending node, with its duration bounds): a later step
// that interferes with that end is ordered before it at once, so a partial
// plan whose running action can no longer end in time is caught when it
// arises, not when the end is finally applied.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "planner/continuous_schedule.h"
#include "planner/search_state.h"
#include "planner/simple_temporal_network.h"
#include "planner/snap_action.h"
#include "planner/task_index.h"

namespace alplan {

constexpr double kInfiniteDuration = std::numeric_limits<double>::infinity();

struct StepRecord {
  Snap snap;
  std::uint32_t start_step = kNoId;  // End: the step of its start (kNoId: running before the plan)
  double min_duration = 0.0;         // Start and End: the duration window
  double max_duration = kInfiniteDuration;
  // What the snap does to and asks of continuously changing variables; null
  // in tasks without continuous change. Owned by the successor generator that
  // made the step, which lives as long as the search space (a raw pointer
  // keeps the record trivially copyable: partial plans copy their steps for
  // every child).
  const ContinuousStep* continuous = nullptr;
  // A step in the happening of this earlier step (the snap that opened a
  // happening a search state holds open: successor_generator.h): the same
  // time, and not interfering with it (kNoId: free).
  std::uint32_t simultaneous_with = kNoId;
  // None of the snap's conditional effects fired: its quiet footprint
  // (TaskIndex::footprint) orders it.
  bool quiet = false;
};

class PartialPlan {
 public:
  // `running` are actions already running when the plan begins; their
  // bounds count from the origin.
  // `values` are the numeric values the plan starts from (the task's initial
  // values when empty); only continuous change reads them.
  PartialPlan(const TaskIndex& index, double epsilon, double release = 0.0,
              const std::vector<RunningAction>& running = {}, const std::vector<double>& values = {});

  // Appends a step and its constraints; false (and no change) when the
  // network becomes inconsistent, e.g. a deadline can no longer be met.
  bool append(const StepRecord& step);
  // Appends a step known to fit (replaying a stored chain): with continuous
  // change the linear program is left unsolved until `settle()`.
  void replay(const StepRecord& step);
  void settle();

  std::size_t size() const { return steps_.size(); }
  const std::vector<StepRecord>& steps() const { return steps_; }
  double time_of(std::uint32_t step) const { return node_time(node_of_step_[step]); }
  // The times to print: the earliest schedule that keeps epsilon between
  // snaps that may share a happening wherever the constraints allow (VAL
  // accepts them together, but a plan that can keep them apart reads as
  // POPF's and OPTIC's do); with continuous change, time_of's.
  std::vector<double> preferred_times() const;
  // With continuous change: the conditions every plan from here must meet at
  // its end (the goal's on changing variables); false when they cannot.
  bool require_final(const std::vector<LinearCondition>& conditions);
  // With continuous change: sets the changing variables of `state` (the
  // state after the last step) to their values in the schedule found.
  void set_changing_values(SearchState& state) const;
  // With continuous change: the range of a changing variable after the last
  // step over every schedule the plan allows (its value when none changes).
  std::pair<double, double> changing_bounds(NumericVarId v, double value, bool least = true,
                                            bool greatest = true) const;
  // With continuous change: the time (in the current schedule) at which a
  // changing variable has the value the state holds for it (its last change);
  // 0 without continuous change.
  double changing_value_time(NumericVarId v) const;
  // With continuous change: see ContinuousSchedule::failing_at_end.
  std::vector<std::pair<ActionId, std::vector<NumericVarId>>> invariants_failing_at_end() const;
  // The earliest time the end of a running action can come (of its
  // earliest run, when it runs more than once).
  double pending_end_time(ActionId action) const;
  // For each of `running`, in its order: the latest time its end can come
  // with every other step at its earliest time, how much room the action has
  // left; infinite when nothing bounds it. One pass over the network's edges
  // for all of them: the search asks per child, the relaxation per
  // evaluation, and a pass per action grew with running actions x edges.
  std::vector<double> latest_end_times(const std::vector<RunningAction>& running) const;
  // The latest earliest time of a step taken (running actions' ends aside).
  double frontier() const;
  // The latest earliest time of a step that is not a timed literal, or of
  // the end of a running action.
  double makespan() const;
  // The earliest time a new snap may use the fact as it now stands: `gap`
  // after its last writer (the release when none wrote it).
  double available_from(FactId fact, double gap) const;
  double available_from(FactId fact) const { return available_from(fact, epsilon_); }
  double epsilon() const { return epsilon_; }

  // What the schedule allows of every step appended later. A later step is
  // ordered after the origin (the release), the last writer of each fact and
  // variable it touches, and (if it writes one) the readers since that write;
  // and before the pending ends it interferes with, and a timed literal at its
  // time, which binds it to the origin. So a new constraint can close a cycle
  // through the existing network only by entering it at a pending end (or at
  // the origin, while timed literals remain: the targets) and leaving it at a
  // source (the origin, a last writer, a reader since, a running action's
  // start or end). Two plans of one state compare by the longest path from
  // each target to each source (Dechter, Meiri & Pearl's minimal network,
  // restricted to those points): if one's are all no longer, any sequence of
  // steps that can be scheduled after the other can be scheduled after it.
  // With nothing running and no timed literal left there is no target: the
  // past constrains no future and all plans of the state are alike.
  struct Interface {
    // Per target (timed literals' origin first, then the runs in order of
    // action and start), the longest path to each source, by source id
    // (kind * 2^32 + key); a key without a writer stands at the origin.
    struct Target {
      std::vector<std::pair<std::uint64_t, double>> longest;  // sorted by id
      double to_origin = 0.0;
    };
    std::vector<Target> targets;
    // How each written key was last written, by writer source id (sorted).
    std::vector<std::pair<std::uint64_t, unsigned char>> writer_kinds;
    bool allows_all_of(const Interface& other) const;
  };
  Interface interface(bool timed_literals_remain) const;

 private:
  // How a snap wrote a key: one polarity, additively, or otherwise. Writers
  // of one kind may share a happening (snap_action.h).
  enum class WriteKind : unsigned char { Add, Delete, Additive, Other };
  struct Use {
    std::uint32_t key;   // fact or variable id
    std::uint32_t step;
    WriteKind kind = WriteKind::Other;  // writers: how; readers: Other for a read, Add for a hold
  };
  // What a snap does to the keys of one ledger: facts or variables.
  struct Touch {
    const std::vector<std::uint32_t>& reads;
    const std::vector<std::uint32_t>& holds;
    const std::vector<std::uint32_t>& writes;
    const std::vector<std::uint32_t>& adds;  // facts: added; variables: written additively
    const std::vector<std::uint32_t>& dels;  // facts: deleted; variables: none
    const std::vector<std::uint32_t>& reads_first;  // Footprint::reads_first
    WriteKind kind_of(std::uint32_t key) const;
  };
  static Touch fact_touch(const Footprint& fp);
  static Touch value_touch(const Footprint& fp);
  // The last writer of each key touched so far (sorted by key), and every
  // read and hold, in order.
  struct Ledger {
    std::vector<Use> writers;
    std::vector<Use> reads;
    std::optional<std::uint32_t> writer(std::uint32_t key) const;
    const Use* last_write(std::uint32_t key) const;
    // The reads of `key` since its last write.
    std::pair<std::vector<Use>::const_iterator, std::vector<Use>::const_iterator> reads_of(std::uint32_t key) const;
    // Edges of no gap (holders, writers of one kind) also go to `loose`:
    // the schedule keeps epsilon there where it can (preferred_times).
    void add_constraints(const Touch& touch, std::uint32_t node, double epsilon, std::vector<TemporalEdge>& edges,
                         std::vector<TemporalEdge>& loose, const std::vector<std::uint32_t>& node_of_step) const;
    void record(const Touch& touch, std::uint32_t step);
  };
  // The least gap between two snaps whose footprints touch a common key,
  // `earlier` first: epsilon where VAL would call them a mutex, 0 where they
  // may share a happening; nullopt when they touch nothing in common.
  std::optional<double> separation(const Footprint& earlier, const Footprint& later) const;
  // Whether a zero-duration action's start and end may share a happening.
  bool zero_duration_together(ActionId action) const;

  struct PendingEnd {
    ActionId action;
    std::uint32_t node;
    std::uint32_t start_node;  // 0 for an action running before the plan
    double max_duration;
  };
  // Orders `node` before every pending end it interferes with, but the
  // one at index `except` (the end being appended; pending_.size(): none).
  void order_before_pending(const Footprint& fp, std::uint32_t node, std::size_t except,
                            std::vector<TemporalEdge>& edges) const;

  double node_time(std::uint32_t node) const;
  bool is_timed_literal_node(std::uint32_t node) const;
  SnapNodes snap_nodes(const StepRecord& step, std::uint32_t node) const;

  const TaskIndex* index_;
  double epsilon_;
  double release_;  // no step before this time
  std::vector<StepRecord> steps_;
  std::vector<std::uint32_t> node_of_step_;
  std::vector<std::uint32_t> timed_literal_nodes_;  // few: the timed literals applied so far
  std::vector<PendingEnd> pending_;
  SimpleTemporalNetwork network_;
  std::vector<TemporalEdge> loose_;  // edges of no gap that could take epsilon
  Ledger facts_, values_;
  std::optional<ContinuousSchedule> continuous_;
  bool replaying_ = false;
};

}  // namespace alplan
