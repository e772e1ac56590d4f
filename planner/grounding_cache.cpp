#include "planner/grounding_cache.h"

#include <algorithm>
#include <cmath>
#include <unordered_set>

#include "pddl_parser/writer.h"

namespace alplan {
namespace {

// Everything of a problem but its initial state and timed literals.
bool same_frame(const pddl::Problem& a, const pddl::Problem& b) {
  return a.name == b.name && a.domain_name == b.domain_name && a.requirements == b.requirements &&
         a.objects == b.objects && a.goal == b.goal && a.constraints == b.constraints && a.metric == b.metric;
}

// Ground keys by names, with the reference's ids; a name it lacks makes the
// problem a miss (grounding afresh then reports it, if it is an error).
class KeyMapper {
 public:
  explicit KeyMapper(const NormalizedTask& task) {
    for (ObjectId o = 0; o < task.objects.size(); ++o) objects_.emplace(task.objects[o], o);
    for (PredicateId p = 0; p < task.predicates.size(); ++p) predicates_.emplace(task.predicates[p].name, p);
    for (FunctionId f = 0; f < task.functions.size(); ++f) functions_.emplace(task.functions[f].name, f);
  }

  bool atom(const pddl::Atom& atom, GroundKey& key) const { return map(predicates_, atom.name, atom.args, key); }
  bool term(const pddl::FunctionTerm& term, GroundKey& key) const {
    return map(functions_, term.name, term.args, key);
  }

 private:
  bool map(const std::unordered_map<std::string, std::uint32_t>& heads, const std::string& head,
           const std::vector<pddl::Term>& args, GroundKey& key) const {
    const auto h = heads.find(head);
    if (h == heads.end()) return false;
    key.head = h->second;
    key.args.resize(args.size());
    for (std::size_t i = 0; i < args.size(); ++i) {
      const auto o = objects_.find(args[i].name);
      if (o == objects_.end()) return false;
      key.args[i] = o->second;
    }
    return true;
  }

  std::unordered_map<std::string, ObjectId> objects_;
  std::unordered_map<std::string, PredicateId> predicates_;
  std::unordered_map<std::string, FunctionId> functions_;
};

// Marks which of a reference's static atoms (or values) a problem states,
// so that "the same statics" is checked in both directions.
class StaticIndex {
 public:
  std::uint32_t add(const GroundKey& key) {
    return ids_.emplace(key, static_cast<std::uint32_t>(ids_.size())).first->second;
  }
  std::optional<std::uint32_t> find(const GroundKey& key) const {
    const auto it = ids_.find(key);
    return it == ids_.end() ? std::nullopt : std::optional<std::uint32_t>(it->second);
  }
  std::size_t size() const { return ids_.size(); }

 private:
  std::unordered_map<GroundKey, std::uint32_t, GroundKeyHash> ids_;
};

std::shared_ptr<const GroundTask> missing(std::string& miss, std::string why) {
  miss = std::move(why);
  return nullptr;
}

}  // namespace

struct GroundingCache::Reference {
  pddl::Domain domain;
  pddl::Problem frame;
  std::shared_ptr<const NormalizedTask> lifted;
  IncrementalReachability reachability;
  StaticFacts statics;
  std::shared_ptr<const GroundTask> task;  // grows when the fixpoint is carried on
  KeyMapper keys;
  StaticIndex static_atoms;
  StaticIndex static_terms;
  std::vector<double> static_values;  // by static_terms id

  Reference(const pddl::Domain& d, const pddl::Problem& p, std::shared_ptr<const NormalizedTask> normalized,
            const GroundingOptions& options)
      : domain(d),
        frame(p),
        lifted(std::move(normalized)),
        reachability(lifted, reachability_options(options)),
        statics(StaticFacts::of(*lifted)),
        task(ground_reachable(lifted, reachability.reachable(), options)),
        keys(*lifted) {
    frame.init.clear();
    frame.numeric_init.clear();
    frame.timed_literals.clear();
    for (const GroundKey& k : statics.true_atoms) static_atoms.add(k);
    for (const auto& [k, value] : statics.values) {
      static_terms.add(k);
      static_values.push_back(value);
    }
  }

