// PDDL 3 :constraints sections to LiftedConstraints: conjunctions and
// universal quantifiers are unfolded into the constraint list (each keeps the
// foralls enclosing it), preferences mark their constraints soft.
#include "pddl_parser/writer.h"
#include "planner/normalize_internal.h"

namespace alplan {

const char* to_string(ModalOperator op) {
  switch (op) {
    case ModalOperator::AtEnd: return "at end";
    case ModalOperator::Always: return "always";
    case ModalOperator::Sometime: return "sometime";
    case ModalOperator::Within: return "within";
    case ModalOperator::AtMostOnce: return "at-most-once";
    case ModalOperator::SometimeAfter: return "sometime-after";
    case ModalOperator::SometimeBefore: return "sometime-before";
    case ModalOperator::AlwaysWithin: return "always-within";
    case ModalOperator::HoldDuring: return "hold-during";
    case ModalOperator::HoldAfter: return "hold-after";
  }
  return "?";
}

namespace detail {

using CKind = pddl::Condition::Kind;

struct FormulaConverter::ConstraintContext {
  std::vector<QuantifiedVariable> forall;
  std::optional<std::uint32_t> preference;
  std::size_t separate = 0;
  // The preference's own monitor group, for constraints under a forall inside it.
  std::uint32_t group = 0;
  std::uint32_t* next_group = nullptr;
};

void FormulaConverter::constraints(const pddl::Condition& c) {
  VariableScope scope;
  std::uint32_t next_group = 0;
  for (const LiftedConstraint& existing : task_.pddl3.constraints) {
    next_group = std::max(next_group, existing.monitor_group + 1);
  }
  ConstraintContext context;
  context.next_group = &next_group;
  constraint(c, scope, context);
}

void FormulaConverter::constraint(const pddl::Condition& c, VariableScope& scope, ConstraintContext& context) {
  switch (c.kind) {
    case CKind::And:
      for (const pddl::Condition& child : c.children) constraint(child, scope, context);
      return;
    case CKind::Forall: {
      std::vector<QuantifiedVariable> variables = bind_all(c.variables, scope);
      context.forall.insert(context.forall.end(), variables.begin(), variables.end());
      constraint(c.children.front(), scope, context);
      context.forall.resize(context.forall.size() - variables.size());
      scope.unbind(c.variables.size());
      return;
    }
    case CKind::Preference: {
      const std::string name = c.preference_name.empty() ? "anonymous" : c.preference_name;
      pddl3_use(c.location, "PDDL 3 preference " + name);
      if (context.preference) {
        unsupported(c.location, "a PDDL 3 preference inside a preference");
        return;
      }
      ConstraintContext inner = context;
      inner.preference = preference_id(name);
      inner.separate = context.forall.size();
      inner.group = (*context.next_group)++;
      constraint(c.children.front(), scope, inner);
      return;
    }
    case CKind::Timed:
      if (c.time == pddl::TimeSpecifier::AtEnd) return add_constraint(c, scope, context);
      break;
    case CKind::Always:
    case CKind::Sometime:
    case CKind::Within:
    case CKind::AtMostOnce:
    case CKind::SometimeAfter:
    case CKind::SometimeBefore:
    case CKind::AlwaysWithin:
    case CKind::HoldDuring:
    case CKind::HoldAfter: return add_constraint(c, scope, context);
    default: break;
  }
  unsupported(c.location, "a goal in :constraints that is not a modal operator (at end, always, sometime, ...)");
}

void FormulaConverter::add_constraint(const pddl::Condition& c, VariableScope& scope,
                                      const ConstraintContext& context) {
  LiftedConstraint k;
  k.forall = context.forall;
  k.preference = context.preference;
  k.separate = context.preference ? context.separate : context.forall.size();
  // Constraints under a forall inside the preference share its monitor;
  // any other constraint has one of its own (VAL's CollectProps).
  const bool shared = context.preference && context.forall.size() > context.separate;
  k.monitor_group = shared ? context.group : (*context.next_group)++;
  k.text = pddl::write_condition(c);
  k.where = where(c.location);
  auto one = [&](std::size_t i) { return condition(c.children.at(i), scope); };
  switch (c.kind) {
    case CKind::Timed: k.op = ModalOperator::AtEnd; k.requirement = one(0); break;
    case CKind::Always: k.op = ModalOperator::Always; k.requirement = one(0); break;
    case CKind::Sometime: k.op = ModalOperator::Sometime; k.requirement = one(0); break;
    case CKind::AtMostOnce: k.op = ModalOperator::AtMostOnce; k.requirement = one(0); break;
    case CKind::Within:
      k.op = ModalOperator::Within;
      k.deadline = c.numbers.at(0);
      k.requirement = one(0);
      break;
    case CKind::SometimeAfter:
    case CKind::SometimeBefore:
      k.op = c.kind == CKind::SometimeAfter ? ModalOperator::SometimeAfter : ModalOperator::SometimeBefore;
      k.trigger = one(0);
      k.requirement = one(1);
      break;
    case CKind::AlwaysWithin:
      k.op = ModalOperator::AlwaysWithin;
      k.deadline = c.numbers.at(0);
      k.trigger = one(0);
      k.requirement = one(1);
      break;
    case CKind::HoldDuring:
      k.op = ModalOperator::HoldDuring;
      k.from = c.numbers.at(0);
      k.deadline = c.numbers.at(1);
      k.requirement = one(0);
      break;
    case CKind::HoldAfter:
      k.op = ModalOperator::HoldAfter;
      k.deadline = c.numbers.at(0);
      k.requirement = one(0);
      break;
    default: return;
  }
  pddl3_use(c.location, std::string("PDDL 3 trajectory constraint (") + to_string(k.op) + " ...)");
  k.variable_slots = scope.slots_used();
  task_.pddl3.constraints.push_back(std::move(k));
}

}  // namespace detail
}  // namespace alplan
