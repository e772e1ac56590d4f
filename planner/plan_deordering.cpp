#include "planner/plan_deordering.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "planner/derived_support.h"
#include "planner/simple_temporal_network.h"

namespace alplan {
namespace {

constexpr std::uint32_t kInitial = kNoId;  // an achiever: the starting state

// What one step of the plan needs and does, for the causal analysis.
struct StepFacts {
  std::vector<FactId> pre_pos, pre_neg;      // conditions at the step itself
  std::vector<FactId> inv_pos, inv_neg;      // a start's invariant, held until its end
  std::vector<FactId> add, del;              // unconditional effects
  std::vector<FactId> loose_read, loose_write;  // read or written in ways links do not explain
  std::vector<NumericVarId> num_read;
  std::vector<std::pair<NumericVarId, bool>> num_write;  // variable, additive
  std::uint32_t end = kNoId;                 // a start's end step
  bool timed_literal = false;
};

bool has(const std::vector<FactId>& v, FactId f) { return std::find(v.begin(), v.end(), f) != v.end(); }

void formula_reads(const GroundFormula& f, StepFacts& s) {
  if (f.kind == GroundFormula::Kind::Literal) s.loose_read.push_back(f.fact);
  if (f.kind == GroundFormula::Kind::Comparison) {
    append_variables(f.comparison.left, s.num_read);
    append_variables(f.comparison.right, s.num_read);
  }
  for (const GroundFormula& c : f.children) formula_reads(c, s);
}

class StepAnalysis {
 public:
  explicit StepAnalysis(const GroundTask& task) : task_(task), derived_(task) {}

  void conditions(const ConditionSet& c, std::vector<FactId>& pos, std::vector<FactId>& neg, StepFacts& s) {
    auto literal = [&](FactId f, std::vector<FactId>& into) {
      if (!task_.is_derived(f)) {
        into.push_back(f);
        return;
      }
      const DerivedSupport::Support& support = derived_.of(f);
      s.loose_read.insert(s.loose_read.end(), support.facts.begin(), support.facts.end());
      s.num_read.insert(s.num_read.end(), support.variables.begin(), support.variables.end());
    };
    for (FactId f : c.positive) literal(f, pos);
    for (FactId f : c.negative) literal(f, neg);
    s.loose_read.insert(s.loose_read.end(), c.mentioned.begin(), c.mentioned.end());
    for (const GroundComparison& cmp : c.numeric) {
      append_variables(cmp.left, s.num_read);
      append_variables(cmp.right, s.num_read);
    }
    for (const GroundFormula& f : c.complex) formula_reads(f, s);
  }

  void effects(const HappeningEffects& e, StepFacts& s) {
    s.add.insert(s.add.end(), e.add.begin(), e.add.end());
    s.del.insert(s.del.end(), e.del.begin(), e.del.end());
    auto numeric = [&](const std::vector<NumericAssignment>& assignments) {
      for (const NumericAssignment& n : assignments) {
        append_variables(n.value, s.num_read);
        const bool additive = n.assign == pddl::AssignOperator::Increase || n.assign == pddl::AssignOperator::Decrease;
        s.num_write.emplace_back(n.variable, additive);
      }
    };
    numeric(e.numeric);
    for (const ConditionalEffect& c : e.conditional) {
      std::vector<FactId> pos, neg;
      conditions(c.condition, pos, neg, s);
      s.loose_read.insert(s.loose_read.end(), pos.begin(), pos.end());
      s.loose_read.insert(s.loose_read.end(), neg.begin(), neg.end());
      s.loose_write.insert(s.loose_write.end(), c.add.begin(), c.add.end());
      s.loose_write.insert(s.loose_write.end(), c.del.begin(), c.del.end());
      numeric(c.numeric);
    }
  }

  StepFacts of(const StepRecord& step) {
    StepFacts s;
    if (step.snap.kind == SnapKind::TimedLiteral) {
      const GroundTimedLiteral& til = task_.timed_literals[step.snap.index];
      (til.positive ? s.add : s.del).push_back(til.fact);
      s.timed_literal = true;
      return s;
    }
    const GroundAction& a = task_.actions[step.snap.index];
    if (step.snap.kind == SnapKind::End) {
      conditions(a.at_end, s.pre_pos, s.pre_neg, s);
      effects(a.end, s);
      return s;
    }
    conditions(a.at_start, s.pre_pos, s.pre_neg, s);
    if (step.snap.kind == SnapKind::Start) {
      conditions(a.over_all, s.inv_pos, s.inv_neg, s);
      for (const GroundDurationConstraint& d : a.duration) append_variables(d.value, s.num_read);
    }
    effects(a.start, s);
    return s;
  }

 private:
  const GroundTask& task_;
  DerivedSupport derived_;
};

class Deordering {
 public:
  Deordering(const DeorderingInput& input, const Solution& solution)
      : input_(input), solution_(solution), n_(static_cast<std::uint32_t>(solution.steps.size())) {}

