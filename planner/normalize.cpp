#include "planner/normalize.h"

#include <algorithm>
#include <limits>
#include <map>

#include "pddl_parser/type_hierarchy.h"
#include "pddl_parser/writer.h"
#include "planner/normalize_internal.h"

namespace alplan {
namespace {

using detail::FormulaConverter;
using detail::NameTables;
using detail::VariableScope;

void add_objects(const std::vector<pddl::TypedName>& declared, NormalizedTask& task, NameTables& names,
                 std::vector<pddl::TypeNames>& object_types) {
  for (const pddl::TypedName& o : declared) {
    auto [it, inserted] = names.objects.emplace(o.name, static_cast<ObjectId>(task.objects.size()));
    if (inserted) {
      task.objects.push_back(o.name);
      object_types.push_back(o.types);
      continue;
    }
    pddl::TypeNames& types = object_types[it->second];
    for (const std::string& t : o.types) {
      if (std::find(types.begin(), types.end(), t) == types.end()) types.push_back(t);
    }
  }
}

// Objects of a declared type list belong to the same types, so membership
// is decided once per distinct list (a home has a few dozen of those and
// hundreds of objects), not once per object and type.
void build_types(const pddl::Domain& domain, const std::vector<pddl::TypeNames>& object_types,
                 NormalizedTask& task, NameTables& names) {
  const pddl::TypeHierarchy hierarchy(domain);
  const std::vector<std::string>& types = hierarchy.types();
  for (const std::string& type : types) {
    names.types.emplace(type, static_cast<TypeId>(task.types.size()));
    TypeInfo info;
    info.name = type;
    task.types.push_back(std::move(info));
  }
  // An object belongs to its declared types, their ancestors and "object".
  auto membership = [&](const pddl::TypeNames& own) {
    std::vector<bool> member(types.size(), false);
    auto mark = [&](const std::string& type) {
      if (auto id = names.types.find(type); id != names.types.end()) member[id->second] = true;
    };
    mark("object");
    for (const std::string& x : own) {
      mark(x);
      if (const auto* ancestors = hierarchy.ancestors(x)) {
        for (const std::string& a : *ancestors) mark(a);
      }
    }
    std::vector<TypeId> ids;
    for (TypeId t = 0; t < member.size(); ++t) {
      if (member[t]) ids.push_back(t);
    }
    return ids;
  };
  std::map<pddl::TypeNames, std::vector<TypeId>> memberships;
  for (ObjectId o = 0; o < task.objects.size(); ++o) {
    const pddl::TypeNames& own = object_types[o];
    auto [it, inserted] = memberships.try_emplace(own);
    if (inserted) it->second = membership(own);
    for (TypeId t : it->second) task.types[t].objects.push_back(o);
  }
}

std::vector<Parameter> parameters_of(const std::vector<pddl::TypedName>& declared, FormulaConverter& convert,
                                     VariableScope& scope) {
  std::vector<Parameter> parameters;
  for (const pddl::TypedName& p : declared) {
    scope.bind(p.name);
    parameters.push_back({p.name, convert.type_of(p.types)});
  }
  return parameters;
}

void add_signatures(const pddl::Domain& domain, NormalizedTask& task, NameTables& names,
                    FormulaConverter& convert) {
  for (const pddl::PredicateDeclaration& p : domain.predicates) {
    names.predicates.emplace(p.name, static_cast<PredicateId>(task.predicates.size()));
    PredicateInfo info;
    info.name = p.name;
    for (const pddl::TypedName& param : p.parameters) info.parameter_types.push_back(convert.type_of(param.types));
    task.predicates.push_back(std::move(info));
  }
  for (const pddl::DerivedPredicate& d : domain.derived_predicates) {
    task.predicates.at(names.predicates.at(d.name)).derived = true;
  }
  for (const pddl::FunctionDeclaration& f : domain.functions) {
    names.functions.emplace(f.name, static_cast<FunctionId>(task.functions.size()));
    FunctionInfo info;
    info.name = f.name;
    for (const pddl::TypedName& param : f.parameters) info.parameter_types.push_back(convert.type_of(param.types));
    task.functions.push_back(std::move(info));
  }
}

ActionSchema convert_action(const pddl::Action& a, FormulaConverter& convert) {
  ActionSchema schema;
  schema.name = a.name;
  VariableScope scope;
  schema.parameters = parameters_of(a.parameters, convert, scope);
  if (a.precondition) schema.at_start = convert.condition(*a.precondition, scope);
  if (a.effect) convert.effects(*a.effect, false, scope, schema);
  schema.variable_slots = scope.slots_used();
  return schema;
}

// Whether constant duration constraints admit no duration but 0.
bool always_zero_duration(const std::vector<pddl::DurationConstraint>& constraints) {
  double lo = 0.0, hi = std::numeric_limits<double>::infinity();
  for (const pddl::DurationConstraint& d : constraints) {
    if (d.value.kind != pddl::NumericExpression::Kind::Number) return false;
    switch (d.comparison) {
      case pddl::Comparison::Equal: lo = std::max(lo, d.value.value); hi = std::min(hi, d.value.value); break;
      case pddl::Comparison::LessEqual: hi = std::min(hi, d.value.value); break;
      case pddl::Comparison::GreaterEqual: lo = std::max(lo, d.value.value); break;
      default: return false;
    }
  }
  return lo == 0.0 && hi == 0.0;
}

ActionSchema convert_durative(const pddl::DurativeAction& a, FormulaConverter& convert) {
  ActionSchema schema;
  schema.name = a.name;
  schema.durative = true;
  VariableScope scope;
  schema.parameters = parameters_of(a.parameters, convert, scope);
  for (const pddl::DurationConstraint& d : a.duration) {
    const Moment moment = d.time == pddl::TimeSpecifier::AtEnd ? Moment::End : Moment::Start;
    schema.duration.push_back({d.comparison, convert.expression(d.value, scope), moment});
  }
  if (a.condition) {
    schema.at_start = convert.timed_part(*a.condition, pddl::TimeSpecifier::AtStart, scope);
    schema.over_all = convert.timed_part(*a.condition, pddl::TimeSpecifier::OverAll, scope);
    schema.at_end = convert.timed_part(*a.condition, pddl::TimeSpecifier::AtEnd, scope);
  }
  if (a.effect) convert.effects(*a.effect, true, scope, schema);
  // A zero-duration action's invariant spans the empty interval between its
  // start and its end, which are one happening: VAL never checks it, so it
  // constrains nothing (and must not make the action unreachable).
  if (always_zero_duration(a.duration)) schema.over_all = LiftedCondition{};
  schema.variable_slots = scope.slots_used();
  return schema;
}

void mark_fluents(NormalizedTask& task, const std::vector<std::string>& exogenous) {
  for (const ActionSchema& schema : task.actions) {
    for (const PrimitiveEffect& e : schema.effects) {
      if (e.kind == PrimitiveEffect::Kind::Numeric || e.kind == PrimitiveEffect::Kind::Continuous) {
        task.functions[e.target.function].fluent = true;
      } else {
        task.predicates[e.atom.predicate].fluent = true;
      }
    }
  }
  for (const NormalizedTimedLiteral& til : task.timed_literals) task.predicates[til.atom.predicate].fluent = true;
  for (PredicateInfo& p : task.predicates) {
    const bool changed_outside = std::find(exogenous.begin(), exogenous.end(), p.name) != exogenous.end();
    p.fluent = p.fluent || p.derived || changed_outside;
  }
}

GroundAtom ground_atom(const pddl::Atom& a, const NameTables& names) {
  GroundAtom atom;
  atom.predicate = names.predicates.at(a.name);
  for (const pddl::Term& t : a.args) atom.args.push_back(names.objects.at(t.name));
  return atom;
}

void add_problem_state(const pddl::Problem& problem, NormalizedTask& task, const NameTables& names) {
  for (const pddl::Atom& fact : problem.init) task.initial_facts.push_back(ground_atom(fact, names));
  for (const pddl::NumericFact& f : problem.numeric_init) {
    NumericInitialValue value;
    value.function = names.functions.at(f.function.name);
    for (const pddl::Term& t : f.function.args) value.args.push_back(names.objects.at(t.name));
    value.value = f.value;
    task.initial_values.push_back(std::move(value));
  }
  for (const pddl::TimedInitialLiteral& til : problem.timed_literals) {
    task.timed_literals.push_back({til.time, til.positive, ground_atom(til.atom, names)});
  }
  std::stable_sort(task.timed_literals.begin(), task.timed_literals.end(),
                   [](const NormalizedTimedLiteral& a, const NormalizedTimedLiteral& b) { return a.time < b.time; });
}

bool declares(const std::vector<pddl::Requirement>& requirements, const char* flag) {
  return std::any_of(requirements.begin(), requirements.end(),
                     [&](const pddl::Requirement& r) { return r.name == flag; });
}

}  // namespace

NormalizedTask normalize(const pddl::Domain& domain, const pddl::Problem& problem, const NormalizeOptions& options) {
  NormalizedTask task;
  NameTables names;
  task.domain_name = domain.name;
  task.problem_name = problem.name;
  std::vector<pddl::TypeNames> object_types;
  add_objects(domain.constants, task, names, object_types);
  add_objects(problem.objects, task, names, object_types);
  build_types(domain, object_types, task, names);

  FormulaConverter in_domain(task, names, options.domain_file);
  FormulaConverter in_problem(task, names, options.problem_file);
  add_signatures(domain, task, names, in_domain);
  for (const pddl::Action& a : domain.actions) {
    task.actions.push_back(convert_action(a, in_domain));
    task.actions.back().preferences = in_domain.take_preferences();
    for (std::string& m : in_domain.take_unsupported()) task.actions.back().unsupported = std::move(m);
  }
  for (const pddl::DurativeAction& a : domain.durative_actions) {
    task.actions.push_back(convert_durative(a, in_domain));
    task.actions.back().preferences = in_domain.take_preferences();
    for (std::string& m : in_domain.take_unsupported()) task.actions.back().unsupported = std::move(m);
  }
  for (const pddl::DerivedPredicate& d : domain.derived_predicates) {
    DerivedRule rule;
    rule.head = names.predicates.at(d.name);
    VariableScope scope;
    rule.parameters = parameters_of(d.parameters, in_domain, scope);
    rule.body = in_domain.condition(d.body, scope);
    rule.variable_slots = scope.slots_used();
    task.derived_rules.push_back(std::move(rule));
  }
  add_problem_state(problem, task, names);
  mark_fluents(task, options.exogenous_predicates);

  if (problem.goal) {
    VariableScope scope;
    task.goal = in_problem.condition(*problem.goal, scope);
    task.goal_variable_slots = scope.slots_used();
    task.pddl3.goal_preferences = in_problem.take_preferences();
  }
  if (problem.metric) {
    task.metric = NormalizedMetric{problem.metric->minimize, in_problem.expression(problem.metric->expression, {})};
  }
  // PDDL 3 is data here; the planner refuses it where it starts (planner.cpp).
  if (domain.constraints) in_domain.constraints(*domain.constraints);
  if (problem.constraints) in_problem.constraints(*problem.constraints);
  for (std::string& m : in_domain.take_unsupported()) task.unsupported.push_back(std::move(m));
  for (std::string& m : in_problem.take_unsupported()) task.unsupported.push_back(std::move(m));
  task.declares_time = declares(domain.requirements, ":durative-actions") || declares(domain.requirements, ":time");
  task.temporal = task.declares_time || !domain.durative_actions.empty();
  return task;
}

std::optional<PredicateId> NormalizedTask::find_predicate(const std::string& name) const {
  for (PredicateId p = 0; p < predicates.size(); ++p) {
    if (predicates[p].name == name) return p;
  }
  return std::nullopt;
}

std::optional<ObjectId> NormalizedTask::find_object(const std::string& name) const {
  for (ObjectId o = 0; o < objects.size(); ++o) {
    if (objects[o] == name) return o;
  }
  return std::nullopt;
}

std::optional<std::uint32_t> NormalizedTask::find_action(const std::string& name) const {
  for (std::uint32_t a = 0; a < actions.size(); ++a) {
    if (actions[a].name == name) return a;
  }
  return std::nullopt;
}

std::string NormalizedTask::atom_name(const GroundAtom& atom) const {
  std::string s = "(" + predicates[atom.predicate].name;
  for (ObjectId o : atom.args) s += " " + objects[o];
  return s + ")";
}

}  // namespace alplan
