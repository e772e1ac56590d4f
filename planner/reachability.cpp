#include "planner/reachability.h"

#include <algorithm>
#include <deque>
#include <unordered_map>
#include <unordered_set>

#include "planner/deadline.h"

namespace alplan {
namespace {

using LK = LiftedCondition::Kind;
using Conjunctions = std::vector<std::vector<LiftedAtom>>;

// A Datalog rule: if every body atom is reachable under a binding of the
// variables (each of its type), the head instantiation is reachable.
struct Rule {
  bool axiom = false;
  // A durative action's start alone: reachable on its at-start condition
  // (and static invariant), it gives only its at-start adds. The action
  // itself needs its invariant's atoms reachable too, which starts in the
  // same happening may give (two actions can hold up each other's).
  bool start_only = false;
  std::uint32_t owner = 0;          // schema or derived-rule index
  std::uint32_t parameters = 0;     // slots [0, parameters) form the head
  std::vector<TypeId> slot_types;   // kNoId for slots the rule does not use
  std::vector<LiftedAtom> body;
};

// Positive-atom DNF of a relaxed condition (see the header).
class RelaxedDnf {
 public:
  RelaxedDnf(std::size_t limit, std::vector<TypeId>& slot_types) : limit_(limit), slot_types_(slot_types) {}

  Conjunctions of(const LiftedCondition& c) {
    switch (c.kind) {
      case LK::False: return {};
      case LK::Atom:
        if (c.positive) return {{c.atom}};
        return {{}};
      case LK::Exists:
        for (const QuantifiedVariable& v : c.variables) slot_types_[v.slot] = v.type;
        return of(c.children.front());
      case LK::Or: {
        Conjunctions all;
        for (const LiftedCondition& child : c.children) {
          Conjunctions part = of(child);
          all.insert(all.end(), part.begin(), part.end());
        }
        if (all.size() > limit_) return {{}};
        return all;
      }
      case LK::And: {
        Conjunctions product{{}};
        for (const LiftedCondition& child : c.children) {
          Conjunctions part = of(child);
          if (part.empty()) return {};
          if (product.size() * part.size() > limit_) part = {common_atoms(part)};
          Conjunctions next;
          for (const auto& left : product) {
            for (const auto& right : part) {
              next.push_back(left);
              next.back().insert(next.back().end(), right.begin(), right.end());
            }
          }
          product = std::move(next);
        }
        return product;
      }
      default: return {{}};  // equality, comparisons and forall are relaxed away
    }
  }

 private:
  // When splitting would be too large, keep what every disjunct requires.
  static std::vector<LiftedAtom> common_atoms(const Conjunctions& disjuncts) {
    std::vector<LiftedAtom> common;
    for (const LiftedAtom& a : disjuncts.front()) {
      bool everywhere = std::all_of(disjuncts.begin() + 1, disjuncts.end(), [&](const auto& d) {
        return std::any_of(d.begin(), d.end(), [&](const LiftedAtom& b) {
          return b.predicate == a.predicate && b.args == a.args;
        });
      });
      if (everywhere) common.push_back(a);
    }
    return common;
  }