  static ReachabilityOptions reachability_options(const GroundingOptions& options) {
    ReachabilityOptions r;
    r.deadline = options.deadline;
    return r;
  }
};

namespace {

// Whether a condition could read one of the fresh predicates other than as
// a plain positive atom of a conjunction (those an old action cannot have:
// an unreachable one made it never applicable).
bool reads_other_than_required(const LiftedCondition& c, const std::vector<bool>& fresh, bool conjunctive = true) {
  switch (c.kind) {
    case LiftedCondition::Kind::Atom:
      return fresh[c.atom.predicate] && (!c.positive || !conjunctive);
    case LiftedCondition::Kind::And:
      return std::any_of(c.children.begin(), c.children.end(),
                         [&](const LiftedCondition& child) { return reads_other_than_required(child, fresh, conjunctive); });
    case LiftedCondition::Kind::Or:
    case LiftedCondition::Kind::Forall:
    case LiftedCondition::Kind::Exists:
      return std::any_of(c.children.begin(), c.children.end(),
                         [&](const LiftedCondition& child) { return reads_other_than_required(child, fresh, false); });
    default:
      return false;
  }
}

// Whether an action ground before the fresh atoms became reachable lost
// something about them: instantiation drops a delete or a negative
// condition on a fact it does not know, so such an action must be ground
// again, and the cache then grounds everything afresh instead.
bool lost_fresh_atoms(const ActionSchema& schema, const GroundAction& action, const std::vector<bool>& fresh_predicates,
                      const std::unordered_set<GroundKey, GroundKeyHash>& fresh) {
  for (const LiftedCondition* c : {&schema.at_start, &schema.over_all, &schema.at_end}) {
    if (reads_other_than_required(*c, fresh_predicates)) return true;
  }
  GroundKey key;
  for (const PrimitiveEffect& e : schema.effects) {
    if (e.condition.kind != LiftedCondition::Kind::True && reads_other_than_required(e.condition, fresh_predicates, false)) {
      return true;
    }
    if (e.kind != PrimitiveEffect::Kind::Delete || !fresh_predicates[e.atom.predicate]) continue;
    if (!e.forall.empty()) return true;
    key.head = e.atom.predicate;
    key.args.clear();
    for (const LiftedTerm& t : e.atom.args) {
      if (t.is_variable && t.index >= action.args.size()) return true;
      key.args.push_back(t.is_variable ? action.args[t.index] : t.index);
    }
    if (fresh.count(key)) return true;
  }
  return false;
}

}  // namespace

GroundingCache::GroundingCache(GroundingOptions options) : options_(std::move(options)) {}
GroundingCache::~GroundingCache() = default;

std::shared_ptr<const GroundTask> GroundingCache::ground(const pddl::Domain& domain, const pddl::Problem& problem) {
  last_miss_.clear();
  last_reused_ = false;
  if (!reference_) {
    last_miss_ = "nothing grounded yet";
  } else if (!same_frame(problem, reference_->frame)) {
    last_miss_ = "the objects, goal or metric differ";
  } else if (!(domain == reference_->domain)) {
    last_miss_ = "the domain differs";
  } else if (std::shared_ptr<const GroundTask> task = derive(*reference_, problem, last_miss_)) {
    ++statistics_.reused;
    last_reused_ = true;
    return task;
  }
  auto lifted = std::make_shared<const NormalizedTask>(normalize(domain, problem, options_.names));
  reference_ = std::make_unique<Reference>(domain, problem, std::move(lifted), options_);
  ++statistics_.grounded;
  return reference_->task;
}

// Carries the reference's fixpoint on from atoms it never reached, and
// grounds what they make reachable. False (with the reason) when an action
// ground before would change.
bool GroundingCache::extend(Reference& reference, const std::vector<GroundKey>& atoms, std::string& miss) const {
  const ReachableSet& reachable = reference.reachability.reachable();
  const std::uint32_t atoms_before = reachable.atoms.size();
  const std::size_t actions_before = reachable.actions.size(), axioms_before = reachable.axioms.size();
  reference.reachability.add(atoms, options_.deadline);
  if (reachable.axioms.size() != axioms_before) {
    miss = "new facts make new axioms reachable";
    return false;
  }
  const NormalizedTask& lifted = *reference.lifted;
  std::vector<bool> fresh_predicates(lifted.predicates.size(), false);
  std::unordered_set<GroundKey, GroundKeyHash> fresh;
  for (std::uint32_t a = atoms_before; a < reachable.atoms.size(); ++a) {
    const GroundKey& key = reachable.atoms.key(a);
    if (!lifted.predicates[key.head].fluent) continue;
    fresh.insert(key);
    fresh_predicates[key.head] = true;
  }
  const GroundTask& base = *reference.task;
  for (const GroundAction& a : base.actions) {
    if (lost_fresh_atoms(lifted.actions[a.schema], a, fresh_predicates, fresh)) {
      miss = "a new fact changes " + base.action_name(a);
      return false;
    }
  }
  auto task = std::make_shared<GroundTask>(base);
  for (std::uint32_t a = atoms_before; a < reachable.atoms.size(); ++a) {
    if (lifted.predicates[reachable.atoms.key(a).head].fluent) task->facts.intern(reachable.atoms.key(a));
  }
  Instantiator instantiate(lifted, reference.statics, task->facts, task->numeric, {true, false});
  instantiate.set_ghosts(&task->ghosts);
  for (std::size_t i = actions_before; i < reachable.actions.size(); ++i) {
    const Instantiation& n = reachable.actions[i];
    if (!lifted.actions[n.schema].unsupported.empty()) continue;
    GroundAction action = instantiate.action(n.schema, n.args);
    if (!action.at_start.never && !action.over_all.never && !action.at_end.never) task->actions.push_back(std::move(action));
  }
  // The goal may name facts that were unreachable before.
  std::vector<ObjectId> binding(lifted.goal_variable_slots, kNoId);
  instantiate.set_explain(true);
  task->goal = instantiate.condition(lifted.goal, binding);
  reference.task = std::move(task);
  return true;
}

// Null when the problem does not fit the reference.
std::shared_ptr<const GroundTask> GroundingCache::derive(Reference& reference, const pddl::Problem& problem,
                                                         std::string& miss) const {
  std::vector<GroundKey> unreached;
  std::shared_ptr<const GroundTask> task = map_onto(reference, problem, unreached, miss);
  if (task || unreached.empty()) return task;
  if (!extend(reference, unreached, miss)) return nullptr;
  unreached.clear();
  return map_onto(reference, problem, unreached, miss);
}

// The problem's initial state and timed literals on the reference's ids;
// null when it does not fit, with the facts the reference never reaches in
// `unreached` (when that is all that stops it).
std::shared_ptr<const GroundTask> GroundingCache::map_onto(const Reference& reference, const pddl::Problem& problem,
                                                           std::vector<GroundKey>& unreached, std::string& miss) const {
  const GroundTask& base = *reference.task;
  const NormalizedTask& lifted = *base.lifted;
  auto next = std::make_shared<NormalizedTask>(lifted);
  next->initial_facts.clear();
  next->initial_values.clear();
  next->timed_literals.clear();
  auto task = std::make_shared<GroundTask>();
  GroundKey key;

  std::vector<bool> stated(reference.static_atoms.size(), false);
  std::size_t statics_stated = 0;
  for (const pddl::Atom& atom : problem.init) {
    if (!reference.keys.atom(atom, key)) return missing(miss, "an unknown name in " + pddl::write_atom(atom));
    next->initial_facts.push_back({key.head, key.args});
    if (lifted.predicates[key.head].fluent) {
      if (const std::optional<FactId> fact = base.facts.find(key)) {
        task->initial_facts.push_back(*fact);
      } else {
        unreached.push_back(key);
        miss = "the reference never reaches " + pddl::write_atom(atom);
      }
    } else {
      const std::optional<std::uint32_t> s = reference.static_atoms.find(key);
      if (!s) return missing(miss, "a new static fact " + pddl::write_atom(atom));
      if (!stated[*s]) ++statics_stated;
      stated[*s] = true;
    }
  }
  if (statics_stated != stated.size()) return missing(miss, "a static fact no longer holds");
  std::sort(task->initial_facts.begin(), task->initial_facts.end());
  task->initial_facts.erase(std::unique(task->initial_facts.begin(), task->initial_facts.end()),
                            task->initial_facts.end());

  std::vector<bool> valued(reference.static_terms.size(), false);
  std::size_t values_stated = 0;
  task->initial_values.assign(base.numeric.size(), std::nan(""));
  for (const pddl::NumericFact& f : problem.numeric_init) {
    if (!reference.keys.term(f.function, key)) return missing(miss, "an unknown name in a numeric value");
    next->initial_values.push_back({key.head, key.args, f.value});
    if (lifted.functions[key.head].fluent) {
      const std::optional<NumericVarId> variable = base.numeric.find(key);
      if (!variable) return missing(miss, "a numeric variable the reference lacks");
      task->initial_values[*variable] = f.value;
    } else {
      const std::optional<std::uint32_t> s = reference.static_terms.find(key);
      if (!s || reference.static_values[*s] != f.value) return missing(miss, "a static value changed");
      if (!valued[*s]) ++values_stated;
      valued[*s] = true;
    }
  }
  if (values_stated != valued.size()) return missing(miss, "a static value is no longer given");

  for (const pddl::TimedInitialLiteral& til : problem.timed_literals) {
    if (til.numeric_value || !reference.keys.atom(til.atom, key)) return missing(miss, "a timed literal it cannot map");
    if (!lifted.predicates[key.head].fluent) {
      return missing(miss, "a timed literal on the static predicate " + til.atom.name);
    }
    next->timed_literals.push_back({til.time, til.positive, {key.head, key.args}});
  }
  std::stable_sort(next->timed_literals.begin(), next->timed_literals.end(),
                   [](const NormalizedTimedLiteral& a, const NormalizedTimedLiteral& b) { return a.time < b.time; });
  for (const NormalizedTimedLiteral& til : next->timed_literals) {
    key.head = til.atom.predicate;
    key.args = til.atom.args;
    if (const std::optional<FactId> fact = base.facts.find(key)) {
      task->timed_literals.push_back({til.time, *fact, til.positive});
    } else if (til.positive) {
      unreached.push_back(key);
      miss = "a timed literal adds " + lifted.atom_name(til.atom) + ", which the reference never reaches";
    }
  }
  if (!unreached.empty()) return nullptr;

  task->lifted = std::move(next);
  task->facts = base.facts;
  task->numeric = base.numeric;
  task->actions = base.actions;
  task->axioms = base.axioms;
  task->strata = base.strata;
  task->goal = base.goal;
  task->metric = base.metric;
  return task;
}

}  // namespace alplan
