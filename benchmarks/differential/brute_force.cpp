#include "benchmarks/differential/brute_force.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <set>
#include <vector>

#include "pddl_parser/type_hierarchy.h"
#include "planner/normalize.h"
#include "planner/validator.h"

namespace alplan::differential {
namespace {

struct GroundStep {
  std::string action;
  std::vector<std::string> args;
  bool durative = false;
  std::vector<double> durations;  // candidates, for durative steps
};

struct NamedObject {
  std::string name;
  pddl::TypeNames types;
};

// Every object of a type expression (an either-list; empty: object).
std::vector<std::string> objects_of(const pddl::TypeNames& wanted, const std::vector<NamedObject>& objects,
                                    const pddl::TypeHierarchy& types) {
  std::vector<std::string> out;
  for (const NamedObject& o : objects) {
    const bool fits = o.types.empty() ? wanted.empty() || types.fits("object", wanted)
                                      : std::any_of(o.types.begin(), o.types.end(),
                                                    [&](const std::string& t) { return types.fits(t, wanted); });
    if (fits) out.push_back(o.name);
  }
  return out;
}

void tuples(const std::vector<std::vector<std::string>>& domains, std::vector<std::string>& current,
            std::vector<std::vector<std::string>>& out) {
  if (current.size() == domains.size()) {
    out.push_back(current);
    return;
  }
  for (const std::string& o : domains[current.size()]) {
    current.push_back(o);
    tuples(domains, current, out);
    current.pop_back();
  }
}

// Numbers a duration constraint names, when all of it is constant; empty
// when it reads something else.
std::optional<std::vector<double>> constant_durations(const std::vector<pddl::DurationConstraint>& constraints) {
  double lo = 0.0, hi = std::numeric_limits<double>::infinity();
  for (const pddl::DurationConstraint& c : constraints) {
    if (c.value.kind != pddl::NumericExpression::Kind::Number) return std::nullopt;
    const double v = c.value.value;
    switch (c.comparison) {
      case pddl::Comparison::Equal: lo = std::max(lo, v); hi = std::min(hi, v); break;
      case pddl::Comparison::GreaterEqual:
      case pddl::Comparison::Greater: lo = std::max(lo, v); break;
      case pddl::Comparison::LessEqual:
      case pddl::Comparison::Less: hi = std::min(hi, v); break;
    }
  }
  if (lo > hi || !std::isfinite(hi)) return std::nullopt;
  std::set<double> candidates{lo, hi};
  for (double d = std::ceil(lo); d < hi; d += 1.0) candidates.insert(d);
  return std::vector<double>(candidates.begin(), candidates.end());
}

std::vector<GroundStep> ground_steps(const pddl::Domain& domain, const pddl::Problem& problem,
                                     const BruteForceOptions& options) {
  const pddl::TypeHierarchy types(domain);
  std::vector<NamedObject> objects;
  for (const pddl::TypedName& c : domain.constants) objects.push_back({c.name, c.types});
  for (const pddl::TypedName& o : problem.objects) objects.push_back({o.name, o.types});
  std::vector<GroundStep> steps;
  auto instantiate = [&](const std::string& name, const std::vector<pddl::TypedName>& parameters, bool durative,
                         const std::vector<double>& durations) {
    std::vector<std::vector<std::string>> domains;
    for (const pddl::TypedName& p : parameters) domains.push_back(objects_of(p.types, objects, types));
    std::vector<std::vector<std::string>> all;
    std::vector<std::string> current;
    tuples(domains, current, all);
    for (std::vector<std::string>& args : all) steps.push_back({name, std::move(args), durative, durations});
  };
  for (const pddl::Action& a : domain.actions) instantiate(a.name, a.parameters, false, {});
  for (const pddl::DurativeAction& a : domain.durative_actions) {
    std::vector<double> durations;
    if (const auto constant = constant_durations(a.duration)) {
      durations = *constant;
    } else {
      for (int d = 0; d <= options.max_duration; ++d) durations.push_back(d);
    }
    instantiate(a.name, a.parameters, true, durations);
  }
  return steps;
}

class Enumeration {
 public:
  Enumeration(PlanValidator& validator, std::vector<GroundStep> steps, std::vector<double> times,
              const BruteForceOptions& options)
      : validator_(validator), steps_(std::move(steps)), times_(std::move(times)), options_(options) {}