  std::size_t limit_;
  std::vector<TypeId>& slot_types_;
};

// What a durative action's start needs (at_start_only) or the whole action
// (its at-start condition and every positive atom of its invariant): the
// invariant need not hold before the start, since another start in the same
// happening may give it (VAL checks it after that happening), but it must
// be reachable at all for the action to be of use, and requiring it keeps
// actions whose invariant can never hold out of the grounding.
LiftedCondition relaxed_precondition(const NormalizedTask& task, const ActionSchema& schema,
                                     const ReachabilityOptions& options, bool at_start_only) {
  if (!schema.durative || !options.require_over_all) return schema.at_start;
  LiftedCondition both;
  both.kind = LK::And;
  both.children.push_back(schema.at_start);
  auto keep = [&](const LiftedCondition& c) {
    if (!at_start_only) return true;
    return c.kind == LK::Atom && c.positive && !task.predicates[c.atom.predicate].fluent &&
           !task.predicates[c.atom.predicate].derived;
  };
  const LiftedCondition& invariant = schema.over_all;
  if (invariant.kind == LK::And) {
    for (const LiftedCondition& c : invariant.children) {
      if (keep(c)) both.children.push_back(c);
    }
  } else if (keep(invariant)) {
    both.children.push_back(invariant);
  }
  return both;
}

std::vector<Rule> make_rules(const NormalizedTask& task, const ReachabilityOptions& options) {
  std::vector<Rule> rules;
  auto add = [&](bool axiom, bool start_only, std::uint32_t owner, const std::vector<Parameter>& parameters,
                 std::uint32_t slots, const LiftedCondition& condition) {
    std::vector<TypeId> slot_types(std::max<std::size_t>(slots, parameters.size()), kNoId);
    for (std::size_t i = 0; i < parameters.size(); ++i) slot_types[i] = parameters[i].type;
    RelaxedDnf dnf(options.max_disjuncts, slot_types);
    for (std::vector<LiftedAtom>& body : dnf.of(condition)) {
      rules.push_back({axiom, start_only, owner, static_cast<std::uint32_t>(parameters.size()), slot_types, std::move(body)});
    }
  };
  for (std::uint32_t a = 0; a < task.actions.size(); ++a) {
    const ActionSchema& s = task.actions[a];
    add(false, false, a, s.parameters, s.variable_slots, relaxed_precondition(task, s, options, false));
    const bool starts_give = std::any_of(s.effects.begin(), s.effects.end(), [](const PrimitiveEffect& e) {
      return e.kind == PrimitiveEffect::Kind::Add && e.moment == Moment::Start;
    });
    if (s.durative && options.require_over_all && starts_give) {
      add(false, true, a, s.parameters, s.variable_slots, relaxed_precondition(task, s, options, true));
    }
  }
  for (std::uint32_t r = 0; r < task.derived_rules.size(); ++r) {
    const DerivedRule& d = task.derived_rules[r];
    add(true, false, r, d.parameters, d.variable_slots, d.body);
  }
  return rules;
}

}  // namespace

// The fixpoint: a work list of newly reached atoms, each joined with the
// rules whose body mentions its predicate (semi-naive evaluation). Atoms
// added later join with everything known, so the fixpoint can be carried on.
class Fixpoint {
 public:
  Fixpoint(const NormalizedTask& task, std::vector<Rule> rules, Deadline deadline)
      : task_(task), rules_(std::move(rules)), deadline_(deadline) {
    members_.resize(task.types.size());
    for (TypeId t = 0; t < task.types.size(); ++t) {
      members_[t].assign(task.objects.size(), false);
      for (ObjectId o : task.types[t].objects) members_[t][o] = true;
    }
    tuples_.resize(task.predicates.size());
    watchers_.resize(task.predicates.size());
    for (std::uint32_t r = 0; r < rules_.size(); ++r) {
      for (std::uint32_t i = 0; i < rules_[r].body.size(); ++i) watchers_[rules_[r].body[i].predicate].push_back({r, i});
    }
  }

  void run() {
    for (const GroundAtom& a : task_.initial_facts) reach({a.predicate, a.args});
    for (const NormalizedTimedLiteral& til : task_.timed_literals) {
      if (til.positive) reach({til.atom.predicate, til.atom.args});
    }
    for (std::uint32_t r = 0; r < rules_.size(); ++r) {
      if (rules_[r].body.empty()) {
        std::vector<ObjectId> binding(rules_[r].slot_types.size(), kNoId);
        complete(rules_[r], binding, 0);
      }
    }
    drain();
  }

  void add(const std::vector<GroundKey>& atoms, Deadline deadline) {
    deadline_ = deadline;
    for (const GroundKey& key : atoms) reach(key);
    drain();
  }

