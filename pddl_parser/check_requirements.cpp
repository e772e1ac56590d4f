// Constructs a domain uses without declaring their :requirements flag:
// warnings, not errors, since VAL and the IPC files are lax here (umts
// omits :durative-actions, promela omits :derived-predicates, many omit
// :typing or :negative-preconditions). Each flag is warned about once, at
// its first use in the file.
#include <algorithm>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pddl_parser/check_context.h"

namespace alplan::pddl::detail {
namespace {

// The flags that imply others (PDDL 1.2's :adl and :quantified-preconditions,
// PDDL 2.1's :fluents, PDDL 2.2's :timed-initial-literals and
// :duration-inequalities, which imply durative actions).
const std::multimap<std::string_view, std::string_view>& implied_flags() {
  static const std::multimap<std::string_view, std::string_view> implied = {
      {":adl", ":strips"},
      {":adl", ":typing"},
      {":adl", ":negative-preconditions"},
      {":adl", ":disjunctive-preconditions"},
      {":adl", ":equality"},
      {":adl", ":existential-preconditions"},
      {":adl", ":universal-preconditions"},
      {":adl", ":quantified-preconditions"},
      {":adl", ":conditional-effects"},
      {":quantified-preconditions", ":existential-preconditions"},
      {":quantified-preconditions", ":universal-preconditions"},
      {":fluents", ":numeric-fluents"},
      {":fluents", ":object-fluents"},
      {":fluents", ":action-costs"},
      {":numeric-fluents", ":action-costs"},
      {":timed-initial-literals", ":durative-actions"},
      {":duration-inequalities", ":durative-actions"},
  };
  return implied;
}

// The first use of each flag, in the order found.
class FirstUses {
 public:
  void note(std::string_view flag, SourceLocation where, std::string what) {
    if (std::none_of(uses_.begin(), uses_.end(), [&](const Use& u) { return u.flag == flag; })) {
      uses_.push_back({std::string(flag), where, std::move(what)});
    }
  }
  void condition(const Condition& c);
  void effect(const Effect& e);

  struct Use {
    std::string flag;
    SourceLocation where;
    std::string what;
  };
  const std::vector<Use>& uses() const { return uses_; }

 private:
  std::vector<Use> uses_;
};

void FirstUses::condition(const Condition& c) {
  using K = Condition::Kind;
  switch (c.kind) {
    case K::Not:
      // (not (= ?a ?b)) is :equality's, which notes itself below.
      if (!c.children.empty() && c.children.front().kind == K::Atom) {
        note(":negative-preconditions", c.location,
             "a negative condition (not (" + c.children.front().atom.name + " ...))");
      }
      break;
    case K::Or: note(":disjunctive-preconditions", c.location, "a disjunction (or ...)"); break;
    case K::Imply: note(":disjunctive-preconditions", c.location, "an implication (imply ...)"); break;
    case K::Exists: note(":existential-preconditions", c.location, "an existential condition (exists ...)"); break;
    case K::Forall: note(":universal-preconditions", c.location, "a universal condition (forall ...)"); break;
    case K::Equality: note(":equality", c.location, "an equality (= ...)"); break;
    case K::Preference: note(":preferences", c.location, "a preference"); break;
    case K::Always:
    case K::Sometime:
    case K::Within:
    case K::AtMostOnce:
    case K::SometimeAfter:
    case K::SometimeBefore:
    case K::AlwaysWithin:
    case K::HoldDuring:
    case K::HoldAfter: note(":constraints", c.location, "a trajectory constraint"); break;
    default: break;
  }
  for (const Condition& child : c.children) condition(child);
}

void FirstUses::effect(const Effect& e) {
  using K = Effect::Kind;
  if (e.kind == K::When) note(":conditional-effects", e.location, "a conditional effect (when ...)");
  if (e.kind == K::Forall) note(":conditional-effects", e.location, "a universal effect (forall ...)");
  if (e.condition) condition(*e.condition);
  for (const Effect& child : e.children) effect(child);
}

// Numeric functions: (total-cost) alone is :action-costs', any other needs
// numeric fluents.
void note_functions(const Domain& domain, FirstUses& uses) {
  for (const FunctionDeclaration& f : domain.functions) {
    if (f.value_type != "number") continue;
    if (f.name == "total-cost" && f.parameters.empty()) {
      uses.note(":action-costs", f.location, "the function (total-cost)");
    } else {
      uses.note(":numeric-fluents", f.location, "the numeric function (" + f.name + ")");
    }
  }
}

FirstUses uses_of(const Domain& domain) {
  FirstUses uses;
  if (!domain.types.empty()) {
    uses.note(":typing", domain.types.front().location, "the type " + domain.types.front().name);
  }
  note_functions(domain, uses);
  for (const Action& a : domain.actions) {
    if (a.precondition) uses.condition(*a.precondition);
    if (a.effect) uses.effect(*a.effect);
  }
  for (const DurativeAction& a : domain.durative_actions) {
    uses.note(":durative-actions", a.location, "the durative action " + a.name);
    if (a.condition) uses.condition(*a.condition);
    if (a.effect) uses.effect(*a.effect);
  }
  for (const DerivedPredicate& d : domain.derived_predicates) {
    uses.note(":derived-predicates", d.location, "the derived predicate " + d.name);
    uses.condition(d.body);
  }
  if (domain.constraints) uses.condition(*domain.constraints);
  return uses;
}

}  // namespace

void warn_missing_requirements(const Domain& domain, DiagnosticSink& sink) {
  auto declared = [&](std::string_view flag) {
    for (const Requirement& r : domain.requirements) {
      if (r.name == flag) return true;
      const auto [first, last] = implied_flags().equal_range(r.name);
      if (std::any_of(first, last, [&](const auto& implied) { return implied.second == flag; })) return true;
    }
    return false;
  };
  const FirstUses uses = uses_of(domain);
  for (const FirstUses::Use& use : uses.uses()) {
    if (declared(use.flag)) continue;
    // The checker has long let :adl cover derived predicates (IPC 2004's
    // domains declare it so); kept, though PDDL 2.2 does not say so.
    if (use.flag == ":derived-predicates" && declared(":adl")) continue;
    // :adl's parts are commonly declared through :adl itself: name both.
    const auto [first, last] = implied_flags().equal_range(":adl");
    const bool adl_part = std::any_of(first, last, [&](const auto& implied) { return implied.second == use.flag; });
    sink.warning(use.where, use.what + " is used without the requirement " + use.flag +
                                (adl_part ? " (or :adl)" : "") + " in :requirements; read as if declared");
  }
}

}  // namespace alplan::pddl::detail
