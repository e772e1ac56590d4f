#include "planner/instantiate.h"

#include <algorithm>
#include <iterator>
#include <stdexcept>

#include "pddl_parser/writer.h"

namespace alplan {
namespace {

using LK = LiftedCondition::Kind;
using FK = GroundFormula::Kind;

GroundFormula constant_formula(bool value, std::string reason = {}) {
  GroundFormula f;
  f.kind = value ? FK::True : FK::False;
  f.reason = std::move(reason);
  return f;
}

// Combines children under And/Or, folding constants.
GroundFormula junction(FK kind, std::vector<GroundFormula> children) {
  const FK absorbing = kind == FK::And ? FK::False : FK::True;
  const FK neutral = kind == FK::And ? FK::True : FK::False;
  GroundFormula result;
  result.kind = kind;
  std::string reasons;
  for (GroundFormula& c : children) {
    if (c.kind == absorbing) return std::move(c);
    if (c.kind == neutral) {
      if (!c.reason.empty()) reasons += (reasons.empty() ? "" : ", ") + c.reason;
      continue;
    }
    if (c.kind == kind) {
      for (GroundFormula& g : c.children) result.children.push_back(std::move(g));
    } else {
      result.children.push_back(std::move(c));
    }
  }
  if (result.children.empty()) return constant_formula(kind == FK::And, "(or " + reasons + ")");
  if (result.children.size() == 1) return std::move(result.children.front());
  return result;
}

bool is_constant(const GroundExpression& e) { return e.kind == GroundExpression::Kind::Constant; }

bool compare(pddl::Comparison c, double a, double b) {
  switch (c) {
    case pddl::Comparison::Less: return a < b;
    case pddl::Comparison::LessEqual: return a <= b;
    case pddl::Comparison::Equal: return a == b;
    case pddl::Comparison::GreaterEqual: return a >= b;
    case pddl::Comparison::Greater: return a > b;
  }
  return false;
}

// Folds an operation whose operands are all constants.
void fold(GroundExpression& e) {
  using K = GroundExpression::Kind;
  if (!std::all_of(e.operands.begin(), e.operands.end(), is_constant)) return;
  if (e.operands.empty()) return;
  double v = e.operands.front().value;
  switch (e.kind) {
    case K::Add: for (std::size_t i = 1; i < e.operands.size(); ++i) v += e.operands[i].value; break;
    case K::Multiply: for (std::size_t i = 1; i < e.operands.size(); ++i) v *= e.operands[i].value; break;
    case K::Subtract: v -= e.operands[1].value; break;
    case K::Divide:
      if (e.operands[1].value == 0.0) return;  // left for evaluation to report
      v /= e.operands[1].value;
      break;
    case K::Negate: v = -v; break;
    default: return;
  }
  e.kind = K::Constant;
  e.value = v;
  e.operands.clear();
}

// Binds the quantified variables to every combination of their types'
// objects in turn and calls visit() for each, until it returns false.
// Returns false when visit() stopped it; a type without objects means no
// combination at all.
template <typename Visit>
bool for_each_assignment(const NormalizedTask& task, const std::vector<QuantifiedVariable>& variables,
                         std::vector<ObjectId>& binding, Visit visit) {
  for (const QuantifiedVariable& v : variables) {
    if (task.types[v.type].objects.empty()) return true;
  }
  std::vector<std::size_t> position(variables.size(), 0);
  while (true) {
    for (std::size_t i = 0; i < variables.size(); ++i) {
      binding[variables[i].slot] = task.types[variables[i].type].objects[position[i]];
    }
    if (!visit()) return false;
    std::size_t i = 0;
    for (; i < variables.size(); ++i) {
      if (++position[i] < task.types[variables[i].type].objects.size()) break;
      position[i] = 0;
    }
    if (i == variables.size()) return true;
  }
}

template <typename T>
void sort_unique(std::vector<T>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

}  // namespace

StaticFacts StaticFacts::of(const NormalizedTask& task) {
  StaticFacts statics;
  for (const GroundAtom& a : task.initial_facts) {
    if (!task.predicates[a.predicate].fluent) statics.true_atoms.insert({a.predicate, a.args});
  }
  for (const NumericInitialValue& v : task.initial_values) {
    if (!task.functions[v.function].fluent) statics.values[{v.function, v.args}] = v.value;
  }
  return statics;
}

Instantiator::Instantiator(const NormalizedTask& task, const StaticFacts& statics, GroundKeyTable& facts,
                           GroundKeyTable& numeric, InstantiationOptions options)
    : task_(task), statics_(statics), facts_(facts), numeric_(numeric), options_(options) {}

GroundKey Instantiator::key(const LiftedAtom& atom, const std::vector<ObjectId>& binding) const {
  GroundKey k{atom.predicate, {}};
  k.args.reserve(atom.args.size());
  for (const LiftedTerm& t : atom.args) k.args.push_back(t.is_variable ? binding[t.index] : t.index);
  return k;
}

GroundKey Instantiator::key(const LiftedFunctionTerm& term, const std::vector<ObjectId>& binding) const {
  GroundKey k{term.function, {}};
  k.args.reserve(term.args.size());
  for (const LiftedTerm& t : term.args) k.args.push_back(t.is_variable ? binding[t.index] : t.index);
  return k;
}

const GroundKey& Instantiator::scratch(std::uint32_t head, const std::vector<LiftedTerm>& args,
                                      const std::vector<ObjectId>& binding) {
  scratch_.head = head;
  scratch_.args.clear();
  for (const LiftedTerm& t : args) scratch_.args.push_back(t.is_variable ? binding[t.index] : t.index);
  return scratch_;
}

std::string Instantiator::name(const GroundKey& k, bool function) const {
  return key_name(k, function ? task_.functions[k.head].name : task_.predicates[k.head].name, task_.objects);
}

std::optional<FactId> Instantiator::fact(const GroundKey& k) {
  if (options_.intern_unknown) return facts_.intern(k);
  return facts_.find(k);
}

GroundExpression Instantiator::expression(const LiftedExpression& e, const std::vector<ObjectId>& binding) {
  using LE = LiftedExpression::Kind;
  using K = GroundExpression::Kind;
  GroundExpression g;
  switch (e.kind) {
    case LE::Constant: g.kind = K::Constant; g.value = e.value; return g;
    case LE::Duration: g.kind = K::Duration; return g;
    case LE::TotalTime: g.kind = K::TotalTime; return g;
    case LE::IsViolated: g.kind = K::IsViolated; g.variable = e.preference; return g;
    case LE::Function: {
      const GroundKey& k = scratch(e.term.function, e.term.args, binding);
      if (!task_.functions[e.term.function].fluent) {
        auto it = statics_.values.find(k);
        if (it != statics_.values.end()) {
          g.kind = K::Constant;
          g.value = it->second;
        } else {
          g.kind = K::Undefined;
          g.undefined_term = name(k, true);
        }
        return g;
      }
      g.kind = K::Variable;
      g.variable = numeric_.intern(k);
      return g;
    }
    case LE::Add: g.kind = K::Add; break;
    case LE::Subtract: g.kind = K::Subtract; break;
    case LE::Multiply: g.kind = K::Multiply; break;
    case LE::Divide: g.kind = K::Divide; break;
    case LE::Negate: g.kind = K::Negate; break;
  }
  for (const LiftedExpression& operand : e.operands) g.operands.push_back(expression(operand, binding));
  fold(g);
  return g;
}

GroundFormula Instantiator::formula(const LiftedCondition& c, std::vector<ObjectId>& binding) {
  switch (c.kind) {
    case LK::True: return constant_formula(true);
    case LK::False: return constant_formula(false, "false");
    case LK::And:
    case LK::Or: {
      std::vector<GroundFormula> children;
      children.reserve(c.children.size());
      for (const LiftedCondition& child : c.children) {
        children.push_back(formula(child, binding));
        if (c.kind == LK::And && children.back().kind == FK::False) return std::move(children.back());
        if (c.kind == LK::Or && children.back().kind == FK::True) return std::move(children.back());
      }
      return junction(c.kind == LK::And ? FK::And : FK::Or, std::move(children));
    }
    case LK::Forall:
    case LK::Exists: {
      // Expand over every combination of the quantified variables' objects.
      const bool all = c.kind == LK::Forall;
      for (const QuantifiedVariable& v : c.variables) {
        if (task_.types[v.type].objects.empty()) return constant_formula(all, all ? "" : "(exists over no object)");
      }
      std::vector<GroundFormula> children;
      const bool decided = !for_each_assignment(task_, c.variables, binding, [&] {
        children.push_back(formula(c.children.front(), binding));
        return children.back().kind != (all ? FK::False : FK::True);
      });
      if (decided) return std::move(children.back());
      return junction(all ? FK::And : FK::Or, std::move(children));
    }
    case LK::Equality: {
      const ObjectId a = c.left.is_variable ? binding[c.left.index] : c.left.index;
      const ObjectId b = c.right.is_variable ? binding[c.right.index] : c.right.index;
      const bool holds = (a == b) == c.positive;
      if (holds) return constant_formula(true);
      if (!options_.explain) return constant_formula(false);
      const std::string eq = "(= " + task_.objects[a] + " " + task_.objects[b] + ")";
      return constant_formula(false, c.positive ? eq : "(not " + eq + ")");
    }
    case LK::Atom: {
      const GroundKey& k = scratch(c.atom.predicate, c.atom.args, binding);
      const PredicateInfo& p = task_.predicates[c.atom.predicate];
      if (!p.fluent && options_.simplify_static) {
        const bool holds = statics_.true_atoms.count(k) != 0;
        if (holds == c.positive) return constant_formula(true);
        if (!options_.explain) return constant_formula(false);
        return constant_formula(false, c.positive ? name(k, false) : "(not " + name(k, false) + ")");
      }
      std::optional<FactId> id = fact(k);
      if (!id) {
        if (!c.positive) return constant_formula(true);
        return constant_formula(false, options_.explain ? name(k, false) : std::string());
      }
      GroundFormula f;
      f.kind = FK::Literal;
      f.fact = *id;
      f.positive = c.positive;
      return f;
    }
    case LK::Comparison: {
      GroundFormula f;
      f.kind = FK::Comparison;
      f.comparison.comparison = c.comparison;
      f.comparison.left = expression(c.sides[0], binding);
      f.comparison.right = expression(c.sides[1], binding);
      if (is_constant(f.comparison.left) && is_constant(f.comparison.right)) {
        if (compare(c.comparison, f.comparison.left.value, f.comparison.right.value)) return constant_formula(true);
        if (!options_.explain) return constant_formula(false);
        return constant_formula(false, std::string("(") + pddl::to_string(c.comparison) + " " +
                                           pddl::format_number(f.comparison.left.value) + " " +
                                           pddl::format_number(f.comparison.right.value) + ")");
      }
      return f;
    }
  }
  return constant_formula(true);
}

ConditionSet flatten(GroundFormula f) {
  ConditionSet set;
  auto add = [&](GroundFormula& g) {
    switch (g.kind) {
      case FK::True: break;
      case FK::False: set.never = g.reason.empty() ? "false" : g.reason; break;
      case FK::Literal: (g.positive ? set.positive : set.negative).push_back(g.fact); break;
      case FK::Comparison: set.numeric.push_back(std::move(g.comparison)); break;
      default: set.complex.push_back(std::move(g)); break;
    }
  };
  if (f.kind == FK::And) {
    for (GroundFormula& child : f.children) add(child);
  } else {
    add(f);
  }
  sort_unique(set.positive);
  sort_unique(set.negative);
  return set;
}


void Instantiator::mentioned_facts(const LiftedCondition& c, std::vector<ObjectId>& binding,
                                   std::vector<FactId>& out, std::vector<std::uint32_t>& ghosts) {
  switch (c.kind) {
    case LK::And:
    case LK::Or:
      for (const LiftedCondition& child : c.children) mentioned_facts(child, binding, out, ghosts);
      return;
    case LK::Forall:
    case LK::Exists:
      for_each_assignment(task_, c.variables, binding, [&] {
        mentioned_facts(c.children.front(), binding, out, ghosts);
        return true;
      });
      return;
    case LK::Atom:
      if (task_.predicates[c.atom.predicate].fluent) {
        const GroundKey& k = scratch(c.atom.predicate, c.atom.args, binding);
        if (std::optional<FactId> id = facts_.find(k)) {
          out.push_back(*id);
        } else if (ghosts_) {
          // Never true, but an action may delete it: VAL's mutex rule counts it.
          ghosts.push_back(ghosts_->intern(k));
        }
      }
      return;
    default:
      return;
  }
}

ConditionSet Instantiator::condition(const LiftedCondition& c, std::vector<ObjectId>& binding) {
  return flatten(formula(c, binding));
}

ConditionSet Instantiator::preference_condition(const LiftedCondition& c, std::vector<ObjectId>& binding) {
  ConditionSet set = condition(c, binding);
  add_mentions(c, binding, set, true);
  return set;
}

void Instantiator::add_mentions(const LiftedCondition& c, std::vector<ObjectId>& binding, ConditionSet& set,
                                bool even_never) {
  // A literal simplified away still counts: VAL marks what a condition
  // names, true or not, so a statically true (not f) read by a start is a
  // mutex with its zero-duration end deleting f (differential tester).
  if (!options_.simplify_static || (set.never && !even_never)) return;
  std::vector<FactId> named;
  std::vector<std::uint32_t> ghosts;
  mentioned_facts(c, binding, named, ghosts);
  sort_unique(named);
  sort_unique(ghosts);
  set.ghost_mentioned = std::move(ghosts);
  std::vector<FactId> kept = set.positive;
  kept.insert(kept.end(), set.negative.begin(), set.negative.end());
  sort_unique(kept);
  std::set_difference(named.begin(), named.end(), kept.begin(), kept.end(), std::back_inserter(set.mentioned));
}

void Instantiator::primitive(const PrimitiveEffect& e, std::vector<ObjectId>& binding, std::size_t forall_index,
                             GroundAction& action) {
  if (forall_index < e.forall.size()) {
    const QuantifiedVariable& v = e.forall[forall_index];
    for (ObjectId o : task_.types[v.type].objects) {
      binding[v.slot] = o;
      primitive(e, binding, forall_index + 1, action);
    }
    return;
  }
  if (e.kind == PrimitiveEffect::Kind::Continuous) {
    action.continuous.push_back({numeric_.intern(key(e.target, binding)), e.assign, expression(e.value, binding)});
    return;
  }
  ConditionSet condition = this->condition(e.condition, binding);
  if (condition.never) return;
  HappeningEffects& target = e.moment == Moment::End ? action.end : action.start;
  std::vector<FactId>* add = &target.add;
  std::vector<FactId>* del = &target.del;
  std::vector<NumericAssignment>* numeric = &target.numeric;
  std::vector<std::uint32_t>* ghost_del = &target.ghost_del;
  if (!condition.empty()) {
    target.conditional.push_back({std::move(condition), e.condition_moment, {}, {}, {}, {}});
    add = &target.conditional.back().add;
    del = &target.conditional.back().del;
    ghost_del = &target.conditional.back().ghost_del;
    numeric = &target.conditional.back().numeric;
  }
  switch (e.kind) {
    case PrimitiveEffect::Kind::Add: {
      std::optional<FactId> id = fact(key(e.atom, binding));
      if (!id) throw std::logic_error("an add effect of a reachable action is not a reachable fact");
      add->push_back(*id);
      break;
    }
    case PrimitiveEffect::Kind::Delete:
      if (std::optional<FactId> id = fact(key(e.atom, binding))) {
        del->push_back(*id);
      } else if (ghosts_) {
        // Deleting what is never true changes nothing, but VAL's mutex rule
        // still counts the delete (ghost_mentioned says how).
        ghost_del->push_back(ghosts_->intern(key(e.atom, binding)));
      }
      break;
    case PrimitiveEffect::Kind::Continuous: break;  // handled above
    case PrimitiveEffect::Kind::Numeric:
      numeric->push_back({numeric_.intern(key(e.target, binding)), e.assign, expression(e.value, binding)});
      break;
  }
}

void Instantiator::effects(const ActionSchema& schema, std::vector<ObjectId>& binding, GroundAction& action) {
  for (const PrimitiveEffect& e : schema.effects) primitive(e, binding, 0, action);
  for (HappeningEffects* h : {&action.start, &action.end}) {
    std::sort(h->add.begin(), h->add.end());
    for (std::size_t i = 1; i < h->add.size(); ++i) {
      if (h->add[i] == h->add[i - 1] && (h->added_twice.empty() || h->added_twice.back() != h->add[i]))
        h->added_twice.push_back(h->add[i]);
    }
    sort_unique(h->add);
    sort_unique(h->del);
  }
}

GroundAction Instantiator::action(std::uint32_t schema_index, const std::vector<ObjectId>& args) {
  const ActionSchema& schema = task_.actions[schema_index];
  GroundAction action;
  action.schema = schema_index;
  action.args = args;
  action.durative = schema.durative;
  std::vector<ObjectId> binding(std::max<std::size_t>(schema.variable_slots, args.size()), kNoId);
  std::copy(args.begin(), args.end(), binding.begin());
  action.at_start = condition(schema.at_start, binding);
  action.over_all = condition(schema.over_all, binding);
  action.at_end = condition(schema.at_end, binding);
  // Only the snaps' own conditions: they are what VAL's mutex rule reads.
  add_mentions(schema.at_start, binding, action.at_start);
  add_mentions(schema.over_all, binding, action.over_all);
  add_mentions(schema.at_end, binding, action.at_end);
  for (const LiftedDurationConstraint& d : schema.duration) {
    action.duration.push_back({d.comparison, expression(d.value, binding), d.moment});
  }
  effects(schema, binding, action);
  action.preferences = ground_preferences(schema.preferences, binding, *this);
  return action;
}

namespace {

void bind_from(const NormalizedTask& task, const std::vector<QuantifiedVariable>& variables, std::size_t index,
               std::vector<ObjectId>& binding, const std::function<void()>& visit) {
  if (index == variables.size()) {
    visit();
    return;
  }
  const QuantifiedVariable& v = variables[index];
  if (binding.size() <= v.slot) binding.resize(v.slot + 1, kNoId);
  for (ObjectId o : task.types[v.type].objects) {
    binding[v.slot] = o;
    bind_from(task, variables, index + 1, binding, visit);
  }
}

}  // namespace

void for_each_binding(const NormalizedTask& task, const std::vector<QuantifiedVariable>& variables,
                      std::vector<ObjectId>& binding, const std::function<void()>& visit) {
  bind_from(task, variables, 0, binding, visit);
}

std::vector<GroundPreference> ground_preferences(const std::vector<PreferenceCondition>& preferences,
                                                 std::vector<ObjectId> binding, Instantiator& instantiate) {
  std::vector<GroundPreference> result;
  for (const PreferenceCondition& p : preferences) {
    for_each_binding(instantiate.task(), p.forall, binding, [&] {
      std::vector<ObjectId> scratch = binding;
      result.push_back({p.preference, instantiate.preference_condition(p.condition, scratch), p.time});
    });
  }
  return result;
}

}  // namespace alplan
