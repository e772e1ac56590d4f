#include "benchmarks/differential/random_task.h"

#include <algorithm>
#include <random>
#include <sstream>
#include <vector>

namespace alplan::differential {
namespace {

// Draws from the engine's raw output: std::uniform_int_distribution is not
// the same on every standard library, and a seed must name one task.
class Draw {
 public:
  explicit Draw(std::uint64_t seed) : engine_(seed * 0x9E3779B97F4A7C15ull + 1) {}
  int below(int n) { return n <= 1 ? 0 : static_cast<int>(engine_() % static_cast<std::uint64_t>(n)); }
  int between(int lo, int hi) { return lo + below(hi - lo + 1); }
  bool chance(int percent) { return below(100) < percent; }

 private:
  std::mt19937_64 engine_;
};

// A proposition as an action sees it: a nullary predicate, or a unary one on
// the action's parameter (or on a constant when it has none).
struct Atom {
  int predicate = 0;  // < nullary: p<i>; else q<i - nullary>
  int object = -1;    // unary: the constant's index, -1 for the parameter
};

struct Literal {
  Atom atom;
  bool positive = true;
};

struct NumericPart {
  std::string text;
};

struct ActionModel {
  std::string name;
  bool durative = true;
  bool parameter = false;
  int min_duration = 1, max_duration = 1;  // equal: (= ?duration d)
  std::vector<Literal> at_start, over_all, at_end;
  std::vector<Literal> start_effects, end_effects;
  std::vector<std::string> numeric_conditions;  // already timed for durative actions
  std::vector<std::string> numeric_effects;
};

class Generator {
 public:
  Generator(std::uint64_t seed, const RandomTaskOptions& options) : draw_(seed), options_(options), seed_(seed) {}
  RandomTask run();

 private:
  Atom random_atom(bool parameter) {
    Atom a;
    a.predicate = draw_.below(nullary_ + unary_);
    if (a.predicate >= nullary_) a.object = parameter && draw_.chance(70) ? -1 : draw_.below(options_.objects);
    return a;
  }
  Literal random_literal(bool parameter, bool may_be_negative) {
    return {random_atom(parameter), !(may_be_negative && draw_.chance(options_.negative_conditions))};
  }
  std::string atom_text(const Atom& a, const std::string& parameter_name) const {
    if (a.predicate < nullary_) return "(p" + std::to_string(a.predicate) + ")";
    const std::string arg = a.object < 0 ? parameter_name : "k" + std::to_string(a.object);
    return "(q" + std::to_string(a.predicate - nullary_) + " " + arg + ")";
  }
  std::string literal_text(const Literal& l, const std::string& parameter_name) const {
    const std::string atom = atom_text(l.atom, parameter_name);
    return l.positive ? atom : "(not " + atom + ")";
  }
  ActionModel random_action(int index, bool durative);
  void plant_self_support(ActionModel& a);
  void plant_required_concurrency();
  void plant_numeric();
  std::string write_domain() const;
  std::string write_problem();

