#include "benchmarks/differential/task_generator.h"

#include <algorithm>
#include <random>
#include <set>

#include "benchmarks/differential/task_model.h"
#include "pddl_parser/writer.h"

namespace alplan::differential {
namespace {

// Draws from the engine's raw output: std::uniform_int_distribution is not
// the same on every standard library, and a seed must name one task.
class Draw {
 public:
  explicit Draw(std::uint64_t seed) : engine_(seed * 0x9E3779B97F4A7C15ull + 7) {}
  int below(int n) { return n <= 1 ? 0 : static_cast<int>(engine_() % static_cast<std::uint64_t>(n)); }
  int between(int lo, int hi) { return lo + below(hi - lo + 1); }
  bool chance(int percent) { return below(100) < percent; }
  template <typename T>
  T& pick(std::vector<T>& v) { return v[static_cast<std::size_t>(below(static_cast<int>(v.size())))]; }

 private:
  std::mt19937_64 engine_;
};

std::string num(double x) { return pddl::format_number(x); }

class Generator {
 public:
  Generator(std::uint64_t seed, const GeneratorOptions& options) : draw_(seed), o_(options) {
    m_.name = "fuzz-" + std::to_string(seed);
  }

  TaskModel run() {
    const TaskFeatures& f = o_.features;
    m_.facts = draw_.between(3, std::max(3, o_.max_facts));
    if (draw_.chance(f.unary)) m_.unary = draw_.between(1, 2);
    negative_ = draw_.chance(f.negative_conditions);
    make_actions();
    plant_chain();
    if (draw_.chance(f.self_support)) self_support();
    if (draw_.chance(f.required_concurrency)) required_concurrency();
    if (draw_.chance(f.timed_literals)) timed_literals();
    if (draw_.chance(f.numeric)) numeric();
    if (draw_.chance(f.conditional_effects)) conditional_effect();
    if (draw_.chance(f.derived_predicates)) derived_predicate();
    if (draw_.chance(f.zero_duration)) zero_duration();
    if (draw_.chance(f.hard_constraints)) hard_constraint();
    if (draw_.chance(f.preferences)) preferences();
    decorate();
    initial_state();
    requirements();
    return m_;
  }

 private:
  std::string fact(int k) const { return "(f" + std::to_string(k) + ")"; }
  std::string any_fact() { return fact(draw_.below(m_.facts)); }
  // A fact an action may read or change: nullary, or unary on its parameter.
  std::string fact_for(const ActionModel& a) {
    if (m_.unary > 0 && draw_.chance(35)) {
      const std::string g = "(g" + std::to_string(draw_.below(m_.unary));
      return g + (a.parameter && draw_.chance(70) ? " ?x)" : " o" + std::to_string(draw_.between(1, m_.objects)) + ")");
    }
    return any_fact();
  }
  std::string literal_for(const ActionModel& a) {
    const std::string atom = fact_for(a);
    if (negative_ && draw_.chance(30)) return "(not " + atom + ")";
    return atom;
  }
  std::string duration_text(int quanta) { return "(= ?duration " + num(quanta * o_.quantum) + ")"; }
  std::vector<int> durative_indices() const {
    std::vector<int> out;
    for (std::size_t i = 0; i < m_.actions.size(); ++i) {
      if (m_.actions[i].durative) out.push_back(static_cast<int>(i));
    }
    return out;
  }
  ActionModel& action(int i) { return m_.actions[static_cast<std::size_t>(i)]; }
  double quanta_of(const ActionModel& a) const;
  void feature(const std::string& name) { m_.features.push_back(name); }

  void make_actions();
  void plant_chain();
  void decorate();
  void self_support();
  void required_concurrency();
  void timed_literals();
  void numeric();
  void numeric_chain();
  void simultaneous_change();
  void conditional_effect();
  void derived_predicate();
  void zero_duration();
  void hard_constraint();
  void preferences();
  void initial_state();
  void requirements();

