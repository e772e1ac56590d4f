#include "pddl_parser/checker.h"

#include <algorithm>
#include <array>
#include <unordered_set>
#include <string_view>

#include "pddl_parser/check_context.h"
#include "pddl_parser/writer.h"

namespace alplan::pddl {
namespace {

using detail::Declarations;
using detail::FormulaChecker;
using detail::Place;

constexpr std::array<std::string_view, 33> kRequirements = {
    ":strips", ":typing", ":negative-preconditions", ":disjunctive-preconditions", ":equality",
    ":existential-preconditions", ":universal-preconditions", ":quantified-preconditions",
    ":conditional-effects", ":fluents", ":numeric-fluents", ":object-fluents", ":adl",
    ":durative-actions", ":duration-inequalities", ":continuous-effects", ":derived-predicates",
    ":timed-initial-literals", ":preferences", ":constraints", ":action-costs", ":domain-axioms",
    ":safety-constraints", ":action-expansions", ":foreach-expansions", ":dag-expansions",
    ":subgoals-through-axioms", ":expression-evaluation", ":open-world", ":true-negation", ":ucpop",
    ":time", ":timed-initial-fluents"};

std::string line_of(SourceLocation where) { return "line " + std::to_string(where.line); }

// Records first declarations by name and reports later ones as duplicates.
class DuplicateFinder {
 public:
  DuplicateFinder(DiagnosticSink& sink, std::string what) : sink_(sink), what_(std::move(what)) {}
  bool add(const std::string& name, SourceLocation where) {
    auto [it, inserted] = first_.emplace(name, where);
    if (!inserted) {
      sink_.error(where, what_ + " '" + name + "' is declared twice (first at " + line_of(it->second) + ")");
    }
    return inserted;
  }

