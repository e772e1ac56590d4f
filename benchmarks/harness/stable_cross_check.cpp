// The classical compilation of minimum-distance repair (stable_cross_check.h
// says what it is and why its minimum is `stable`'s). Written from the AST
// alone, apart from repair/stable_compilation.
#include "benchmarks/harness/stable_cross_check.h"

#include <algorithm>
#include <map>
#include <stdexcept>

#include "planner/ground_task.h"

namespace alplan::bench {
namespace {

using pddl::Condition;
using pddl::Effect;
using pddl::TimeSpecifier;
constexpr const char* kPrefix = "xcheck-";
using Substitution = std::map<std::string, std::string>;  // ?parameter -> object

std::string named(const std::string& what) { return std::string(kPrefix) + what; }

// ---- substitution of objects for parameters ----

void substitute(pddl::Atom& atom, const Substitution& s) {
  for (pddl::Term& t : atom.args) {
    const auto it = t.is_variable() ? s.find(t.name) : s.end();
    if (it == s.end()) continue;
    t.kind = pddl::Term::Kind::Name;
    t.name = it->second;
  }
}

void substitute(pddl::NumericExpression& e, const Substitution& s) {
  substitute(e.function, s);
  for (pddl::NumericExpression& o : e.operands) substitute(o, s);
}

// A quantifier's own variables are not the parameters they may shadow.
Substitution inside(const Substitution& s, const std::vector<pddl::TypedName>& bound) {
  Substitution inner = s;
  for (const pddl::TypedName& v : bound) inner.erase(v.name);
  return inner;
}

void substitute(Condition& c, const Substitution& s) {
  const Substitution inner = inside(s, c.variables);
  substitute(c.atom, inner);
  for (pddl::NumericExpression& e : c.expressions) substitute(e, inner);
  for (Condition& child : c.children) substitute(child, inner);
}

void substitute(Effect& e, const Substitution& s) {
  const Substitution inner = inside(s, e.variables);
  substitute(e.atom, inner);
  if (e.value) substitute(*e.value, inner);
  if (e.condition) substitute(*e.condition, inner);
  for (Effect& child : e.children) substitute(child, inner);
}

// ---- building blocks ----

pddl::Atom atom(const std::string& name, const std::vector<pddl::TypedName>& parameters = {}) {
  pddl::Atom a;
  a.name = name;
  for (const pddl::TypedName& p : parameters) {
    pddl::Term t;
    t.kind = pddl::Term::Kind::Variable;
    t.name = p.name;
    a.args.push_back(t);
  }
  return a;
}

Condition holds(pddl::Atom a) {
  Condition c;
  c.kind = Condition::Kind::Atom;
  c.atom = std::move(a);
  return c;
}

Condition all_true(std::vector<Condition> parts) {
  Condition c;  // And; with no parts, true
  c.children = std::move(parts);
  return c;
}

Effect literal(pddl::Atom a, bool add) {
  Effect e;
  e.kind = add ? Effect::Kind::Add : Effect::Kind::Delete;
  e.atom = std::move(a);
  return e;
}

Effect all_of(std::vector<Effect> parts) {
  Effect e;  // And; with no parts, nothing
  e.children = std::move(parts);
  return e;
}

Effect cost(double amount) {
  Effect e;
  e.kind = Effect::Kind::Numeric;
  e.assign = pddl::AssignOperator::Increase;
  e.atom = atom("total-cost");
  pddl::NumericExpression v;
  v.value = amount;
  e.value = v;
  return e;
}

// ---- what keeps the two minima apart (the header's list) ----

bool reads(const pddl::NumericExpression& e, pddl::NumericExpression::Kind kind) {
  if (e.kind == kind) return true;
  return std::any_of(e.operands.begin(), e.operands.end(), [&](const auto& o) { return reads(o, kind); });
}

// The first reason in a condition: a duration read, a preference.
std::string condition_limit(const Condition& c) {
  if (c.kind == Condition::Kind::Preference) return "a preference (PDDL 3)";
  for (const pddl::NumericExpression& e : c.expressions) {
    if (reads(e, pddl::NumericExpression::Kind::Duration)) return "a condition reads ?duration";
  }
  for (const Condition& child : c.children) {
    if (std::string why = condition_limit(child); !why.empty()) return why;
  }
  return "";
}

std::string effect_limit(const Effect& e, bool durative) {
  if (e.kind == Effect::Kind::Numeric) {
    if (e.value && reads(*e.value, pddl::NumericExpression::Kind::Duration)) return "an effect reads ?duration";
    if (e.value && reads(*e.value, pddl::NumericExpression::Kind::ContinuousTime)) return "continuous change";
    return "an effect changes the value of " + e.atom.name;
  }
  if (e.kind == Effect::Kind::When && durative) return "a conditional effect in a durative action";
  if (e.condition) {
    if (std::string why = condition_limit(*e.condition); !why.empty()) return why;
  }
  for (const Effect& child : e.children) {
    if (std::string why = effect_limit(child, durative); !why.empty()) return why;
  }
  return "";
}

std::string action_limit(const pddl::DurativeAction& a) {
  for (const pddl::DurationConstraint& d : a.duration) {
    if (reads(d.value, pddl::NumericExpression::Kind::Duration)) return a.name + ": its duration reads ?duration";
  }
  std::string why = a.condition ? condition_limit(*a.condition) : "";
  if (why.empty() && a.effect) why = effect_limit(*a.effect, true);
  return why.empty() ? "" : a.name + ": " + why;
}

std::string task_limit(const pddl::Domain& domain, const pddl::Problem& problem, bool own_timed_literals) {
  if (own_timed_literals) return "the problem has timed initial literals of its own (waiting may cost)";
  if (!domain.derived_predicates.empty()) return "derived predicates";
  if (domain.constraints || problem.constraints) return "PDDL 3 constraints";
  if (problem.goal) {
    if (std::string why = condition_limit(*problem.goal); !why.empty()) return "the goal: " + why;
  }
  for (const pddl::Action& a : domain.actions) {
    std::string why = a.precondition ? condition_limit(*a.precondition) : "";
    if (why.empty() && a.effect) why = effect_limit(*a.effect, false);
    if (!why.empty()) return a.name + ": " + why;
  }
  for (const pddl::DurativeAction& a : domain.durative_actions) {
    if (std::string why = action_limit(a); !why.empty()) return why;
  }
  return "";
}

// ---- the parts of a durative action at one time ----

// The part of a durative condition at `time`; nullopt when none. An
// untimed node below a quantifier or a disjunction keeps the quantifier or
// disjunction around its part.
std::optional<Condition> condition_at(const Condition& c, TimeSpecifier time) {
  if (c.kind == Condition::Kind::Timed) {
    if (c.time != time) return std::nullopt;
    return c.children.front();
  }
  if (c.kind == Condition::Kind::And || c.kind == Condition::Kind::Forall) {
    Condition part = c;
    part.children.clear();
    for (const Condition& child : c.children) {
      if (std::optional<Condition> p = condition_at(child, time)) part.children.push_back(std::move(*p));
    }
    if (part.children.empty()) return std::nullopt;
    return part;
  }
  // Anything else untimed (not PDDL 2.1, but tolerated): read at start.
  if (time == TimeSpecifier::AtStart) return c;
  return std::nullopt;
}

std::optional<Effect> effect_at(const Effect& e, TimeSpecifier time) {
  if (e.kind == Effect::Kind::Timed) {
    if (e.time != time) return std::nullopt;
    return e.children.front();
  }
  if (e.kind == Effect::Kind::And || e.kind == Effect::Kind::Forall) {
    Effect part = e;
    part.children.clear();
    for (const Effect& child : e.children) {
      if (std::optional<Effect> p = effect_at(child, time)) part.children.push_back(std::move(*p));
    }
    if (part.children.empty()) return std::nullopt;
    return part;
  }
  return std::nullopt;  // untimed literals and values: not PDDL 2.1; a When or numeric: not comparable
}

// What the grounder asks of a durative action's duration: that each value
// it is constrained by be defined (a function the problem gives no value
// makes the action not exist) and, where it bounds the duration from
// above, positive.
std::vector<Condition> durations_defined(const pddl::DurativeAction& a) {
  std::vector<Condition> needs;
  for (const pddl::DurationConstraint& d : a.duration) {
    if (!reads(d.value, pddl::NumericExpression::Kind::Function)) continue;
    Condition c;
    c.kind = Condition::Kind::Comparison;
    const bool above = d.comparison == pddl::Comparison::Equal || d.comparison == pddl::Comparison::LessEqual ||
                       d.comparison == pddl::Comparison::Less;
    c.comparison = above ? pddl::Comparison::Greater : pddl::Comparison::GreaterEqual;
    pddl::NumericExpression zero;
    c.expressions = {d.value, above ? zero : d.value};  // (>= v v): defined
    needs.push_back(std::move(c));
  }
  return needs;
}

// ---- the compiled actions ----

// The two halves of a compressed durative action; `start_needs` and
// `end_gives` carry a keep's bookkeeping, `mid` joins the halves.
struct Halves {
  pddl::Action start, end;
};

Halves compress(const pddl::DurativeAction& a, const std::string& name, const pddl::Atom& mid, double price,
                std::vector<Condition> start_needs, std::vector<Effect> start_gives, std::vector<Effect> end_gives) {
  Halves h;
  h.start.name = named("start-" + name);
  h.end.name = named("end-" + name);
  h.start.parameters = h.end.parameters = a.parameters;
  start_needs.push_back(holds(atom(named("free"))));
  if (a.condition) {
    if (std::optional<Condition> c = condition_at(*a.condition, TimeSpecifier::AtStart)) start_needs.push_back(*c);
  }
  for (Condition& c : durations_defined(a)) start_needs.push_back(std::move(c));
  h.start.precondition = all_true(std::move(start_needs));
  if (a.effect) {
    if (std::optional<Effect> e = effect_at(*a.effect, TimeSpecifier::AtStart)) start_gives.push_back(*e);
  }
  start_gives.push_back(literal(atom(named("free")), false));
  start_gives.push_back(literal(mid, true));
  if (price > 0) start_gives.push_back(cost(price));
  h.start.effect = all_of(std::move(start_gives));
  std::vector<Condition> end_needs{holds(mid)};
  for (TimeSpecifier t : {TimeSpecifier::OverAll, TimeSpecifier::AtEnd}) {
    if (!a.condition) break;
    if (std::optional<Condition> c = condition_at(*a.condition, t)) end_needs.push_back(*c);
  }
  h.end.precondition = all_true(std::move(end_needs));
  if (a.effect) {
    if (std::optional<Effect> e = effect_at(*a.effect, TimeSpecifier::AtEnd)) end_gives.push_back(*e);
  }
  end_gives.push_back(literal(mid, false));
  end_gives.push_back(literal(atom(named("free")), true));
  h.end.effect = all_of(std::move(end_gives));
  return h;
}

void add_predicate(pddl::Domain& d, const std::string& name, const std::vector<pddl::TypedName>& parameters = {}) {
  pddl::PredicateDeclaration p;
  p.name = name;
  p.parameters = parameters;
  d.predicates.push_back(std::move(p));
}

// An instantaneous action of the domain, or its keep copy: it also needs
// (xcheck-free), so it never comes between a durative action's halves.
pddl::Action instantaneous(const pddl::Action& a, std::vector<Condition> needs, std::vector<Effect> gives) {
  pddl::Action copy = a;
  needs.push_back(holds(atom(named("free"))));
  if (a.precondition) needs.push_back(*a.precondition);
  copy.precondition = all_true(std::move(needs));
  if (a.effect) gives.insert(gives.begin(), *a.effect);
  copy.effect = all_of(std::move(gives));
  return copy;
}

Substitution substitution(const std::vector<pddl::TypedName>& parameters, const CrossCheckStep& step) {
  if (parameters.size() != step.args.size()) {
    throw std::invalid_argument("old step " + step.schema + " has " + std::to_string(step.args.size()) +
                                " objects; its schema takes " + std::to_string(parameters.size()));
  }
  Substitution s;
  for (std::size_t p = 0; p < parameters.size(); ++p) s[parameters[p].name] = step.args[p];
  return s;
}

// keep-i: the occurrence's own action, parameter-free, at no cost; pending-i
// is taken when it starts, done-i given when it ends.
void add_keep(const pddl::Domain& domain, const CrossCheckStep& step, std::size_t i, pddl::Domain& out) {
  const std::string n = std::to_string(i);
  const pddl::Atom pending = atom(named("pending-" + n)), done = atom(named("done-" + n));
  for (const pddl::Action& a : domain.actions) {
    if (a.name != step.schema) continue;
    pddl::Action keep = a;
    keep.name = named("keep-" + n + "-" + a.name);
    keep.parameters.clear();
    const Substitution s = substitution(a.parameters, step);
    if (keep.precondition) substitute(*keep.precondition, s);
    if (keep.effect) substitute(*keep.effect, s);
    out.actions.push_back(
        instantaneous(keep, {holds(pending)}, {literal(pending, false), literal(done, true)}));
    return;
  }
  for (const pddl::DurativeAction& a : domain.durative_actions) {
    if (a.name != step.schema) continue;
    pddl::DurativeAction keep = a;
    keep.parameters.clear();
    const Substitution s = substitution(a.parameters, step);
    if (keep.condition) substitute(*keep.condition, s);
    if (keep.effect) substitute(*keep.effect, s);
    for (pddl::DurationConstraint& d : keep.duration) substitute(d.value, s);
    const pddl::Atom mid = atom(named("keep-mid-" + n));
    add_predicate(out, mid.name);
    Halves h = compress(keep, "keep-" + n + "-" + a.name, mid, 0.0, {holds(pending)}, {literal(pending, false)},
                        {literal(done, true)});
    out.actions.push_back(std::move(h.start));
    out.actions.push_back(std::move(h.end));
    return;
  }
  throw std::invalid_argument("the domain has no action " + step.schema + " for an old step");
}

pddl::Action forgo(std::size_t i) {
  const std::string n = std::to_string(i);
  pddl::Action a;
  a.name = named("forgo-" + n);
  a.precondition = all_true({holds(atom(named("free"))), holds(atom(named("pending-" + n)))});
  a.effect = all_of({literal(atom(named("pending-" + n)), false), literal(atom(named("done-" + n)), true), cost(1.0)});
  return a;
}

bool temporal_requirement(const pddl::Requirement& r) {
  return r.name == ":durative-actions" || r.name == ":duration-inequalities" ||
         r.name == ":timed-initial-literals" || r.name == ":continuous-effects";
}

// The domain's actions, each at cost 1 (a durative one as its two halves),
// without bookkeeping of the old plan.
pddl::Domain classical_domain(const pddl::Domain& domain) {
  pddl::Domain out = domain;
  std::erase_if(out.requirements, temporal_requirement);
  out.durative_actions.clear();
  out.actions.clear();
  const bool has_cost = std::any_of(domain.functions.begin(), domain.functions.end(),
                                    [](const auto& f) { return f.name == "total-cost"; });
  if (!has_cost) {
    pddl::FunctionDeclaration f;
    f.name = "total-cost";
    out.functions.push_back(f);
  }
  add_predicate(out, named("free"));
  for (const pddl::Action& a : domain.actions) out.actions.push_back(instantaneous(a, {}, {cost(1.0)}));
  for (const pddl::DurativeAction& a : domain.durative_actions) {
    const pddl::Atom mid = atom(named("mid-" + a.name), a.parameters);
    add_predicate(out, mid.name, a.parameters);
    Halves h = compress(a, a.name, mid, 1.0, {}, {}, {});
    out.actions.push_back(std::move(h.start));
    out.actions.push_back(std::move(h.end));
  }
  return out;
}

std::string key(const pddl::Atom& a) {
  std::string k = a.name;
  for (const pddl::Term& t : a.args) k += " " + t.name;
  return k;
}

// The initial state once every timed literal has happened, in time order
// (at one time the deletes first, as an action's effects): the running
// actions' committed ends, before the new plan begins.
std::vector<pddl::Atom> after_timed_literals(const pddl::Problem& problem) {
  std::map<std::string, pddl::Atom> state;
  for (const pddl::Atom& a : problem.init) state[key(a)] = a;
  std::vector<pddl::TimedInitialLiteral> tils = problem.timed_literals;
  std::stable_sort(tils.begin(), tils.end(), [](const auto& a, const auto& b) { return a.time < b.time; });
  for (std::size_t i = 0; i < tils.size();) {
    std::size_t j = i;
    while (j < tils.size() && tils[j].time == tils[i].time) ++j;
    for (std::size_t k = i; k < j; ++k) {
      if (!tils[k].positive) state.erase(key(tils[k].atom));
    }
    for (std::size_t k = i; k < j; ++k) {
      if (tils[k].positive) state[key(tils[k].atom)] = tils[k].atom;
    }
    i = j;
  }
  std::vector<pddl::Atom> init;
  for (auto& [k, a] : state) init.push_back(std::move(a));
  return init;
}

void check_names(const pddl::Domain& domain) {
  auto ours = [](const std::string& name) { return name.rfind(kPrefix, 0) == 0; };
  for (const auto& p : domain.predicates) {
    if (ours(p.name)) throw std::invalid_argument("the domain already names " + p.name);
  }
  for (const auto& a : domain.actions) {
    if (ours(a.name)) throw std::invalid_argument("the domain already names " + a.name);
  }
  for (const auto& a : domain.durative_actions) {
    if (ours(a.name)) throw std::invalid_argument("the domain already names " + a.name);
  }
}

}  // namespace

std::vector<CrossCheckStep> steps_from(const repair::ExecutingPlan& plan, double now) {
  std::vector<CrossCheckStep> steps;
  for (const repair::ScheduledAction& s : plan.steps) {
    if (s.start + 1e-9 < now) continue;
    const GroundAction& g = plan.task->actions[s.action];
    CrossCheckStep step{plan.task->lifted->actions[g.schema].name, {}};
    for (ObjectId o : g.args) step.args.push_back(plan.task->lifted->objects[o]);
    steps.push_back(std::move(step));
  }
  return steps;
}

ClassicalRepairTask compile_classical_repair(const pddl::Domain& domain, const pddl::Problem& reformulated,
                                             const std::vector<CrossCheckStep>& old, bool own_timed_literals) {
  check_names(domain);
  ClassicalRepairTask task;
  task.not_comparable = task_limit(domain, reformulated, own_timed_literals);
  task.domain = classical_domain(domain);
  task.problem = reformulated;
  std::erase_if(task.problem.requirements, temporal_requirement);
  task.problem.init = after_timed_literals(reformulated);
  task.problem.timed_literals.clear();
  task.problem.init.push_back(atom(named("free")));
  std::erase_if(task.problem.numeric_init, [](const auto& f) { return f.function.name == "total-cost"; });
  pddl::NumericFact zero;
  zero.function = atom("total-cost");
  task.problem.numeric_init.push_back(zero);
  std::vector<Condition> goal;
  if (reformulated.goal) goal.push_back(*reformulated.goal);
  for (std::size_t i = 0; i < old.size(); ++i) {
    const std::string n = std::to_string(i);
    add_predicate(task.domain, named("pending-" + n));
    add_predicate(task.domain, named("done-" + n));
    add_keep(domain, old[i], i, task.domain);
    task.domain.actions.push_back(forgo(i));
    task.problem.init.push_back(atom(named("pending-" + n)));
    goal.push_back(holds(atom(named("done-" + n))));
  }
  task.problem.goal = all_true(std::move(goal));
  pddl::Metric metric;
  metric.expression.kind = pddl::NumericExpression::Kind::Function;
  metric.expression.function = atom("total-cost");
  task.problem.metric = metric;
  return task;
}

const char* to_string(CrossCheckStatus status) {
  switch (status) {
    case CrossCheckStatus::Proven: return "proven";
    case CrossCheckStatus::NotProven: return "not proven";
    case CrossCheckStatus::NotComparable: return "not comparable";
  }
  return "?";
}


}  // namespace alplan::bench