  std::optional<Solution> run() {
    StepAnalysis analysis(input_.index.task());
    for (const StepRecord& r : solution_.steps) steps_.push_back(analysis.of(r));
    for (std::uint32_t i = 0; i < n_; ++i) {
      const StepRecord& r = solution_.steps[i];
      if (r.snap.kind == SnapKind::End && r.start_step != kNoId) steps_[r.start_step].end = i;
    }
    if (!link_all() || !order_loose()) return std::nullopt;
    for (int round = 0; round < 32; ++round) {
      std::optional<std::vector<double>> times = schedule();
      if (!times) return std::nullopt;
      if (!separate_clashes(*times)) {
        Solution result = solution_;
        result.times = std::move(*times);
        result.makespan = 0.0;
        for (std::uint32_t i = 0; i < n_; ++i) {
          if (!steps_[i].timed_literal) result.makespan = std::max(result.makespan, result.times[i]);
        }
        return result;
      }
    }
    return std::nullopt;
  }

 private:
  void edge(std::uint32_t from, std::uint32_t to, double weight) { edges_.push_back({from + 1, to + 1, weight}); }

  bool adds(std::uint32_t k, FactId f, bool positive) const {
    return positive ? has(steps_[k].add, f) : has(steps_[k].del, f) && !has(steps_[k].add, f);
  }
  bool undoes(std::uint32_t k, FactId f, bool positive) const { return adds(k, f, !positive); }

  // The earliest achiever of `f` (true when `positive`) for step j: no step
  // between them undoes it. kInitial when the start state holds it and no
  // step before j undid it; nullopt when nothing explains it.
  std::optional<std::uint32_t> achiever(std::uint32_t j, FactId f, bool positive) const {
    std::optional<std::uint32_t> candidate;
    for (std::uint32_t k = j; k-- > 0;) {
      if (adds(k, f, positive)) {
        candidate = k;
      } else if (undoes(k, f, positive)) {
        return candidate;
      }
    }
    if (input_.start.fact(f) == positive) return kInitial;
    return candidate;
  }

  // A causal link from `from` to a consumer at step `to`, the fact held
  // until step `until`: steps that undo it stay outside, `after` past
  // `until`: epsilon past a condition's reader (one happening would be a
  // mutex); 0 past an invariant's end, since VAL checks an invariant on its
  // action's open interval (OPTIC schedules it so too).
  bool protect(std::uint32_t from, std::uint32_t until, FactId f, bool positive, double after) {
    for (std::uint32_t k = 0; k < n_; ++k) {
      if (k == from || k == until || !undoes(k, f, positive)) continue;
      if (from != kInitial && k < from) {
        edge(k, from, input_.epsilon);
      } else if (k > until) {
        edge(until, k, after);
      } else {
        return false;
      }
    }
    return true;
  }

  // `gap` is epsilon for a condition; an invariant, checked on the open
  // interval after its start, may be given at the start's very time.
  bool link(std::uint32_t j, FactId f, bool positive, std::uint32_t until, double gap) {
    const std::optional<std::uint32_t> a = achiever(j, f, positive);
    if (!a) return false;
    if (*a != kInitial && *a != j) edge(*a, j, gap);
    return protect(*a, until, f, positive, until == j ? input_.epsilon : 0.0);
  }

  bool link_all() {
    for (std::uint32_t j = 0; j < n_; ++j) {
      const StepFacts& s = steps_[j];
      for (FactId f : s.pre_pos) {
        if (!link(j, f, true, j, input_.epsilon)) return false;
      }
      for (FactId f : s.pre_neg) {
        if (!link(j, f, false, j, input_.epsilon)) return false;
      }
      if (s.end == kNoId) continue;
      // An invariant holds from its start (which may give it itself) to its
      // end; the start is no precondition of it in VAL's mutex rule, so
      // another step may give it at the start's very time.
      for (FactId f : s.inv_pos) {
        if (has(s.add, f)) {
          if (!protect(j, s.end, f, true, 0.0)) return false;
        } else if (!link(j, f, true, s.end, 0.0)) {
          return false;
        }
      }
      for (FactId f : s.inv_neg) {
        if (!link(j, f, false, s.end, 0.0)) return false;
      }
    }
    return true;
  }

  // Keys the links do not explain keep the plan's order between a reader
  // and a writer, and between writers unless both only add to a number.
  bool order_loose() {
    struct Touch {
      std::uint32_t step;
      bool write, additive, loose;
    };
    std::map<FactId, std::vector<Touch>> facts;
    std::map<NumericVarId, std::vector<Touch>> values;
    for (std::uint32_t k = 0; k < n_; ++k) {
      const StepFacts& s = steps_[k];
      for (FactId f : s.loose_read) facts[f].push_back({k, false, false, true});
      for (FactId f : s.loose_write) facts[f].push_back({k, true, false, true});
      for (NumericVarId v : s.num_read) values[v].push_back({k, false, false, true});
      for (const auto& [v, additive] : s.num_write) values[v].push_back({k, true, additive, true});
    }
    for (auto& [f, touches] : facts) {
      for (std::uint32_t k = 0; k < n_; ++k) {
        const StepFacts& s = steps_[k];
        if (has(s.pre_pos, f) || has(s.pre_neg, f) || has(s.inv_pos, f) || has(s.inv_neg, f)) {
          touches.push_back({k, false, false, false});
        }
        if (has(s.add, f) || has(s.del, f)) touches.push_back({k, true, false, false});
      }
    }
    auto order = [&](std::vector<Touch>& touches) {
      std::sort(touches.begin(), touches.end(), [](const Touch& a, const Touch& b) { return a.step < b.step; });
      for (std::size_t a = 0; a < touches.size(); ++a) {
        for (std::size_t b = a + 1; b < touches.size(); ++b) {
          const Touch& x = touches[a];
          const Touch& y = touches[b];
          if (x.step == y.step || (!x.loose && !y.loose) || (!x.write && !y.write)) continue;
          if (x.write && y.write && x.additive && y.additive) continue;
          edge(x.step, y.step, input_.epsilon);
        }
      }
    };
    for (auto& [f, touches] : facts) order(touches);
    for (auto& [v, touches] : values) order(touches);
    return true;
  }

