#include "benchmarks/differential/brute_force.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <set>
#include <vector>

#include "oracle/judge.h"
#include "oracle/world.h"

namespace alplan::differential {
namespace {

struct GroundStep {
  std::string action;
  std::vector<std::string> args;
  bool durative = false;
  std::vector<double> durations;  // fixed candidates
  double min_duration = 0.0, max_duration = 0.0;  // the range end-aligned durations must lie in
};

// Fixed candidates and the admissible range of a duration constraint whose
// every bound is a number; nullopt when a bound reads the state.
bool constant_durations(const std::vector<pddl::DurationConstraint>& constraints, GroundStep& step) {
  double lo = 0.0, hi = std::numeric_limits<double>::infinity();
  for (const pddl::DurationConstraint& c : constraints) {
    if (c.value.kind != pddl::NumericExpression::Kind::Number) return false;
    const double v = c.value.value;
    switch (c.comparison) {
      case pddl::Comparison::Equal: lo = std::max(lo, v); hi = std::min(hi, v); break;
      case pddl::Comparison::GreaterEqual:
      case pddl::Comparison::Greater: lo = std::max(lo, v); break;
      case pddl::Comparison::LessEqual:
      case pddl::Comparison::Less: hi = std::min(hi, v); break;
    }
  }
  if (lo > hi) {
    step.durations.clear();  // no duration at all: the step is never tried
    return true;
  }
  step.min_duration = lo;
  step.max_duration = hi;
  step.durations = {lo};
  if (std::isfinite(hi) && hi > lo) step.durations.push_back(hi);
  return true;
}

std::vector<GroundStep> ground_steps(oracle::World& world, const BruteForceOptions& options) {
  std::vector<GroundStep> steps;
  auto instantiate = [&](const std::string& name, const std::vector<pddl::TypedName>& parameters,
                         const GroundStep& pattern) {
    std::vector<std::vector<std::string>> domains;
    for (const pddl::TypedName& p : parameters) domains.push_back(world.objects_of(p.types));
    std::vector<std::size_t> index(domains.size(), 0);
    for (const auto& d : domains) {
      if (d.empty()) return;
    }
    while (true) {
      GroundStep s = pattern;
      s.action = name;
      for (std::size_t k = 0; k < domains.size(); ++k) s.args.push_back(domains[k][index[k]]);
      steps.push_back(std::move(s));
      std::size_t k = 0;
      while (k < domains.size() && ++index[k] == domains[k].size()) index[k++] = 0;
      if (k == domains.size()) return;
    }
  };
  for (const pddl::Action& a : world.domain().actions) instantiate(a.name, a.parameters, GroundStep{});
  for (const pddl::DurativeAction& a : world.domain().durative_actions) {
    GroundStep pattern;
    pattern.durative = true;
    if (!constant_durations(a.duration, pattern)) {
      pattern.min_duration = 0.0;
      pattern.max_duration = options.max_duration;
      for (double d = 0.0; d <= options.max_duration + 1e-9; d += options.quantum) pattern.durations.push_back(d);
    }
    instantiate(a.name, a.parameters, pattern);
  }
  return steps;
}

// Times within `offsets` epsilons of each anchor, rounded to 1e-9 so that
// sums of the same times compare equal.
std::vector<double> around(const std::vector<double>& anchors, int offsets, double epsilon) {
  std::set<double> out;
  for (double a : anchors) {
    for (int m = -offsets; m <= offsets; ++m) {
      const double t = std::round((a + m * epsilon) * 1e9) / 1e9;
      if (t >= 0.0) out.insert(t);
    }
  }
  return {out.begin(), out.end()};
}

class Enumeration {
 public:
  Enumeration(oracle::Judge& judge, std::vector<GroundStep> steps, std::vector<double> til_times,
              const BruteForceOptions& options)
      : judge_(judge), steps_(std::move(steps)), til_times_(std::move(til_times)), options_(options) {}

  // True when a valid plan extends `prefix`.
  bool extend(oracle::TimedPlan& prefix);
  BruteForceResult& result() { return result_; }

 private:
  bool try_plan(oracle::TimedPlan& plan);
  std::vector<double> anchors(const oracle::TimedPlan& prefix) const {
    std::vector<double> a{0.0};
    a.insert(a.end(), til_times_.begin(), til_times_.end());
    for (const oracle::TimedStep& s : prefix.steps) {
      a.push_back(s.time);
      if (s.duration) a.push_back(s.time + *s.duration);
    }
    return a;
  }