  Draw draw_;
  RandomTaskOptions options_;
  std::uint64_t seed_;
  int nullary_ = 1, unary_ = 0;
  bool negative_ = false, numeric_ = false, ranges_ = false, literals_ = false;
  std::vector<ActionModel> actions_;
};

ActionModel Generator::random_action(int index, bool durative) {
  ActionModel a;
  a.durative = durative;
  a.name = (durative ? "d" : "i") + std::to_string(index);
  a.parameter = unary_ > 0 && draw_.chance(40);
  auto literals = [&](int lo, int hi, bool conditions) {
    std::vector<Literal> out;
    for (int n = draw_.between(lo, hi); n > 0; --n) out.push_back(random_literal(a.parameter, conditions && negative_));
    return out;
  };
  if (!durative) {
    a.at_start = literals(0, 2, true);
    a.start_effects = literals(1, 2, false);
    for (Literal& l : a.start_effects) l.positive = draw_.chance(65);
    return a;
  }
  if (draw_.chance(5)) {
    a.min_duration = a.max_duration = 0;
  } else {
    a.min_duration = draw_.between(1, options_.max_duration);
    a.max_duration = a.min_duration;
    if (draw_.chance(options_.duration_range)) {
      ranges_ = true;
      a.max_duration = draw_.between(a.min_duration, options_.max_duration + 1);
    }
  }
  a.at_start = literals(0, 2, true);
  a.over_all = literals(0, 1, true);
  a.at_end = literals(0, 1, true);
  a.start_effects = literals(0, 2, false);
  for (Literal& l : a.start_effects) l.positive = draw_.chance(50);
  a.end_effects = literals(1, 2, false);
  for (Literal& l : a.end_effects) l.positive = draw_.chance(70);
  return a;
}

// The action gives itself its own over-all condition at start (and may take
// it back at its end): a relaxation that checks the invariant before the
// start's effects never lets it start.
void Generator::plant_self_support(ActionModel& a) {
  const Atom f = random_atom(a.parameter);
  a.start_effects.push_back({f, true});
  a.over_all.push_back({f, true});
  if (draw_.chance(60)) a.end_effects.push_back({f, false});
}

// A provider whose start gives a fact its end takes back, and a holder that
// needs the fact over all: the holder must run inside the provider.
void Generator::plant_required_concurrency() {
  std::vector<int> durative;
  for (int i = 0; i < static_cast<int>(actions_.size()); ++i) {
    if (actions_[static_cast<std::size_t>(i)].durative) durative.push_back(i);
  }
  if (durative.size() < 2) return;
  const int p = durative[static_cast<std::size_t>(draw_.below(static_cast<int>(durative.size())))];
  int h = p;
  while (h == p) h = durative[static_cast<std::size_t>(draw_.below(static_cast<int>(durative.size())))];
  ActionModel& provider = actions_[static_cast<std::size_t>(p)];
  ActionModel& holder = actions_[static_cast<std::size_t>(h)];
  Atom f;
  f.predicate = draw_.below(nullary_);
  provider.start_effects.push_back({f, true});
  provider.end_effects.push_back({f, false});
  (draw_.chance(70) ? holder.over_all : holder.at_end).push_back({f, true});
  // Sometimes the holder fits inside the provider only if it starts late.
  if (draw_.chance(40) && !holder.at_end.empty()) holder.at_end.push_back({random_atom(holder.parameter), true});
}

// A counter: increased and decreased by actions, compared in conditions.
void Generator::plant_numeric() {
  numeric_ = true;
  for (ActionModel& a : actions_) {
    const bool both = a.durative;
    if (draw_.chance(60)) {
      const std::string when = both ? (draw_.chance(50) ? "at start " : "at end ") : "";
      const std::string op = draw_.chance(60) ? "increase" : "decrease";
      std::string e = "(" + op + " (c) 1)";
      a.numeric_effects.push_back(both ? "(" + when + e + ")" : e);
      // A borrow: what the start takes the end gives back (a lit match).
      if (both && when == "at start " && draw_.chance(40)) {
        a.numeric_effects.push_back(std::string("(at end (") + (op == "increase" ? "decrease" : "increase") +
                                    " (c) 1))");
      }
    }
    if (draw_.chance(40)) {
      const char* comparisons[] = {">", ">=", "<", "<="};
      const std::string cmp = comparisons[draw_.below(4)];
      const std::string c = "(" + cmp + " (c) " + std::to_string(draw_.between(0, 2)) + ")";
      const char* times[] = {"at start", "at end", "over all"};
      a.numeric_conditions.push_back(both ? "(" + std::string(times[draw_.below(3)]) + " " + c + ")" : c);
    }
  }
}

std::string Generator::write_domain() const {
  std::ostringstream d;
  d << "(define (domain fuzz-" << seed_ << ")\n  (:requirements :strips :typing :durative-actions";
  if (negative_) d << " :negative-preconditions";
  if (literals_) d << " :timed-initial-literals";
  if (numeric_) d << " :numeric-fluents";
  if (ranges_) d << " :duration-inequalities";
  d << ")\n  (:types thing)\n";
  if (unary_ > 0) {
    d << "  (:constants";
    for (int o = 0; o < options_.objects; ++o) d << " k" << o;
    d << " - thing)\n";
  }
  d << "  (:predicates";
  for (int p = 0; p < nullary_; ++p) d << " (p" << p << ")";
  for (int q = 0; q < unary_; ++q) d << " (q" << q << " ?o - thing)";
  d << ")\n";
  if (numeric_) d << "  (:functions (c))\n";
  for (const ActionModel& a : actions_) {
    const std::string parameter = a.parameter ? "?x" : "";
    auto conjunction = [&](const std::vector<std::string>& parts) {
      if (parts.empty()) return std::string("(and)");
      if (parts.size() == 1) return parts.front();
      std::string s = "(and";
      for (const std::string& p : parts) s += " " + p;
      return s + ")";
    };
    auto timed = [&](const char* when, const std::vector<Literal>& ls, std::vector<std::string>& out) {
      for (const Literal& l : ls) out.push_back("(" + std::string(when) + " " + literal_text(l, parameter) + ")");
    };
    if (a.durative) {
      d << "  (:durative-action " << a.name << "\n    :parameters (" << (a.parameter ? "?x - thing" : "") << ")\n";
      if (a.min_duration == a.max_duration) {
        d << "    :duration (= ?duration " << a.min_duration << ")\n";
      } else {
        d << "    :duration (and (>= ?duration " << a.min_duration << ") (<= ?duration " << a.max_duration << "))\n";
      }
      std::vector<std::string> conditions, effects;
      timed("at start", a.at_start, conditions);
      timed("over all", a.over_all, conditions);
      timed("at end", a.at_end, conditions);
      conditions.insert(conditions.end(), a.numeric_conditions.begin(), a.numeric_conditions.end());
      timed("at start", a.start_effects, effects);
      timed("at end", a.end_effects, effects);
      effects.insert(effects.end(), a.numeric_effects.begin(), a.numeric_effects.end());
      d << "    :condition " << conjunction(conditions) << "\n    :effect " << conjunction(effects) << ")\n";
    } else {
      d << "  (:action " << a.name << "\n    :parameters (" << (a.parameter ? "?x - thing" : "") << ")\n";
      std::vector<std::string> conditions, effects;
      for (const Literal& l : a.at_start) conditions.push_back(literal_text(l, parameter));
      conditions.insert(conditions.end(), a.numeric_conditions.begin(), a.numeric_conditions.end());
      for (const Literal& l : a.start_effects) effects.push_back(literal_text(l, parameter));
      effects.insert(effects.end(), a.numeric_effects.begin(), a.numeric_effects.end());
      d << "    :precondition " << conjunction(conditions) << "\n    :effect " << conjunction(effects) << ")\n";
    }
  }
  d << ")\n";
  return d.str();
}

std::string Generator::write_problem() {
  std::ostringstream p;
  p << "(define (problem fuzz-" << seed_ << "-1)\n  (:domain fuzz-" << seed_ << ")\n  (:init";
  auto ground_atom = [&](int predicate, int object) {
    Atom a;
    a.predicate = predicate;
    a.object = object;
    return atom_text(a, "");
  };
  std::vector<std::string> atoms;
  for (int i = 0; i < nullary_; ++i) atoms.push_back(ground_atom(i, 0));
  for (int q = 0; q < unary_; ++q) {
    for (int o = 0; o < options_.objects; ++o) atoms.push_back(ground_atom(nullary_ + q, o));
  }
  for (const std::string& a : atoms) {
    if (draw_.chance(35)) p << " " << a;
  }
  if (numeric_) p << " (= (c) " << draw_.between(0, 1) << ")";
  if (literals_) {
    for (int n = draw_.between(1, 2); n > 0; --n) {
      const std::string& a = atoms[static_cast<std::size_t>(draw_.below(static_cast<int>(atoms.size())))];
      const int t = draw_.between(1, options_.max_literal_time);
      p << " (at " << t << " " << (draw_.chance(55) ? a : "(not " + a + ")") << ")";
      // A window: given at t, taken away a little later.
      if (draw_.chance(40)) p << " (at " << t + draw_.between(1, 4) << " (not " << a << "))";
    }
  }
  p << ")\n  (:goal ";
  std::vector<std::string> goals;
  for (int n = draw_.between(1, 2); n > 0; --n) {
    const std::string& a = atoms[static_cast<std::size_t>(draw_.below(static_cast<int>(atoms.size())))];
    if (draw_.chance(85)) {
      goals.push_back(a);
    } else {
      goals.push_back("(not " + a + ")");
      negative_ = true;
    }
  }
  if (numeric_ && draw_.chance(40)) goals.push_back("(>= (c) " + std::to_string(draw_.between(1, 3)) + ")");
  std::sort(goals.begin(), goals.end());
  goals.erase(std::unique(goals.begin(), goals.end()), goals.end());
  if (goals.size() == 1) {
    p << goals.front();
  } else {
    p << "(and";
    for (const std::string& g : goals) p << " " << g;
    p << ")";
  }
  p << ")\n  (:metric minimize (total-time)))\n";
  return p.str();
}

RandomTask Generator::run() {
  nullary_ = draw_.between(2, std::max(2, options_.max_nullary));
  unary_ = draw_.between(0, options_.max_unary);
  negative_ = draw_.chance(50);
  literals_ = draw_.chance(options_.timed_literals);
  const int durative = draw_.between(1, std::max(1, options_.max_durative_actions));
  const int instant = draw_.between(0, options_.max_instant_actions);
  for (int i = 0; i < durative; ++i) actions_.push_back(random_action(i, true));
  for (int i = 0; i < instant; ++i) actions_.push_back(random_action(i, false));
  for (ActionModel& a : actions_) {
    if (a.durative && draw_.chance(options_.self_support)) plant_self_support(a);
  }
  if (draw_.chance(options_.required_concurrency)) plant_required_concurrency();
  if (draw_.chance(options_.numeric)) plant_numeric();
  // A literal both added and deleted by one happening is legal PDDL but says
  // nothing a test needs; keep the add.
  for (ActionModel& a : actions_) {
    for (std::vector<Literal>* effects : {&a.start_effects, &a.end_effects}) {
      std::vector<Literal> kept;
      for (const Literal& l : *effects) {
        const auto same_atom = [&](const Literal& k) {
          return k.atom.predicate == l.atom.predicate && k.atom.object == l.atom.object;
        };
        auto it = std::find_if(kept.begin(), kept.end(), same_atom);
        if (it == kept.end()) {
          kept.push_back(l);
        } else if (l.positive) {
          it->positive = true;
        }
      }
      *effects = std::move(kept);
    }
  }
  RandomTask task;
  task.name = "fuzz-" + std::to_string(seed_);
  task.problem = write_problem();  // draws the initial state first, then
  task.domain = write_domain();    // writes what the actions need declared
  return task;
}

}  // namespace

RandomTask random_task(std::uint64_t seed, const RandomTaskOptions& options) {
  return Generator(seed, options).run();
}

}  // namespace alplan::differential
