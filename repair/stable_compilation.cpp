#include "repair/stable_compilation.h"

#include <algorithm>
#include <stdexcept>

namespace alplan::repair {
namespace {

constexpr const char* kPrefix = "alplan-";
constexpr const char* kDistance = "alplan-distance";  // adapt's counter (DistanceCounter::Apart)
using Binding = std::map<std::string, std::string>;  // ?variable -> object

void bind_term(pddl::Term& t, const Binding& binding) {
  if (!t.is_variable()) return;
  if (const auto it = binding.find(t.name); it != binding.end()) {
    t.kind = pddl::Term::Kind::Name;
    t.name = it->second;
  }
}

void bind_atom(pddl::Atom& a, const Binding& binding) {
  for (pddl::Term& t : a.args) bind_term(t, binding);
}

void bind_expression(pddl::NumericExpression& e, const Binding& binding) {
  bind_atom(e.function, binding);
  for (pddl::NumericExpression& o : e.operands) bind_expression(o, binding);
}

// A quantifier's variables hide the parameters of the same name.
Binding hidden_by(const Binding& binding, const std::vector<pddl::TypedName>& variables) {
  Binding inner = binding;
  for (const pddl::TypedName& v : variables) inner.erase(v.name);
  return inner;
}

void bind_condition(pddl::Condition& c, const Binding& binding) {
  const Binding inner = c.variables.empty() ? binding : hidden_by(binding, c.variables);
  bind_atom(c.atom, inner);
  for (pddl::NumericExpression& e : c.expressions) bind_expression(e, inner);
  for (pddl::Condition& child : c.children) bind_condition(child, inner);
}

void bind_effect(pddl::Effect& e, const Binding& binding) {
  const Binding inner = e.variables.empty() ? binding : hidden_by(binding, e.variables);
  bind_atom(e.atom, inner);
  if (e.value) bind_expression(*e.value, inner);
  if (e.condition) bind_condition(*e.condition, inner);
  for (pddl::Effect& child : e.children) bind_effect(child, inner);
}

pddl::Atom atom(const std::string& name) {
  pddl::Atom a;
  a.name = name;
  return a;
}

pddl::Condition holds(const std::string& predicate) {
  pddl::Condition c;
  c.kind = pddl::Condition::Kind::Atom;
  c.atom = atom(predicate);
  return c;
}

pddl::Condition timed(pddl::TimeSpecifier time, pddl::Condition inner) {
  pddl::Condition c;
  c.kind = pddl::Condition::Kind::Timed;
  c.time = time;
  c.children.push_back(std::move(inner));
  return c;
}

pddl::Condition conjunction(std::vector<pddl::Condition> parts) {
  pddl::Condition c;
  c.kind = pddl::Condition::Kind::And;
  c.children = std::move(parts);
  return c;
}

pddl::Effect literal(const std::string& predicate, bool positive) {
  pddl::Effect e;
  e.kind = positive ? pddl::Effect::Kind::Add : pddl::Effect::Kind::Delete;
  e.atom = atom(predicate);
  return e;
}

pddl::Effect timed(pddl::TimeSpecifier time, pddl::Effect inner) {
  pddl::Effect e;
  e.kind = pddl::Effect::Kind::Timed;
  e.time = time;
  e.children.push_back(std::move(inner));
  return e;
}

pddl::Effect all_of(std::vector<pddl::Effect> parts) {
  pddl::Effect e;
  e.kind = pddl::Effect::Kind::And;
  e.children = std::move(parts);
  return e;
}

pddl::Effect cost_increase(double amount, const std::string& function = "total-cost") {
  pddl::Effect e;
  e.kind = pddl::Effect::Kind::Numeric;
  e.assign = pddl::AssignOperator::Increase;
  e.atom = atom(function);
  pddl::NumericExpression value;
  value.value = amount;
  e.value = value;
  return e;
}

// The effect without its changes to (total-cost): the compiled metric is
// the distance alone.
// An emptied conjunction stands in for a dropped effect, so that a timed or
// conditional effect keeps the child it must have.
void drop_cost_effects(pddl::Effect& e) {
  if (e.kind == pddl::Effect::Kind::Numeric && e.atom.name == "total-cost" && e.atom.args.empty()) {
    e = pddl::Effect{};
    return;
  }
  for (pddl::Effect& child : e.children) drop_cost_effects(child);
}

pddl::Domain without_costs(const pddl::Domain& domain) {
  pddl::Domain uncosted = domain;
  for (pddl::Action& a : uncosted.actions) {
    if (a.effect) drop_cost_effects(*a.effect);
  }
  for (pddl::DurativeAction& a : uncosted.durative_actions) {
    if (a.effect) drop_cost_effects(*a.effect);
  }
  return uncosted;
}

pddl::Effect with_effect(const std::optional<pddl::Effect>& effect, pddl::Effect extra) {
  std::vector<pddl::Effect> parts;
  if (effect) parts.push_back(*effect);
  parts.push_back(std::move(extra));
  return all_of(std::move(parts));
}

std::string pending(std::size_t i) { return std::string(kPrefix) + "pending-" + std::to_string(i); }
std::string done(std::size_t i) { return std::string(kPrefix) + "done-" + std::to_string(i); }

Binding binding_of(const std::vector<pddl::TypedName>& parameters, const OldStep& step) {
  if (parameters.size() != step.args.size()) {
    throw std::invalid_argument("the old plan's step " + ground_name(step) + " has " +
                                std::to_string(step.args.size()) + " objects; its schema takes " +
                                std::to_string(parameters.size()));
  }
  Binding binding;
  for (std::size_t p = 0; p < parameters.size(); ++p) binding[parameters[p].name] = step.args[p];
  return binding;
}

// `functions`: whether the compilation declares a function of its own
// (alplan-distance), so that the domain's functions may not clash either.
void check_names(const pddl::Domain& domain, bool functions) {
  auto ours = [](const std::string& name) { return name.rfind(kPrefix, 0) == 0; };
  bool clash = std::any_of(domain.predicates.begin(), domain.predicates.end(),
                           [&](const pddl::PredicateDeclaration& p) { return ours(p.name); });
  clash = clash || std::any_of(domain.actions.begin(), domain.actions.end(),
                               [&](const pddl::Action& a) { return ours(a.name); });
  clash = clash || std::any_of(domain.durative_actions.begin(), domain.durative_actions.end(),
                               [&](const pddl::DurativeAction& a) { return ours(a.name); });
  clash = clash || (functions && std::any_of(domain.functions.begin(), domain.functions.end(),
                                             [&](const pddl::FunctionDeclaration& f) { return ours(f.name); }));
  if (clash) throw std::invalid_argument(std::string("the domain already names something ") + kPrefix + "...");
}

// keep-i for an instantaneous schema (add_keep says whose costs it keeps).
pddl::Action keep_action(const pddl::Action& schema, const OldStep& step, std::size_t i) {
  pddl::Action keep = schema;
  keep.name = std::string(kPrefix) + "keep-" + std::to_string(i) + "-" + schema.name;
  keep.parameters.clear();
  const Binding binding = binding_of(schema.parameters, step);
  std::vector<pddl::Condition> needs{holds(pending(i))};
  if (keep.precondition) {
    bind_condition(*keep.precondition, binding);
    needs.push_back(std::move(*keep.precondition));
  }
  keep.precondition = conjunction(std::move(needs));
  if (keep.effect) bind_effect(*keep.effect, binding);
  keep.effect = with_effect(keep.effect, all_of({literal(pending(i), false), literal(done(i), true)}));
  return keep;
}

// keep-i for a durative schema: the bookkeeping on its snaps, so that the
// occurrence is pending until it starts and done once it ends.
pddl::DurativeAction keep_action(const pddl::DurativeAction& schema, const OldStep& step, std::size_t i) {
  pddl::DurativeAction keep = schema;
  keep.name = std::string(kPrefix) + "keep-" + std::to_string(i) + "-" + schema.name;
  keep.parameters.clear();
  const Binding binding = binding_of(schema.parameters, step);
  for (pddl::DurationConstraint& d : keep.duration) bind_expression(d.value, binding);
  std::vector<pddl::Condition> needs{timed(pddl::TimeSpecifier::AtStart, holds(pending(i)))};
  if (keep.condition) {
    bind_condition(*keep.condition, binding);
    needs.push_back(std::move(*keep.condition));
  }
  keep.condition = conjunction(std::move(needs));
  if (keep.effect) bind_effect(*keep.effect, binding);
  keep.effect = with_effect(keep.effect, all_of({timed(pddl::TimeSpecifier::AtStart, literal(pending(i), false)),
                                                 timed(pddl::TimeSpecifier::AtEnd, literal(done(i), true))}));
  return keep;
}

pddl::Action forgo_action(std::size_t i, const std::string& counter) {
  pddl::Action forgo;
  forgo.name = std::string(kPrefix) + "forgo-" + std::to_string(i);
  forgo.precondition = holds(pending(i));
  forgo.effect = all_of({literal(pending(i), false), literal(done(i), true), cost_increase(1.0, counter)});
  return forgo;
}

// Adds keep-i for the occurrence to `into`, from the schema of `source`
// (the domain with its costs dropped for stable, as it is for adapt);
// returns its name.
std::string add_keep(const pddl::Domain& source, const OldStep& step, std::size_t i, pddl::Domain& into) {
  for (const pddl::Action& a : source.actions) {
    if (a.name != step.schema) continue;
    into.actions.push_back(keep_action(a, step, i));
    return into.actions.back().name;
  }
  for (const pddl::DurativeAction& a : source.durative_actions) {
    if (a.name != step.schema) continue;
    into.durative_actions.push_back(keep_action(a, step, i));
    return into.durative_actions.back().name;
  }
  throw std::invalid_argument("the domain has no action " + step.schema + " for the old plan's step " +
                              ground_name(step));
}

// `domain` with every action increasing `function` by `amount` (at end
// when durative), its other effects as they are.
pddl::Domain each_action_increases(pddl::Domain domain, const std::string& function, double amount) {
  for (pddl::Action& a : domain.actions) a.effect = with_effect(a.effect, cost_increase(amount, function));
  for (pddl::DurativeAction& a : domain.durative_actions) {
    a.effect = with_effect(a.effect, timed(pddl::TimeSpecifier::AtEnd, cost_increase(amount, function)));
  }
  return domain;
}

// (= (function) 0) in a copy of `problem`, replacing any value it had.
pddl::Problem with_zero(const pddl::Problem& problem, const std::string& function) {
  pddl::Problem zero = problem;
  std::erase_if(zero.numeric_init, [&](const pddl::NumericFact& f) {
    return f.function.name == function && f.function.args.empty();
  });
  pddl::NumericFact value;
  value.function = atom(function);
  value.value = 0.0;
  zero.numeric_init.push_back(value);
  return zero;
}

// The domain adapt's compilation starts from: the domain's own, costs and
// all, with (alplan-distance) declared and every action adding 1 to it.
pddl::Domain with_distance_counter(const pddl::Domain& domain) {
  pddl::FunctionDeclaration f;
  f.name = kDistance;
  pddl::Domain counted = each_action_increases(domain, kDistance, 1.0);
  counted.functions.push_back(f);
  return counted;
}

}  // namespace

std::string ground_name(const OldStep& step) {
  std::string name = "(" + step.schema;
  for (const std::string& a : step.args) name += " " + a;
  return name + ")";
}

std::vector<OldStep> remaining_steps(const ExecutingPlan& plan, double now) {
  std::vector<OldStep> old;
  for (const ScheduledAction& s : plan.steps) {
    if (s.start + 1e-9 < now) continue;
    const GroundAction& a = plan.task->actions[s.action];
    OldStep step;
    step.schema = plan.task->lifted->actions[a.schema].name;
    for (ObjectId o : a.args) step.args.push_back(plan.task->lifted->objects[o]);
    old.push_back(std::move(step));
  }
  return old;
}


bool declares_total_cost(const pddl::Domain& domain) {
  return std::any_of(domain.functions.begin(), domain.functions.end(),
                     [](const pddl::FunctionDeclaration& f) { return f.name == "total-cost" && f.parameters.empty(); });
}

pddl::Domain with_action_cost(const pddl::Domain& domain, double cost) {
  pddl::Domain costed = each_action_increases(without_costs(domain), "total-cost", cost);
  if (!declares_total_cost(costed)) {
    pddl::FunctionDeclaration f;
    f.name = "total-cost";
    costed.functions.push_back(f);
  }
  return costed;
}

pddl::Problem with_zero_cost(const pddl::Problem& problem) { return with_zero(problem, "total-cost"); }

StableCompilation compile_stability(const pddl::Domain& domain, const pddl::Problem& problem,
                                    const std::vector<OldStep>& old, DistanceCounter counter) {
  const bool apart = counter == DistanceCounter::Apart;
  check_names(domain, apart);
  StableCompilation c;
  c.old = old;
  c.distance = apart ? kDistance : "total-cost";
  c.domain = apart ? with_distance_counter(domain) : with_action_cost(domain, 1.0);
  // The schemas keep-i copies: stable's without their costs (its metric is
  // the distance alone), adapt's with them (its metric counts them).
  const pddl::Domain source = apart ? domain : without_costs(domain);
  c.problem = with_zero(problem, c.distance);
  std::vector<pddl::Condition> goal;
  if (problem.goal) goal.push_back(*problem.goal);
  for (std::size_t i = 0; i < old.size(); ++i) {
    pddl::PredicateDeclaration p;
    p.name = pending(i);
    c.domain.predicates.push_back(p);
    p.name = done(i);
    c.domain.predicates.push_back(p);
    c.keeps[add_keep(source, old[i], i, c.domain)] = i;
    c.domain.actions.push_back(forgo_action(i, c.distance));
    c.forgoes[c.domain.actions.back().name] = i;
    c.problem.init.push_back(atom(pending(i)));
    goal.push_back(holds(done(i)));
  }
  c.problem.goal = conjunction(std::move(goal));
  if (apart) return c;  // the problem's own metric; adapt weighs the distance into it
  pddl::Metric metric;
  metric.minimize = true;
  metric.expression.kind = pddl::NumericExpression::Kind::Function;
  metric.expression.function = atom("total-cost");
  c.problem.metric = metric;
  return c;
}

MappedPlan map_back(const StableCompilation& compilation, const Plan& compiled) {
  MappedPlan mapped;
  for (const PlanStep& step : compiled.steps) {
    if (compilation.forgoes.count(step.action)) {
      ++mapped.forgone;
      continue;
    }
    PlanStep original = step;
    if (const auto keep = compilation.keeps.find(step.action); keep != compilation.keeps.end()) {
      const OldStep& o = compilation.old[keep->second];
      original.action = o.schema;
      original.args = o.args;
      ++mapped.kept;
    } else {
      ++mapped.added;
    }
    mapped.plan.steps.push_back(std::move(original));
  }
  return mapped;
}

}  // namespace alplan::repair