  const ReachableSet& result() const { return result_; }
  ReachableSet take() { return std::move(result_); }

 private:
  void drain() {
    while (!queue_.empty()) {
      deadline_.check("reachability");
      const std::uint32_t atom = queue_.front();
      queue_.pop_front();
      const GroundKey key = result_.atoms.key(atom);
      for (const auto& [rule, index] : watchers_[key.head]) {
        const Rule& r = rules_[rule];
        std::vector<ObjectId> binding(r.slot_types.size(), kNoId);
        if (!match(r.body[index], key.args, r, binding)) continue;
        std::vector<bool> done(r.body.size(), false);
        done[index] = true;
        join(r, binding, done, 1);
      }
    }
  }

  struct Watch {
    std::uint32_t rule, atom;
  };

  void reach(const GroundKey& key) {
    const std::uint32_t before = result_.atoms.size();
    const std::uint32_t id = result_.atoms.intern(key);
    if (id != before) return;
    const std::uint32_t tuple = static_cast<std::uint32_t>(tuples_[key.head].size());
    tuples_[key.head].push_back(id);
    for (std::uint32_t pos = 0; pos < key.args.size(); ++pos) index_[index_key(key.head, pos, key.args[pos])].push_back(tuple);
    queue_.push_back(id);
  }

  static std::uint64_t index_key(PredicateId p, std::uint32_t position, ObjectId o) {
    return (static_cast<std::uint64_t>(p) << 40) ^ (static_cast<std::uint64_t>(position) << 32) ^ o;
  }

  bool match(const LiftedAtom& atom, const std::vector<ObjectId>& args, const Rule& rule,
             std::vector<ObjectId>& binding) const {
    for (std::size_t i = 0; i < args.size(); ++i) {
      const LiftedTerm& t = atom.args[i];
      if (!t.is_variable) {
        if (t.index != args[i]) return false;
        continue;
      }
      ObjectId& slot = binding[t.index];
      if (slot == kNoId) {
        const TypeId type = rule.slot_types[t.index];
        if (type != kNoId && !members_[type][args[i]]) return false;
        slot = args[i];
      } else if (slot != args[i]) {
        return false;
      }
    }
    return true;
  }

  // Binds the remaining body atoms, most-bound first, against known atoms.
  void join(const Rule& rule, std::vector<ObjectId>& binding, std::vector<bool>& done, std::size_t matched) {
    if (matched == rule.body.size()) {
      complete(rule, binding, 0);
      return;
    }
    std::size_t best = rule.body.size();
    int best_bound = -1;
    for (std::size_t i = 0; i < rule.body.size(); ++i) {
      if (done[i]) continue;
      int bound = 0;
      for (const LiftedTerm& t : rule.body[i].args) bound += !t.is_variable || binding[t.index] != kNoId;
      if (bound > best_bound) {
        best_bound = bound;
        best = i;
      }
    }
    const LiftedAtom& atom = rule.body[best];
    const std::vector<std::uint32_t>* candidates = nullptr;
    std::vector<std::uint32_t> all;
    for (std::uint32_t pos = 0; pos < atom.args.size() && !candidates; ++pos) {
      const LiftedTerm& t = atom.args[pos];
      const ObjectId o = t.is_variable ? binding[t.index] : t.index;
      if (o == kNoId) continue;
      auto it = index_.find(index_key(atom.predicate, pos, o));
      if (it == index_.end()) return;
      candidates = &it->second;
    }
    if (!candidates) {
      all.resize(tuples_[atom.predicate].size());
      for (std::uint32_t i = 0; i < all.size(); ++i) all[i] = i;
      candidates = &all;
    }
    done[best] = true;
    const std::vector<ObjectId> saved = binding;
    const std::size_t count = candidates->size();  // atoms reached meanwhile join later
    for (std::size_t c = 0; c < count; ++c) {
      deadline_.check("reachability");  // one join can take long on its own
      const std::uint32_t atom_id = tuples_[atom.predicate][(*candidates)[c]];
      // The key is read before join() can intern atoms (and move the keys).
      if (match(atom, result_.atoms.key(atom_id).args, rule, binding)) join(rule, binding, done, matched + 1);
      binding = saved;
    }
    done[best] = false;
  }