  oracle::Judge& judge_;
  std::vector<GroundStep> steps_;
  std::vector<double> til_times_;
  BruteForceOptions options_;
  BruteForceResult result_;
  std::vector<std::size_t> step_index_;  // the ground step of each step of the prefix
};

// A failure no step starting at or after the last start can mend: one at an
// earlier happening, or at the last start's own happening when it lies in
// the state before it (a condition, a duration) or in its members (a
// mutex; more members cannot undo one). An over-all condition failing after
// the last start's happening could be mended by a step joining it, and a
// failure at a later happening by a later step.
bool beyond_repair(const oracle::Verdict& v, double last_start, double epsilon) {
  using oracle::Failure;
  if (v.failure == Failure::Goal || v.failure == Failure::Constraint) return false;
  if (v.failure == Failure::BadPlan || v.failure == Failure::NotJudged) return true;
  const double window = epsilon / 10.0;
  if (v.time < last_start - window) return true;
  if (v.time > last_start + window) return false;
  return v.failure == Failure::Precondition || v.failure == Failure::Duration || v.failure == Failure::Mutex;
}

bool Enumeration::try_plan(oracle::TimedPlan& plan) {
  if (result_.judgements >= options_.max_judgements) {
    result_.cut_short = true;
    return false;
  }
  ++result_.judgements;
  const oracle::Verdict v = judge_.judge(plan);
  if (v.valid()) {
    result_.plan = plan;
    return true;
  }
  if (static_cast<int>(plan.steps.size()) >= options_.max_steps) return false;
  if (beyond_repair(v, plan.steps.back().time, options_.epsilon)) return false;
  return extend(plan);
}

bool Enumeration::extend(oracle::TimedPlan& prefix) {
  const double last_time = prefix.steps.empty() ? 0.0 : prefix.steps.back().time;
  const std::size_t last_step = step_index_.empty() ? 0 : step_index_.back();
  const std::vector<double> anchor_times = anchors(prefix);
  const std::vector<double> starts = around(anchor_times, options_.offsets, options_.epsilon);
  for (std::size_t g = 0; g < steps_.size(); ++g) {
    const GroundStep& step = steps_[g];
    std::vector<std::pair<double, double>> choices;  // (start, duration)
    for (double t : starts) {
      if (!step.durative) {
        choices.emplace_back(t, 0.0);
        continue;
      }
      for (double d : step.durations) choices.emplace_back(t, d);
      for (double end : starts) {
        const double d = std::round((end - t) * 1e9) / 1e9;
        if (d >= step.min_duration && d <= step.max_duration) choices.emplace_back(t, d);
      }
    }
    for (double end : starts) {
      if (!step.durative) break;
      for (double d : step.durations) choices.emplace_back(std::round((end - d) * 1e9) / 1e9, d);
    }
    std::sort(choices.begin(), choices.end());
    choices.erase(std::unique(choices.begin(), choices.end()), choices.end());
    for (const auto& [t, d] : choices) {
      // Steps in order of start time, simultaneous ones in order of ground step.
      if (t < 0.0 || t < last_time || (!prefix.steps.empty() && t == last_time && g < last_step)) continue;
      oracle::TimedStep s;
      s.time = t;
      s.action = step.action;
      s.args = step.args;
      if (step.durative) s.duration = d;
      prefix.steps.push_back(s);
      step_index_.push_back(g);
      const bool found = try_plan(prefix);
      prefix.steps.pop_back();
      step_index_.pop_back();
      if (found) return true;
      if (result_.cut_short) return false;
    }
  }
  return false;
}

}  // namespace

std::string describe_bound(const BruteForceOptions& o) {
  return "plans of up to " + std::to_string(o.max_steps) + " steps, each starting or ending within " +
         std::to_string(o.offsets) + " epsilon of 0, a timed literal or an earlier step's start or end";
}

BruteForceResult brute_force_plan(std::shared_ptr<const pddl::Domain> domain,
                                  std::shared_ptr<const pddl::Problem> problem, const BruteForceOptions& options) {
  try {
    oracle::JudgeOptions judge_options;
    judge_options.tolerance = options.epsilon;
    judge_options.exact = true;
    judge_options.symmetric_mutex = options.symmetric_mutex;
    if (options.epsilon_separated) judge_options.epsilon_separation = options.epsilon;
    oracle::Judge judge(domain, problem, judge_options);
    oracle::World world(domain, problem);
    std::vector<double> til_times;
    for (const pddl::TimedInitialLiteral& til : problem->timed_literals) til_times.push_back(til.time);
    Enumeration enumeration(judge, ground_steps(world, options), til_times, options);
    oracle::TimedPlan empty;
    ++enumeration.result().judgements;
    const oracle::Verdict v = judge.judge(empty);
    if (!v.judged()) {
      enumeration.result().error = v.reason;
      return enumeration.result();
    }
    if (v.valid()) {
      enumeration.result().plan = empty;
      return enumeration.result();
    }
    enumeration.extend(empty);
    return enumeration.result();
  } catch (const oracle::NotJudged& e) {
    BruteForceResult r;
    r.error = e.what();
    return r;
  }
}

}  // namespace alplan::differential