  std::optional<std::vector<double>> schedule() const {
    std::vector<TemporalEdge> all = edges_;
    for (std::uint32_t i = 0; i < n_; ++i) {
      const StepRecord& r = solution_.steps[i];
      if (steps_[i].timed_literal) {
        const double at = input_.index.task().timed_literals[r.snap.index].time;
        all.push_back({0, i + 1, at});
        all.push_back({i + 1, 0, -at});
        continue;
      }
      all.push_back({0, i + 1, input_.release});
      if (r.snap.kind == SnapKind::End && r.start_step == kNoId) {
        all.push_back({0, i + 1, r.min_duration});
        if (r.max_duration < kInfiniteDuration) all.push_back({i + 1, 0, -r.max_duration});
      }
      if (steps_[i].end != kNoId) {
        const double d = solution_.times[steps_[i].end] - solution_.times[i];
        all.push_back({i + 1, steps_[i].end + 1, d});
        all.push_back({steps_[i].end + 1, i + 1, -d});
      }
    }
    SimpleTemporalNetwork network;
    if (!network.add_nodes(n_, all)) return std::nullopt;
    std::vector<double> times(n_);
    for (std::uint32_t i = 0; i < n_; ++i) times[i] = network.earliest(i + 1);
    return times;
  }

  // Whether two steps at one time interfere as VAL judges a happening's
  // members: one writes what the other reads, or adds what the other
  // deletes, or they write one number in ways that do not commute.
  bool interfere(const StepFacts& a, const StepFacts& b) const {
    auto reads = [](const StepFacts& s, FactId f) {
      return has(s.pre_pos, f) || has(s.pre_neg, f) || has(s.loose_read, f);
    };
    auto writes = [](const StepFacts& s) {
      std::vector<FactId> w = s.add;
      w.insert(w.end(), s.del.begin(), s.del.end());
      w.insert(w.end(), s.loose_write.begin(), s.loose_write.end());
      return w;
    };
    for (FactId f : writes(a)) {
      if (reads(b, f)) return true;
    }
    for (FactId f : writes(b)) {
      if (reads(a, f)) return true;
    }
    for (FactId f : a.add) {
      if (has(b.del, f) || has(b.loose_write, f)) return true;
    }
    for (FactId f : b.add) {
      if (has(a.del, f) || has(a.loose_write, f)) return true;
    }
    for (const auto& [v, additive] : a.num_write) {
      if (std::find(b.num_read.begin(), b.num_read.end(), v) != b.num_read.end()) return true;
      for (const auto& [w, other_additive] : b.num_write) {
        if (v == w && !(additive && other_additive)) return true;
      }
    }
    for (const auto& [v, additive] : b.num_write) {
      if (std::find(a.num_read.begin(), a.num_read.end(), v) != a.num_read.end()) return true;
    }
    return false;
  }

  // Orders clashing happenings at one time as the plan had them; true if
  // any was found (the schedule must be solved again).
  bool separate_clashes(const std::vector<double>& times) {
    const double close = input_.epsilon / 10.0;
    std::vector<std::uint32_t> order(n_);
    for (std::uint32_t i = 0; i < n_; ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return times[a] < times[b]; });
    bool found = false;
    for (std::size_t x = 0; x < order.size(); ++x) {
      for (std::size_t y = x + 1; y < order.size() && times[order[y]] - times[order[x]] <= close; ++y) {
        const std::uint32_t a = std::min(order[x], order[y]), b = std::max(order[x], order[y]);
        if (steps_[a].timed_literal && steps_[b].timed_literal) continue;
        if (interfere(steps_[a], steps_[b])) {
          edge(a, b, input_.epsilon);
          found = true;
        }
      }
    }
    return found;
  }

  const DeorderingInput& input_;
  const Solution& solution_;
  std::uint32_t n_;
  std::vector<StepFacts> steps_;
  std::vector<TemporalEdge> edges_;
};

}  // namespace

std::optional<Solution> deorder(const DeorderingInput& input, const Solution& solution) {
  if (input.index.continuous()) return std::nullopt;  // schedules there are the linear program's
  return Deordering(input, solution).run();
}

}  // namespace alplan