  Draw draw_;
  GeneratorOptions o_;
  TaskModel m_;
  bool negative_ = false, ranges_ = false, tils_ = false, conditional_ = false;
  std::set<std::string> chain_facts_;  // never true at first
  std::vector<std::string> init_false_;
};

double Generator::quanta_of(const ActionModel& a) const {
  // The duration text of a fixed duration is "(= ?duration Q)".
  const std::string prefix = "(= ?duration ";
  if (a.duration.rfind(prefix, 0) != 0) return -1.0;
  return std::stod(a.duration.substr(prefix.size())) / o_.quantum;
}

void Generator::make_actions() {
  const int durative = draw_.between(1, std::max(1, o_.max_durative_actions));
  const int instant = draw_.between(durative == 1 ? 1 : 0, o_.max_instant_actions);
  for (int i = 0; i < durative + instant; ++i) {
    ActionModel a;
    a.durative = i < durative;
    a.name = (a.durative ? "d" : "i") + std::to_string(a.durative ? i : i - durative);
    a.parameter = m_.unary > 0 && draw_.chance(40);
    if (a.durative) {
      const int q = draw_.between(1, o_.max_duration_quanta);
      a.duration = duration_text(q);
      if (draw_.chance(o_.features.duration_range)) {
        ranges_ = true;
        a.duration = "(and (>= ?duration " + num(q * o_.quantum) + ") (<= ?duration " +
                     num((q + draw_.between(1, 3)) * o_.quantum) + "))";
      }
    }
    m_.actions.push_back(std::move(a));
  }
}

// The goal needs what the last action of the chain gives, each needing what
// the one before gives.
void Generator::plant_chain() {
  std::vector<int> order(m_.actions.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  for (std::size_t i = order.size(); i > 1; --i) std::swap(order[i - 1], order[static_cast<std::size_t>(draw_.below(static_cast<int>(i)))]);
  const int length = std::min(static_cast<int>(order.size()), draw_.chance(80) ? draw_.between(2, 3) : 1);
  std::vector<int> facts(static_cast<std::size_t>(m_.facts));
  for (int k = 0; k < m_.facts; ++k) facts[static_cast<std::size_t>(k)] = k;
  for (std::size_t i = facts.size(); i > 1; --i) std::swap(facts[i - 1], facts[static_cast<std::size_t>(draw_.below(static_cast<int>(i)))]);
  for (int i = 0; i < length; ++i) {
    ActionModel& a = action(order[static_cast<std::size_t>(i)]);
    const std::string given = fact(facts[static_cast<std::size_t>(i)]);
    chain_facts_.insert(given);
    if (!a.durative) {
      a.start_effects.push_back(given);
    } else {
      (draw_.chance(30) ? a.start_effects : a.end_effects).push_back(given);
    }
    if (i > 0) {
      const std::string needed = fact(facts[static_cast<std::size_t>(i - 1)]);
      if (!a.durative) {
        a.at_start.push_back(needed);
      } else {
        const int when = draw_.below(3);
        (when == 0 ? a.at_start : when == 1 ? a.over_all : a.at_end).push_back(needed);
      }
    }
  }
  m_.goal.push_back(fact(facts[static_cast<std::size_t>(length - 1)]));
  feature(length >= 2 ? "chain" : "single");
}

// Extra conditions and effects on every action. A condition mostly asks for
// a fact some effect or literal gives (or for one's absence), so that the
// plant survives in about half the tasks; an effect never gives the goal,
// so that the chain stays the way to it.
void Generator::decorate() {
  std::vector<std::string> given;
  for (const ActionModel& a : m_.actions) {
    for (const auto* effects : {&a.start_effects, &a.end_effects}) {
      for (const std::string& e : *effects) {
        if (e.rfind("(f", 0) == 0) given.push_back(e);
      }
    }
  }
  for (ActionModel& a : m_.actions) {
    for (int n = draw_.between(0, 1); n > 0; --n) {
      std::vector<std::string>& where = !a.durative ? a.at_start
                                        : draw_.chance(50) ? a.at_start
                                        : draw_.chance(50) ? a.over_all
                                                           : a.at_end;
      if (!given.empty() && draw_.chance(60)) {
        const std::string f = draw_.pick(given);
        where.push_back(negative_ && draw_.chance(25) ? "(not " + f + ")" : f);
      } else {
        where.push_back(literal_for(a));
      }
    }
    for (int n = draw_.between(0, 2); n > 0; --n) {
      const std::string atom = fact_for(a);
      const bool add = draw_.chance(60);
      if (add && std::find(m_.goal.begin(), m_.goal.end(), atom) != m_.goal.end()) continue;
      (a.durative && draw_.chance(50) ? a.end_effects : a.start_effects).push_back(add ? atom : "(not " + atom + ")");
    }
  }
}

// An action that gives itself its own over-all condition at its start.
void Generator::self_support() {
  std::vector<int> durative = durative_indices();
  if (durative.empty()) return;
  ActionModel& a = action(draw_.pick(durative));
  const std::string s = fact_for(a);
  a.start_effects.push_back(s);
  a.over_all.push_back(s);
  if (draw_.chance(60)) a.end_effects.push_back("(not " + s + ")");
  chain_facts_.insert(s);
  feature("self_support");
}

// A provider whose start gives what a holder needs over all and whose end
// takes it back: the holder must run inside it, sometimes exactly as long.
void Generator::required_concurrency() {
  std::vector<int> durative = durative_indices();
  if (durative.size() < 2) return;
  const int p = draw_.pick(durative);
  int h = p;
  while (h == p) h = draw_.pick(durative);
  ActionModel& provider = action(p);
  ActionModel& holder = action(h);
  const std::string r = any_fact();
  provider.start_effects.push_back(r);
  provider.end_effects.push_back("(not " + r + ")");
  (draw_.chance(80) ? holder.over_all : holder.at_end).push_back(r);
  const double q = quanta_of(provider);
  if (q > 0 && quanta_of(holder) > 0) {
    holder.duration = duration_text(draw_.chance(40) ? static_cast<int>(q) : draw_.between(1, static_cast<int>(q)));
  }
  chain_facts_.insert(r);
  feature("required_concurrency");
}

// Windows that timed literals open and close, at fractional times, shorter
// than, as long as or longer than the action that needs them; a fact only a
// literal gives; a fact a literal takes away.
void Generator::timed_literals() {
  tils_ = true;
  feature("timed_literals");
  for (int n = draw_.between(1, 2); n > 0; --n) {
    ActionModel& a = draw_.pick(m_.actions);
    const std::string w = any_fact();
    const double open = draw_.between(1, 8) * o_.quantum / (draw_.chance(30) ? 2.0 : 1.0);
    const double q = a.durative ? std::max(0.0, quanta_of(a)) : 0.0;
    const int shape = draw_.below(3);  // shorter, as long as, longer than the action
    const double length = (shape == 0   ? std::max(0.5, q - 1.0)
                           : shape == 1 ? std::max(0.5, q)
                                        : q + draw_.between(1, 3)) * o_.quantum;
    m_.init.push_back("(at " + num(open) + " " + w + ")");
    if (draw_.chance(85)) m_.init.push_back("(at " + num(open + length) + " (not " + w + "))");
    init_false_.push_back(w);
    if (!a.durative) {
      a.at_start.push_back(w);
    } else {
      const int when = draw_.below(3);
      (when == 0 ? a.at_start : when == 1 ? a.over_all : a.at_end).push_back(w);
    }
  }
  if (draw_.chance(30)) {
    const std::string gone = any_fact();
    m_.init.push_back(gone);
    m_.init.push_back("(at " + num(draw_.between(1, 6) * o_.quantum) + " (not " + gone + "))");
  }
}

void Generator::numeric() {
  const TaskFeatures& f = o_.features;
  m_.fluents = draw_.between(1, 3);
  feature("numeric");
  auto fluent = [&] { return "(x" + std::to_string(draw_.below(m_.fluents)) + ")"; };
  for (ActionModel& a : m_.actions) {
    if (draw_.chance(55)) {
      std::string effect;
      const std::string target = fluent();
      if (draw_.chance(f.assign_or_scale)) {
        effect = draw_.chance(50) ? "(assign " + target + " " + std::to_string(draw_.between(0, 3)) + ")"
                                  : "(scale-up " + target + " 2)";
        feature("assign_or_scale");
      } else if (m_.fluents > 1 && draw_.chance(f.amount_from_fluent)) {
        std::string other = fluent();
        while (other == target) other = fluent();
        effect = "(increase " + target + " " + other + ")";
        feature("amount_from_fluent");
      } else {
        effect = "(" + std::string(draw_.chance(65) ? "increase" : "decrease") + " " + target + " 1)";
      }
      (a.durative && draw_.chance(50) ? a.end_effects : a.start_effects).push_back(effect);
    }
    if (draw_.chance(35)) {
      static const char* const ops[] = {">", ">=", "<", "<=", "="};
      std::string c = "(" + std::string(ops[draw_.below(5)]) + " " + fluent() + " ";
      if (m_.fluents > 1 && draw_.chance(f.fluent_comparison)) {
        c += fluent() + ")";
        feature("fluent_comparison");
      } else {
        c += std::to_string(draw_.between(0, 2)) + ")";
      }
      (!a.durative || draw_.chance(50) ? a.at_start : draw_.chance(50) ? a.over_all : a.at_end).push_back(c);
    }
  }
  for (int x = 0; x < m_.fluents; ++x) m_.init.push_back("(= (x" + std::to_string(x) + ") " + std::to_string(draw_.between(0, 2)) + ")");
  if (draw_.chance(30)) m_.goal.push_back("(>= " + fluent() + " " + std::to_string(draw_.between(1, 3)) + ")");
  if (m_.fluents > 1 && draw_.chance(35)) numeric_chain();
  if (draw_.chance(f.simultaneous_change)) simultaneous_change();
}

// One action raises y, another adds y to x, a third needs x: the amount is
// read when the second acts (issue 42's first case).
void Generator::numeric_chain() {
  if (m_.actions.size() < 2) return;
  ActionModel& raise = draw_.pick(m_.actions);
  ActionModel& copy = draw_.pick(m_.actions);
  ActionModel& use = draw_.pick(m_.actions);
  (raise.durative ? raise.end_effects : raise.start_effects).push_back("(increase (x1) 1)");
  (copy.durative ? copy.end_effects : copy.start_effects).push_back("(increase (x0) (x1))");
  use.at_start.push_back("(>= (x0) " + std::to_string(draw_.between(1, 2)) + ")");
  feature("numeric_chain");
}

// Two actions that both change x at their starts, inside a window too short
// for them to be apart: only together, in one happening, as VAL allows
// additive changes.
void Generator::simultaneous_change() {
  std::vector<int> durative = durative_indices();
  if (durative.size() < 2) return;
  const int a = draw_.pick(durative);
  int b = a;
  while (b == a) b = draw_.pick(durative);
  const std::string w = any_fact();
  const double open = draw_.between(1, 4) * o_.quantum;
  m_.init.push_back("(at " + num(open) + " " + w + ")");
  m_.init.push_back("(at " + num(open + 0.0015) + " (not " + w + "))");
  init_false_.push_back(w);
  for (int k : {a, b}) {
    action(k).at_start.push_back(w);
    action(k).start_effects.push_back("(increase (x0) 1)");
  }
  m_.goal.push_back("(>= (x0) 2)");
  tils_ = true;
  feature("simultaneous_change");
}

// A conditional effect, its condition read when it takes effect: written
// (when (at end c) (at end e)) in durative actions, the form VAL reads (it
// refuses (at end (when c e)) with a constant in c). (when (at start c)
// (at end e)) is PDDL 2.1 too, but the planner refuses it (exit 2), so it
// is not drawn: a test of what it plans.
void Generator::conditional_effect() {
  ActionModel& a = draw_.pick(m_.actions);
  const std::string c = literal_for(a), e = fact_for(a);
  conditional_ = true;
  if (!a.durative) {
    a.effects.push_back("(when " + c + " " + e + ")");
  } else {
    const std::string when = draw_.chance(50) ? "at end" : "at start";
    a.effects.push_back("(when (" + when + " " + c + ") (" + when + " " + e + "))");
  }
  feature("conditional_effect");
}

void Generator::derived_predicate() {
  const std::string a = any_fact(), b = any_fact();
  std::string body;
  switch (draw_.below(m_.fluents > 0 ? 3 : 2)) {
    case 0: body = "(and " + a + " (not " + b + "))"; break;
    case 1: body = "(or " + a + " " + b + ")"; break;
    default: body = "(>= (x0) " + std::to_string(draw_.between(1, 2)) + ")"; break;
  }
  m_.derived.push_back("(:derived (d0) " + body + ")");
  const std::string use = draw_.chance(75) ? "(d0)" : "(not (d0))";
  if (draw_.chance(40)) {
    m_.goal.push_back(use);
  } else {
    ActionModel& user = draw_.pick(m_.actions);
    (!user.durative || draw_.chance(50) ? user.at_start : user.over_all).push_back(use);
  }
  if (use != "(d0)") negative_ = true;
  feature("derived_predicate");
}

void Generator::zero_duration() {
  std::vector<int> durative = durative_indices();
  if (durative.empty()) return;
  action(draw_.pick(durative)).duration = "(= ?duration 0)";
  feature("zero_duration");
}

void Generator::hard_constraint() {
  const std::string f = any_fact();
  switch (draw_.below(4)) {
    case 0: m_.constraints.push_back("(always (not " + f + "))"); break;
    case 1: m_.constraints.push_back("(sometime " + f + ")"); break;
    case 2: m_.constraints.push_back("(within " + num(draw_.between(2, 10) * o_.quantum) + " " + f + ")"); break;
    default: m_.constraints.push_back("(at end " + f + ")"); break;
  }
  feature("hard_constraint");
}

void Generator::preferences() {
  m_.goal.push_back("(preference pg " + any_fact() + ")");
  m_.metric_terms.push_back("(* 3 (is-violated pg))");
  ActionModel& a = draw_.pick(m_.actions);
  const std::string c = literal_for(a);
  a.conditions.push_back(a.durative ? "(preference pp (at start " + c + "))" : "(preference pp " + c + ")");
  m_.metric_terms.push_back("(* 2 (is-violated pp))");
  feature("preferences");
}

void Generator::initial_state() {
  std::set<std::string> excluded(chain_facts_.begin(), chain_facts_.end());
  excluded.insert(init_false_.begin(), init_false_.end());
  for (int k = 0; k < m_.facts; ++k) {
    if (!excluded.count(fact(k)) && draw_.chance(35)) m_.init.push_back(fact(k));
  }
  for (int g = 0; g < m_.unary; ++g) {
    for (int o = 1; o <= m_.objects; ++o) {
      if (draw_.chance(35)) m_.init.push_back("(g" + std::to_string(g) + " o" + std::to_string(o) + ")");
    }
  }
}

void Generator::requirements() {
  std::vector<std::string>& r = m_.requirements;
  r = {":strips", ":typing", ":durative-actions"};
  bool negative = negative_;
  for (const std::string& g : m_.goal) negative = negative || g.find("(not") != std::string::npos;
  if (negative) r.push_back(":negative-preconditions");
  if (ranges_) r.push_back(":duration-inequalities");
  if (tils_) r.push_back(":timed-initial-literals");
  if (m_.fluents > 0) r.push_back(":numeric-fluents");
  if (conditional_) r.push_back(":conditional-effects");
  if (!m_.derived.empty()) r.push_back(":derived-predicates");
  if (!m_.constraints.empty()) r.push_back(":constraints");
  if (!m_.metric_terms.empty()) r.push_back(":preferences");
}

}  // namespace

GeneratedTask generate_task(std::uint64_t seed, const GeneratorOptions& options) {
  const TaskModel model = Generator(seed, options).run();
  GeneratedTask task;
  task.name = model.name;
  task.domain = write_domain(model);
  task.problem = write_problem(model);
  task.features = model.features;
  std::sort(task.features.begin(), task.features.end());
  task.features.erase(std::unique(task.features.begin(), task.features.end()), task.features.end());
  return task;
}

}  // namespace alplan::differential