 private:
  DiagnosticSink& sink_;
  std::string what_;
  std::unordered_map<std::string, SourceLocation> first_;
};

void check_parameters(const std::vector<TypedName>& parameters, const std::string& owner, DiagnosticSink& sink) {
  DuplicateFinder names(sink, "parameter of " + owner);
  for (const TypedName& p : parameters) names.add(p.name, p.location);
}

void check_requirements(const std::vector<Requirement>& requirements, DiagnosticSink& sink) {
  for (const Requirement& r : requirements) {
    if (!is_known_requirement(r.name)) {
      sink.error(r.location, "unknown requirement '" + r.name + "'" +
                                 detail::did_you_mean(r.name, {kRequirements.begin(), kRequirements.end()}));
    }
  }
}

// A type may be declared again with another parent: that is how several IPC
// domains (storage) write multiple inheritance, so it is not a duplicate.
void declare_types(const Domain& domain, const Declarations& decls, DiagnosticSink& sink) {
  for (const TypeDeclaration& t : domain.types) {
    if (t.name == "object" && !t.parents.empty()) {
      sink.error(t.location, "the root type 'object' cannot have a parent");
    }
  }
  for (const std::string& cyclic : decls.types.cyclic_types()) {
    auto it = std::find_if(domain.types.begin(), domain.types.end(),
                           [&](const TypeDeclaration& t) { return t.name == cyclic; });
    sink.error(it == domain.types.end() ? domain.location : it->location,
               "type '" + cyclic + "' is its own ancestor (cyclic type hierarchy)");
  }
}

void declare_object(const TypedName& o, Declarations& decls, DuplicateFinder& duplicates, DiagnosticSink& sink) {
  for (const std::string& type : o.types) {
    if (!decls.types.is_known(type)) {
      sink.error(o.location, "undefined type '" + type + "' of '" + o.name + "'" +
                                 detail::did_you_mean(type, decls.types.types()));
    }
  }
  // Declaring an object again with another type gives it both types, as
  // temporal-machine-shop does (kiln0 - kiln8, kiln0 - kiln20); only a
  // repetition with the same type is a duplicate.
  auto [it, inserted] = decls.objects.emplace(o.name, o.types);
  if (inserted) {
    duplicates.add(o.name, o.location);
    return;
  }
  TypeNames& types = it->second;
  const bool adds_type = std::any_of(o.types.begin(), o.types.end(), [&](const std::string& t) {
    return std::find(types.begin(), types.end(), t) == types.end();
  });
  if (!adds_type) {
    duplicates.add(o.name, o.location);
    return;
  }
  for (const std::string& t : o.types) {
    if (std::find(types.begin(), types.end(), t) == types.end()) types.push_back(t);
  }
}

void check_signature_types(const std::vector<TypedName>& parameters, const Declarations& decls,
                           DiagnosticSink& sink) {
  for (const TypedName& p : parameters) {
    for (const std::string& type : p.types) {
      if (!decls.types.is_known(type)) {
        sink.error(p.location, "undefined type '" + type + "' of " + p.name +
                                   detail::did_you_mean(type, decls.types.types()));
      }
    }
  }
}

void declare_symbols(const Domain& domain, Declarations& decls, DiagnosticSink& sink) {
  DuplicateFinder predicates(sink, "predicate");
  for (const PredicateDeclaration& p : domain.predicates) {
    check_parameters(p.parameters, "predicate " + p.name, sink);
    check_signature_types(p.parameters, decls, sink);
    if (predicates.add(p.name, p.location)) decls.predicates.emplace(p.name, &p);
  }
  DuplicateFinder functions(sink, "function");
  for (const FunctionDeclaration& f : domain.functions) {
    check_parameters(f.parameters, "function " + f.name, sink);
    check_signature_types(f.parameters, decls, sink);
    if (f.value_type != "number" && !decls.types.is_known(f.value_type)) {
      sink.error(f.location, "undefined value type '" + f.value_type + "' of function " + f.name);
    }
    if (functions.add(f.name, f.location)) decls.functions.emplace(f.name, &f);
  }
  // Several rules may derive one predicate: repeated names are not duplicates.
  for (const DerivedPredicate& d : domain.derived_predicates) decls.derived.insert(d.name);
}

Declarations declarations_of(const Domain& domain, DiagnosticSink& sink, bool report) {
  Declarations decls(domain);
  DiagnosticSink quiet(sink.file_name());
  DiagnosticSink& target = report ? sink : quiet;
  declare_types(domain, decls, target);
  DuplicateFinder constants(target, "constant");
  for (const TypedName& c : domain.constants) declare_object(c, decls, constants, target);
  declare_symbols(domain, decls, target);
  return decls;
}

void check_derived(const DerivedPredicate& d, const Declarations& decls, FormulaChecker& formulas,
                   DiagnosticSink& sink) {
  auto it = decls.predicates.find(d.name);
  if (it == decls.predicates.end()) {
    sink.error(d.location, "derived predicate '" + d.name + "' is not declared in :predicates");
  } else if (it->second->parameters.size() != d.parameters.size()) {
    sink.error(d.location, "wrong arity: derived predicate '" + d.name + "' is declared with " +
                               std::to_string(it->second->parameters.size()) + " parameters, its rule has " +
                               std::to_string(d.parameters.size()));
  }
  check_parameters(d.parameters, "derived predicate " + d.name, sink);
  formulas.set_scope(d.parameters, "derived predicate " + d.name);
  formulas.check_condition(d.body, Place::DerivedBody);
}

bool constrains_duration(const std::vector<DurationConstraint>& duration) { return !duration.empty(); }

void check_actions(const Domain& domain, FormulaChecker& formulas, DiagnosticSink& sink) {
  DuplicateFinder actions(sink, "action");
  for (const Action& a : domain.actions) {
    actions.add(a.name, a.location);
    check_parameters(a.parameters, "action " + a.name, sink);
    formulas.set_scope(a.parameters, "action " + a.name);
    if (a.precondition) formulas.check_condition(*a.precondition, Place::Precondition);
    if (a.effect) formulas.check_effect(*a.effect, Place::Effect);
  }
  for (const DurativeAction& a : domain.durative_actions) {
    actions.add(a.name, a.location);
    check_parameters(a.parameters, "durative action " + a.name, sink);
    formulas.set_scope(a.parameters, "durative action " + a.name);
    if (!constrains_duration(a.duration)) {
      sink.error(a.location, "durative action " + a.name +
                                 " has no ?duration constraint: add :duration (= ?duration VALUE)");
    }
    for (const DurationConstraint& d : a.duration) formulas.check_expression(d.value, Place::DurativeCondition);
    if (a.condition) formulas.check_condition(*a.condition, Place::DurativeCondition);
    if (a.effect) formulas.check_effect(*a.effect, Place::DurativeEffect);
  }
}

}  // namespace

bool is_known_requirement(const std::string& name) {
  return std::find(kRequirements.begin(), kRequirements.end(), name) != kRequirements.end();
}

std::vector<Diagnostic> check_domain(const Domain& domain, const std::string& file_name) {
  DiagnosticSink sink(file_name);
  check_requirements(domain.requirements, sink);
  detail::warn_missing_requirements(domain, sink);
  Declarations decls = declarations_of(domain, sink, true);
  FormulaChecker formulas(decls, sink);
  for (const DerivedPredicate& d : domain.derived_predicates) check_derived(d, decls, formulas, sink);
  check_actions(domain, formulas, sink);
  if (domain.constraints) {
    formulas.set_scope({}, "the domain's constraints");
    formulas.check_condition(*domain.constraints, Place::Constraint);
  }
  return sink.take();
}

namespace {

void check_init(const Problem& problem, const Declarations& decls, FormulaChecker& formulas,
                DiagnosticSink& sink) {
  for (const Atom& fact : problem.init) {
    formulas.check_ground_atom(fact, ":init");
    if (decls.derived.count(fact.name)) {
      sink.error(fact.location, "the initial fact " + write_atom(fact) + " sets the derived predicate '" +
                                    fact.name + "', which only its :derived rule may define");
    }
  }
  // IPC-2006 pathways gives some values twice, in 13 problems with different
  // numbers. VAL applies :init in order, so the later value stands; we say
  // so instead of refusing the problem.
  std::unordered_map<std::string, const NumericFact*> assigned;
  for (const NumericFact& f : problem.numeric_init) {
    formulas.check_ground_function(f.function);
    auto [it, inserted] = assigned.emplace(write_atom(f.function), &f);
    if (inserted) continue;
    const std::string where = " (first at " + line_of(it->second->location) + ")";
    if (it->second->value == f.value) {
      sink.warning(f.location, "the value of " + it->first + " is given twice" + where);
    } else {
      sink.warning(f.location, "the value of " + it->first + " is given twice with different values, " +
                                   format_number(it->second->value) + " and " + format_number(f.value) + where +
                                   "; the later value is used, as VAL does");
    }
    it->second = &f;
  }
  for (const TimedInitialLiteral& til : problem.timed_literals) {
    if (til.time < 0) sink.error(til.location, "timed initial literal at negative time " + format_number(til.time));
    if (til.numeric_value) {
      sink.error(til.location, "timed initial literal on the numeric function " + write_atom(til.atom) +
                                   ": PDDL 2.2 timed initial literals set or delete a fluent atom, not a number");
      continue;
    }
    if (decls.derived.count(til.atom.name)) {
      sink.error(til.location, "timed initial literal on the derived predicate '" + til.atom.name +
                                   "', which is not a fluent: only its :derived rule may define it");
      continue;
    }
    if (decls.functions.count(til.atom.name) && !decls.predicates.count(til.atom.name)) {
      sink.error(til.location, "timed initial literal on '" + til.atom.name +
                                   "', which is a numeric function, not a predicate");
      continue;
    }
    formulas.check_ground_atom(til.atom, "a timed initial literal");
  }
}

}  // namespace

std::vector<Diagnostic> check_problem(const Domain& domain, const Problem& problem, const std::string& file_name) {
  DiagnosticSink sink(file_name);
  if (problem.domain_name != domain.name) {
    sink.error(problem.domain_name_location, "the problem is for domain '" + problem.domain_name +
                                                 "', but the domain is '" + domain.name + "'");
  }
  check_requirements(problem.requirements, sink);
  Declarations decls = declarations_of(domain, sink, false);
  decls.in_problem = true;
  DuplicateFinder objects(sink, "object");
  std::unordered_set<std::string> constants;
  for (const TypedName& c : domain.constants) constants.insert(c.name);
  for (const TypedName& o : problem.objects) {
    if (constants.count(o.name)) {
      sink.warning(o.location, "object '" + o.name + "' repeats a constant of the domain");
      continue;
    }
    declare_object(o, decls, objects, sink);
  }
  FormulaChecker formulas(decls, sink);
  formulas.set_scope({}, "");
  check_init(problem, decls, formulas, sink);
  if (problem.goal) formulas.check_condition(*problem.goal, Place::Goal);
  if (problem.constraints) formulas.check_condition(*problem.constraints, Place::Constraint);
  if (problem.metric) formulas.check_expression(problem.metric->expression, Place::Metric);
  return sink.take();
}

}  // namespace alplan::pddl