  // Plans of exactly `length` steps extending `prefix`; true when one is valid.
  bool extend(Plan& prefix, std::size_t length, std::size_t first_time, std::size_t first_action) {
    for (std::size_t t = first_time; t < times_.size(); ++t) {
      for (std::size_t a = t == first_time ? first_action : 0; a < steps_.size(); ++a) {
        const GroundStep& g = steps_[a];
        const std::vector<double> instant{0.0};
        for (double d : g.durative ? g.durations : instant) {
          if (result_.validations >= options_.max_validations) {
            result_.cut_short = true;
            return false;
          }
          PlanStep step;
          step.time = times_[t];
          step.action = g.action;
          step.args = g.args;
          if (g.durative) step.duration = d;
          prefix.steps.push_back(step);
          const bool found = try_prefix(prefix, length, t, a);
          if (found) return true;
          prefix.steps.pop_back();
        }
      }
    }
    return false;
  }

  BruteForceResult& result() { return result_; }

 private:
  bool try_prefix(Plan& prefix, std::size_t length, std::size_t t, std::size_t a) {
    ++result_.validations;
    const ValidationResult v = validator_.validate(prefix);
    if (prefix.steps.size() == length) {
      if (v.valid) result_.plan = prefix;
      return v.valid;
    }
    if (v.violation && v.violation->kind != Violation::Kind::GoalNotReached &&
        v.violation->time <= times_[t] + options_.epsilon / 20.0) {
      return false;  // nothing starting at or after this step can repair it
    }
    // The next step starts no earlier; at the same time only a later action
    // (the order of simultaneous steps does not matter to the validator).
    return extend(prefix, length, t, a + 1);
  }

  PlanValidator& validator_;
  std::vector<GroundStep> steps_;
  std::vector<double> times_;
  BruteForceOptions options_;
  BruteForceResult result_;
};

}  // namespace

BruteForceResult brute_force_plan(const pddl::Domain& domain, const pddl::Problem& problem,
                                  const BruteForceOptions& options) {
  std::shared_ptr<const NormalizedTask> lifted;
  try {
    lifted = std::make_shared<const NormalizedTask>(normalize(domain, problem));
  } catch (const std::exception& e) {
    BruteForceResult r;
    r.error = e.what();
    return r;
  }
  // Exact comparisons: the planner promises plans that hold without VAL's
  // slack, and a plan that needs it is not one the planner missed.
  PlanValidator validator(lifted, {options.epsilon, false, 0.0});
  std::set<double> grid;
  std::vector<double> anchors;
  for (int n = 0; n <= options.horizon; ++n) anchors.push_back(n);
  for (const pddl::TimedInitialLiteral& til : problem.timed_literals) anchors.push_back(til.time);
  for (double anchor : anchors) {
    for (int m = 0; m <= options.offsets; ++m) grid.insert(anchor + m * options.epsilon);
  }
  Enumeration enumeration(validator, ground_steps(domain, problem, options),
                          std::vector<double>(grid.begin(), grid.end()), options);
  // The empty plan first: the goal may hold from the start.
  Plan plan;
  ++enumeration.result().validations;
  if (validator.validate(plan).valid) {
    enumeration.result().plan = plan;
    return enumeration.result();
  }
  for (int length = 1; length <= options.max_steps; ++length) {
    Plan prefix;
    if (enumeration.extend(prefix, static_cast<std::size_t>(length), 0, 0)) break;
    if (enumeration.result().cut_short) break;
  }
  return enumeration.result();
}

}  // namespace alplan::differential