  // Enumerates head parameters no body atom bound, then records the head.
  void complete(const Rule& rule, std::vector<ObjectId>& binding, std::uint32_t slot) {
    deadline_.check("reachability");
    while (slot < rule.parameters && binding[slot] != kNoId) ++slot;
    if (slot < rule.parameters) {
      for (ObjectId o : task_.types[rule.slot_types[slot]].objects) {
        binding[slot] = o;
        complete(rule, binding, slot + 1);
      }
      binding[slot] = kNoId;
      return;
    }
    std::vector<ObjectId> args(binding.begin(), binding.begin() + rule.parameters);
    if (rule.axiom) {
      if (!seen_axioms_.insert({rule.owner, args}).second) return;
      const DerivedRule& d = task_.derived_rules[rule.owner];
      result_.axioms.push_back({rule.owner, args});
      reach({d.head, std::move(args)});
      return;
    }
    if (rule.start_only) {
      if (!seen_starts_.insert({rule.owner, args}).second) return;
    } else {
      if (!seen_actions_.insert({rule.owner, args}).second) return;
      result_.actions.push_back({rule.owner, args});
    }
    const ActionSchema& schema = task_.actions[rule.owner];
    std::vector<ObjectId> full(std::max<std::size_t>(schema.variable_slots, args.size()), kNoId);
    std::copy(args.begin(), args.end(), full.begin());
    for (const PrimitiveEffect& e : schema.effects) {
      if (e.kind != PrimitiveEffect::Kind::Add) continue;
      if (rule.start_only && e.moment != Moment::Start) continue;
      add_effect(e, full, 0);
    }
  }

  void add_effect(const PrimitiveEffect& e, std::vector<ObjectId>& binding, std::size_t forall_index) {
    if (forall_index < e.forall.size()) {
      const QuantifiedVariable& v = e.forall[forall_index];
      for (ObjectId o : task_.types[v.type].objects) {
        binding[v.slot] = o;
        add_effect(e, binding, forall_index + 1);
      }
      return;
    }
    GroundKey key{e.atom.predicate, {}};
    for (const LiftedTerm& t : e.atom.args) key.args.push_back(t.is_variable ? binding[t.index] : t.index);
    reach(key);
  }

  const NormalizedTask& task_;
  std::vector<Rule> rules_;
  std::vector<std::vector<bool>> members_;
  std::vector<std::vector<std::uint32_t>> tuples_;  // per predicate: atom ids
  std::vector<std::vector<Watch>> watchers_;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> index_;
  std::unordered_set<GroundKey, GroundKeyHash> seen_actions_, seen_axioms_, seen_starts_;
  std::deque<std::uint32_t> queue_;
  ReachableSet result_;
  Deadline deadline_;
};

ReachableSet compute_reachable(const NormalizedTask& task, const ReachabilityOptions& options) {
  Fixpoint fixpoint(task, make_rules(task, options), Deadline(options.deadline));
  fixpoint.run();
  return fixpoint.take();
}

IncrementalReachability::IncrementalReachability(std::shared_ptr<const NormalizedTask> task,
                                                 const ReachabilityOptions& options)
    : task_(std::move(task)),
      fixpoint_(std::make_unique<Fixpoint>(*task_, make_rules(*task_, options), Deadline(options.deadline))) {
  fixpoint_->run();
}

IncrementalReachability::~IncrementalReachability() = default;

const ReachableSet& IncrementalReachability::reachable() const { return fixpoint_->result(); }

void IncrementalReachability::add(const std::vector<GroundKey>& atoms,
                                  std::optional<std::chrono::steady_clock::time_point> deadline) {
  fixpoint_->add(atoms, Deadline(deadline));
}

}  // namespace alplan
