#include "planner/search_configuration.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

namespace alplan {
namespace {

// The expression as a tree of calls, before any meaning is given to it.
struct Call {
  std::string name;
  std::size_t at = 0;  // offset of the name
  struct Argument {
    std::string key;  // empty: positional
    std::size_t at = 0;
    std::shared_ptr<Call> call;  // a pointer: Call is not complete here
    std::optional<double> number;
    std::vector<double> list;
    bool is_list = false;
  };
  std::vector<Argument> arguments;
};

class Reader {
 public:
  explicit Reader(std::string_view text) : text_(text) {}

  Call read_all() {
    Call call = read_call();
    skip_space();
    if (pos_ != text_.size()) fail("unexpected '" + std::string(1, text_[pos_]) + "' after the configuration");
    return call;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw SearchConfigurationError("search configuration, at character " + std::to_string(pos_ + 1) + ": " + what);
  }
  void skip_space() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }
  bool take(char c) {
    skip_space();
    if (pos_ < text_.size() && text_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }
  std::string read_name() {
    skip_space();
    const std::size_t from = pos_;
    while (pos_ < text_.size() && (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_' ||
                                   (pos_ > from && text_[pos_] == '-'))) {
      ++pos_;
    }
    if (pos_ == from || std::isdigit(static_cast<unsigned char>(text_[from]))) {
      pos_ = from;
      fail(pos_ < text_.size() ? "expected a name, found '" + std::string(1, text_[pos_]) + "'"
                               : "expected a name, found the end");
    }
    return std::string(text_.substr(from, pos_ - from));
  }
  std::optional<double> read_number() {
    skip_space();
    if (pos_ >= text_.size()) return std::nullopt;
    const char c = text_[pos_];
    if (!std::isdigit(static_cast<unsigned char>(c)) && c != '.' && c != '-' && c != '+') return std::nullopt;
    const std::string rest(text_.substr(pos_));
    char* end = nullptr;
    const double value = std::strtod(rest.c_str(), &end);
    if (end == rest.c_str() || !std::isfinite(value)) fail("expected a number");
    pos_ += static_cast<std::size_t>(end - rest.c_str());
    return value;
  }
  Call read_call() {
    if (++depth_ > 32) fail("nested too deeply");
    Call call;
    skip_space();
    call.at = pos_;
    call.name = read_name();
    if (take('(')) {
      if (!take(')')) {
        do {
          call.arguments.push_back(read_argument());
        } while (take(','));
        if (!take(')')) fail(pos_ < text_.size() ? "expected ',' or ')'" : "expected ')', found the end");
      }
    }
    --depth_;
    return call;
  }
  Call::Argument read_argument() {
    Call::Argument a;
    skip_space();
    a.at = pos_;
    if (take('[')) {
      a.is_list = true;
      if (!take(']')) {
        do {
          const std::optional<double> n = read_number();
          if (!n) fail("expected a number in the list");
          a.list.push_back(*n);
        } while (take(','));
        if (!take(']')) fail("expected ',' or ']'");
      }
      return a;
    }
    if ((a.number = read_number())) return a;
    Call c = read_call();
    if (c.arguments.empty() && take('=')) {
      a.key = c.name;
      skip_space();
      a.at = pos_;
      if (take('[')) {
        --pos_;
        Call::Argument v = read_argument();
        a.is_list = true;
        a.list = v.list;
        return a;
      }
      if ((a.number = read_number())) return a;
      a.call = std::make_shared<Call>(read_call());
      return a;
    }
    a.call = std::make_shared<Call>(std::move(c));
    return a;
  }

  std::string_view text_;
  std::size_t pos_ = 0;
  int depth_ = 0;
};

[[noreturn]] void fail_at(std::size_t at, const std::string& what) {
  throw SearchConfigurationError("search configuration, at character " + std::to_string(at + 1) + ": " + what);
}

bool boolean(const Call::Argument& a) {
  if (a.call && a.call->arguments.empty() && (a.call->name == "true" || a.call->name == "false")) {
    return a.call->name == "true";
  }
  fail_at(a.at, a.key + " takes true or false");
}

double number(const Call::Argument& a, double least) {
  if (!a.number) fail_at(a.at, a.key + " takes a number");
  if (*a.number < least) fail_at(a.at, a.key + " must be at least " + std::to_string(least));
  return *a.number;
}

HeuristicSpec heuristic_of(const Call& c) {
  HeuristicSpec h;
  if (c.name == "blind") {
    h.kind = HeuristicSpec::Kind::Blind;
    if (!c.arguments.empty()) fail_at(c.at, "blind takes no options");
    return h;
  }
  if (c.name == "lmcut") {
    h.kind = HeuristicSpec::Kind::LmCut;
    if (!c.arguments.empty()) fail_at(c.at, "lmcut takes no options");
    return h;
  }
  if (c.name != "trpg") fail_at(c.at, "unknown heuristic '" + c.name + "' (expected trpg, blind or lmcut)");
  for (const Call::Argument& a : c.arguments) {
    if (a.key == "helpful") h.helpful = boolean(a);
    else if (a.key == "repetitions") h.repetitions = boolean(a);
    else if (a.key == "balance") h.balance = boolean(a);
    else fail_at(a.at, "trpg has no option '" + a.key + "' (helpful, repetitions, balance)");
  }
  return h;
}

EngineSpec engine_of(const Call& c);

// Options every phase takes: its budget.
bool budget_option(EngineSpec& e, const Call::Argument& a) {
  if (a.key == "expansions") {
    e.expansions = static_cast<std::uint64_t>(number(a, 0));
  } else if (a.key == "time_share") {
    e.time_share = number(a, 0);
    if (e.time_share > 1) fail_at(a.at, "time_share is a share of the time limit, at most 1");
  } else {
    return false;
  }
  return true;
}

EngineSpec leaf_of(const Call& c, EngineSpec::Kind kind) {
  EngineSpec e;
  e.kind = kind;
  bool heuristic_given = false;
  for (const Call::Argument& a : c.arguments) {
    if (a.key.empty()) {
      if (heuristic_given || !a.call) fail_at(a.at, c.name + " takes one heuristic, then options by name");
      e.heuristic = heuristic_of(*a.call);
      heuristic_given = true;
      continue;
    }
    if (budget_option(e, a)) continue;
    if (a.key == "share" && kind != EngineSpec::Kind::Ehc) {
      e.share = number(a, 0);
      if (e.share <= 0 || e.share > 1) fail_at(a.at, "share is a share of the portfolio's expansions, in (0, 1]");
      continue;
    }
    if (a.key == "share_after" && kind != EngineSpec::Kind::Ehc) {
      e.share_after = static_cast<std::uint64_t>(number(a, 0));
      continue;
    }
    const bool greedy = kind == EngineSpec::Kind::Gbfs, weighted = kind == EngineSpec::Kind::Wastar;
    if (a.key == "goal_orders" && kind != EngineSpec::Kind::Wastar) {
      e.goal_orders = boolean(a);
    } else if (a.key == "children" && kind == EngineSpec::Kind::Ehc) {
      if (!a.call || (a.call->name != "makespan" && a.call->name != "listed")) fail_at(a.at, "children is makespan or listed");
      e.makespan_first = a.call->name == "makespan";
    } else if (a.key == "ties" && (greedy || weighted)) {
      if (!a.call || (a.call->name != "fifo" && a.call->name != "makespan")) fail_at(a.at, "ties is fifo or makespan");
      e.makespan_ties = a.call->name == "makespan";
    } else if (a.key == "queue" && greedy) {
      if (!a.call || (a.call->name != "plain" && a.call->name != "typed")) fail_at(a.at, "queue is plain or typed");
      e.typed = a.call->name == "typed";
    } else if (a.key == "novelty" && greedy) {
      const double n = number(a, 0);
      if (n != 0 && n != 1 && n != 2) fail_at(a.at, "novelty is 0, 1 or 2");
      e.novelty = static_cast<int>(n);
    } else if (a.key == "deferred" && (greedy || weighted)) {
      e.deferred = boolean(a);
    } else if (a.key == "preferred" && (greedy || weighted)) {
      e.preferred = boolean(a);
    } else if (a.key == "w" && weighted) {
      e.weight = number(a, 0);
      if (e.weight <= 0) fail_at(a.at, "w must be positive");
    } else if (a.key == "order" && weighted) {
      if (!a.call || (a.call->name != "steps" && a.call->name != "metric")) fail_at(a.at, "order is steps or metric");
      e.metric_order = a.call->name == "metric";
    } else {
      fail_at(a.at, c.name + " has no option '" + a.key + "'");
    }
  }
  return e;
}

// portfolio(E, ...) and then(E, ...).
EngineSpec combination_of(const Call& c) {
  using K = EngineSpec::Kind;
  EngineSpec e;
  e.kind = c.name == "then" ? K::Then : K::Portfolio;
  for (const Call::Argument& a : c.arguments) {
    if (!a.key.empty()) {
      if (e.kind == K::Portfolio && budget_option(e, a)) continue;
      if (e.kind == K::Portfolio && a.key == "turns") {
        if (!a.call || (a.call->name != "expansions" && a.call->name != "evaluations")) {
          fail_at(a.at, "turns is expansions or evaluations");
        }
        e.share_evaluations = a.call->name == "evaluations";
        continue;
      }
      fail_at(a.at, c.name + " has no option '" + a.key + "'");
    }
    if (!a.call) fail_at(a.at, c.name + " takes engines");
    EngineSpec child = engine_of(*a.call);
    if (child.kind == K::Preferences) fail_at(a.at, "preferences goes outermost");
    if (e.kind == K::Portfolio && (child.kind == K::Portfolio || child.kind == K::Then || child.kind == K::Anytime)) {
      fail_at(a.at, "a portfolio takes ehc, gbfs and wastar engines");
    }
    if (e.kind == K::Then && child.kind == K::Anytime) fail_at(a.at, "anytime goes around a then, not inside");
    e.children.push_back(std::move(child));
  }
  if (e.children.empty()) fail_at(c.at, c.name + " takes at least one engine");
  return e;
}

// improve=neighbourhood(by=states|actions, depth=D, max_depth=M), anytime's
// plan improvement.
void neighbourhood_of(const Call::Argument& a, EngineSpec& e) {
  if (!a.call || a.call->name != "neighbourhood") {
    fail_at(a.at, "improve is neighbourhood(by=states|actions, depth=D, max_depth=M)");
  }
  e.neighbourhood_depth = 1;
  bool max_given = false;
  for (const Call::Argument& o : a.call->arguments) {
    if (o.key == "by") {
      if (!o.call || (o.call->name != "states" && o.call->name != "actions")) fail_at(o.at, "by is states or actions");
      e.neighbourhood_actions = o.call->name == "actions";
      continue;
    }
    if (o.key != "depth" && o.key != "max_depth") fail_at(o.at, "neighbourhood has no option '" + o.key + "'");
    // A neighbourhood grows exponentially with its depth: past 8 one round
    // would take any time limit whole.
    const double n = number(o, 1);
    if (n > 8 || n != std::floor(n)) fail_at(o.at, o.key + " is a whole number from 1 to 8");
    (o.key == "depth" ? e.neighbourhood_depth : e.neighbourhood_max_depth) = static_cast<int>(n);
    max_given = max_given || o.key == "max_depth";
  }
  if (!max_given) e.neighbourhood_max_depth = std::max(e.neighbourhood_max_depth, e.neighbourhood_depth);
  if (e.neighbourhood_max_depth < e.neighbourhood_depth) fail_at(a.at, "max_depth is below depth");
}

// anytime(E, weights=[...], expansions=N, order=..., deferred=..., ties=..., improve=..., heuristic=H).
EngineSpec anytime_of(const Call& c) {
  using K = EngineSpec::Kind;
  EngineSpec e;
  e.kind = K::Anytime;
  e.weights = {5.0, 3.0, 2.0, 1.5, 1.0};
  for (const Call::Argument& a : c.arguments) {
    if (a.key.empty()) {
      if (!e.children.empty() || !a.call) fail_at(a.at, "anytime takes one engine, then options by name");
      e.children.push_back(engine_of(*a.call));
      if (e.children.back().kind == K::Anytime) fail_at(a.at, "anytime inside anytime");
      if (e.children.back().kind == K::Preferences) fail_at(a.at, "preferences goes outermost");
    } else if (a.key == "weights") {
      if (!a.is_list || a.list.empty()) fail_at(a.at, "weights is a list of numbers, [5, 3, 1]");
      for (double w : a.list) {
        if (w < 1) fail_at(a.at, "weights are at least 1");
      }
      e.weights = a.list;
    } else if (a.key == "expansions") {
      e.expansions = static_cast<std::uint64_t>(number(a, 0));
    } else if (a.key == "order") {
      if (!a.call || (a.call->name != "steps" && a.call->name != "metric")) fail_at(a.at, "order is steps or metric");
      e.metric_order = a.call->name == "metric";
    } else if (a.key == "deferred") {
      e.deferred = boolean(a);
    } else if (a.key == "ties") {
      if (!a.call || (a.call->name != "fifo" && a.call->name != "makespan")) fail_at(a.at, "ties is fifo or makespan");
      e.makespan_ties = a.call->name == "makespan";
    } else if (a.key == "improve") {
      neighbourhood_of(a, e);
    } else if (a.key == "heuristic") {
      if (!a.call) fail_at(a.at, "heuristic is trpg, blind or lmcut");
      e.heuristic = heuristic_of(*a.call);
      e.own_heuristic = true;
    } else {
      fail_at(a.at, "anytime has no option '" + a.key + "'");
    }
  }
  if (e.children.empty()) fail_at(c.at, "anytime takes the engine that finds the first plan");
  return e;
}

// preferences(E, rounds=B).
EngineSpec preferences_of(const Call& c) {
  EngineSpec e;
  e.kind = EngineSpec::Kind::Preferences;
  for (const Call::Argument& a : c.arguments) {
    if (a.key.empty()) {
      if (!e.children.empty() || !a.call) fail_at(a.at, "preferences takes one engine, then options by name");
      e.children.push_back(engine_of(*a.call));
      if (e.children.back().kind == EngineSpec::Kind::Preferences) fail_at(a.at, "preferences inside preferences");
    } else if (a.key == "rounds") {
      e.rounds = boolean(a);
    } else {
      fail_at(a.at, "preferences has no option '" + a.key + "'");
    }
  }
  if (e.children.empty()) fail_at(c.at, "preferences takes the engine that plans each round");
  return e;
}

EngineSpec engine_of(const Call& c) {
  using K = EngineSpec::Kind;
  // A bare alias that is not an engine's name stands for its expression
  // (`gbfs` alone is the engine with its defaults; `--alias gbfs` the alias).
  if (c.arguments.empty() && (c.name == "default" || c.name == "anytime" || c.name == "quality" || c.name == "complete" ||
                                 c.name == "pddl3")) {
    return parse_search_configuration(alias_expression(c.name)).engine;
  }
  if (c.name == "ehc") return leaf_of(c, K::Ehc);
  if (c.name == "gbfs") return leaf_of(c, K::Gbfs);
  if (c.name == "wastar") return leaf_of(c, K::Wastar);
  if (c.name == "complete") {
    if (c.arguments.size() != 1 || !c.arguments[0].key.empty() || !c.arguments[0].call) {
      fail_at(c.at, "complete takes one engine");
    }
    EngineSpec e = engine_of(*c.arguments[0].call);
    if (e.kind != K::Gbfs && e.kind != K::Wastar) fail_at(c.arguments[0].at, "complete takes a gbfs or a wastar");
    if (e.goal_orders) fail_at(c.arguments[0].at, "a complete search cannot prune by goal orders");
    e.complete = true;
    return e;
  }
  if (c.name == "portfolio" || c.name == "then") return combination_of(c);
  if (c.name == "anytime") return anytime_of(c);
  if (c.name == "preferences") return preferences_of(c);
  fail_at(c.at, "unknown engine '" + c.name +
                    "' (ehc, gbfs, wastar, complete, portfolio, then, anytime, preferences, or an alias)");
}

std::string format_number(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

std::string neighbourhood_text(const EngineSpec& e) {
  return std::string("neighbourhood(by=") + (e.neighbourhood_actions ? "actions" : "states") +
         ", depth=" + std::to_string(e.neighbourhood_depth) + ", max_depth=" + std::to_string(e.neighbourhood_max_depth) +
         ")";
}


std::string engine_text(const EngineSpec& e) {
  using K = EngineSpec::Kind;
  const EngineSpec defaults;
  std::string options;
  auto option = [&](const std::string& text) { options += ", " + text; };
  auto budget = [&] {
    if (e.expansions) option("expansions=" + std::to_string(e.expansions));
    if (e.time_share < 1.0) option("time_share=" + format_number(e.time_share));
  };
  switch (e.kind) {
    case K::Ehc:
    case K::Gbfs:
    case K::Wastar: {
      if (e.kind == K::Wastar) option("w=" + format_number(e.weight));
      if (e.kind == K::Wastar && e.metric_order) option("order=metric");
      if (e.typed) option("queue=typed");
      if (e.novelty) option("novelty=" + std::to_string(e.novelty));
      if (e.deferred) option("deferred=true");
      if (!e.preferred) option("preferred=false");
      if (e.goal_orders) option("goal_orders=true");
      if (e.kind == K::Ehc && !e.makespan_first) option("children=listed");
      if (e.makespan_ties) option("ties=makespan");
      if (e.share < 1.0) option("share=" + format_number(e.share));
      if (e.share_after) option("share_after=" + std::to_string(e.share_after));
      budget();
      const char* name = e.kind == K::Ehc ? "ehc" : e.kind == K::Gbfs ? "gbfs" : "wastar";
      const std::string leaf = std::string(name) + "(" + heuristic_text(e.heuristic) + options + ")";
      return e.complete ? "complete(" + leaf + ")" : leaf;
    }
    case K::Portfolio:
    case K::Then: {
      std::string children;
      for (const EngineSpec& c : e.children) children += (children.empty() ? "" : ", ") + engine_text(c);
      if (e.share_evaluations) option("turns=evaluations");
      budget();
      return std::string(e.kind == K::Then ? "then" : "portfolio") + "(" + children + options + ")";
    }
    case K::Anytime: {
      std::string weights;
      for (double w : e.weights) weights += (weights.empty() ? "" : ", ") + format_number(w);
      option("weights=[" + weights + "]");
      if (e.expansions) option("expansions=" + std::to_string(e.expansions));
      if (e.metric_order) option("order=metric");
      if (e.deferred) option("deferred=true");
      if (e.makespan_ties) option("ties=makespan");
      if (e.neighbourhood_depth) option("improve=" + neighbourhood_text(e));
      if (e.own_heuristic) option("heuristic=" + heuristic_text(e.heuristic));
      return "anytime(" + engine_text(e.children.front()) + options + ")";
    }
    case K::Neighbourhood: return neighbourhood_text(e);
    case K::Preferences:
      if (!e.rounds) option("rounds=false");
      return "preferences(" + engine_text(e.children.front()) + options + ")";
  }
  return "";
}

}  // namespace

std::string heuristic_text(const HeuristicSpec& h) {
  if (h.kind == HeuristicSpec::Kind::Blind) return "blind";
  if (h.kind == HeuristicSpec::Kind::LmCut) return "lmcut";
  std::string options;
  if (!h.helpful) options += ", helpful=false";
  if (!h.repetitions) options += ", repetitions=false";
  if (!h.balance) options += ", balance=false";
  return options.empty() ? "trpg" : "trpg(" + options.substr(2) + ")";
}

std::string SearchConfiguration::to_string() const { return engine_text(engine); }

SearchConfiguration parse_search_configuration(std::string_view expression) {
  SearchConfiguration configuration;
  configuration.engine = engine_of(Reader(expression).read_all());
  return configuration;
}

std::vector<std::string> alias_names() {
  return {"default", "anytime", "quality", "ehc", "gbfs", "wastar", "complete", "pddl3"};
}

std::string default_expression(const DefaultSearchKnobs& k) {
  const std::string h = heuristic_text(k.heuristic);
  const std::string deferred = k.deferred ? ", deferred=true" : "";
  // Ties by makespan (issue 48) on the plain members only: on the typed and
  // novelty members they lost depots 3 and 4 and sokoban 3 (instances 1-5,
  // benchmarks/README.md), which those members find by exploring, not by
  // the order of equal h.
  const std::string ties = k.makespan_ties ? ", ties=makespan" : "";
  std::string fallback = "gbfs(" + h + (k.goal_orders ? ", goal_orders=true" : "") + deferred + ties + ")";
  // EHC's fallback (planner/README.md): a plain GBFS beside the typed one,
  // whose random draws led it astray on robot-battery p04; the typed eager
  // one ordered by novelty (storage, depots 4, parc-printer 5); a typed
  // deferred one (satellite, storage 2014); weighted A*.
  if (k.type_exploration || k.fallback_novelty) {
    fallback += ", gbfs(" + h + (k.type_exploration ? ", queue=typed" : "") +
                (k.fallback_novelty ? ", novelty=" + std::to_string(k.novelty_width) : "") + deferred + ")";
  }
  if (k.fallback_deferred) fallback += ", gbfs(" + h + (k.type_exploration ? ", queue=typed" : "") + ", deferred=true)";
  fallback += ", wastar(" + h + ", w=" + format_number(k.weight) + deferred + ties + ")";
  // The complete search takes its turn beside the others instead of after
  // them: the incomplete searches (no action overlapping itself, states
  // compared without their schedules) may never exhaust a space that holds
  // no plan for them, and a complete search waiting behind them never ran
  // on tasks it solves in milliseconds (three overlapping runs of one
  // action, differential tester). Its exhaustion ends the portfolio.
  // Equal turns for its first expansions (what small tasks need), then a
  // small share: its expansions cost several of the others' (exact
  // duplicates, dead ends confirmed by the sound relaxation), and at an
  // equal turn it halved the speed of storage's searches.
  fallback += ", complete(wastar(" + h + ", w=" + format_number(k.weight) + deferred + ", share=" +
              format_number(k.complete_share) + ", share_after=" + std::to_string(k.complete_share_after) + "))";
  std::string ehc = "ehc(" + h + ", expansions=" + std::to_string(k.ehc_expansions);
  if (k.ehc_time_share < 1.0) ehc += ", time_share=" + format_number(k.ehc_time_share);
  if (k.goal_orders) ehc += ", goal_orders=true";
  ehc += ")";
  return "then(" + ehc + ", portfolio(" + fallback + "))";
}

bool proves_cost_optimal(const EngineSpec& e) {
  const bool admissible = e.heuristic.kind == HeuristicSpec::Kind::Blind || e.heuristic.kind == HeuristicSpec::Kind::LmCut;
  return e.kind == EngineSpec::Kind::Wastar && e.complete && e.metric_order && e.weight == 1.0 && !e.preferred &&
         !e.deferred && admissible;
}

std::string anytime_expression(const std::string& first, double min_weight, std::uint64_t expansions,
                               bool metric_order) {
  std::string weights;
  for (double w : {5.0, 3.0, 2.0, 1.5, 1.0}) {
    if (w >= min_weight) weights += (weights.empty() ? "" : ", ") + format_number(w);
  }
  if (weights.empty()) weights = format_number(min_weight);
  std::string text = "anytime(" + first + ", weights=[" + weights + "]";
  if (expansions) text += ", expansions=" + std::to_string(expansions);
  if (metric_order) text += ", order=metric";
  return text + ")";
}

std::string alias_expression(std::string_view name) {
  if (name == "default" || name == "ehc") return default_expression();
  // `quality` names the configuration to ask for when plan quality matters
  // (issue 48): the default's first plan (EHC trying helpful children
  // shortest makespan first), then the anytime phases under the best plan's
  // value; every plan goes through deordering and action elimination. It is
  // `anytime` today; a script asking for quality gets what measures best.
  if (name == "anytime" || name == "quality") return anytime_expression(default_expression());
  if (name == "gbfs") return "gbfs(trpg, queue=typed)";
  if (name == "wastar") return "wastar(trpg, w=3)";
  if (name == "complete") return "complete(wastar(trpg, w=3))";
  if (name == "pddl3") return "preferences(" + default_expression() + ")";
  std::string names;
  for (const std::string& n : alias_names()) names += (names.empty() ? "" : ", ") + n;
  throw SearchConfigurationError("unknown configuration '" + std::string(name) + "' (aliases: " + names + ")");
}

SearchConfiguration alias(std::string_view name) { return parse_search_configuration(alias_expression(name)); }

SearchConfiguration with_anytime(const SearchConfiguration& configuration, double min_weight, std::uint64_t expansions) {
  if (configuration.engine.kind == EngineSpec::Kind::Preferences) {
    SearchConfiguration result = configuration;
    result.engine.children.front() =
        with_anytime(SearchConfiguration{configuration.engine.children.front()}, min_weight, expansions).engine;
    return result;
  }
  const EngineSpec& e = configuration.engine;
  const bool anytime = e.kind == EngineSpec::Kind::Anytime;
  const SearchConfiguration first{anytime ? e.children.front() : e};
  SearchConfiguration result =
      parse_search_configuration(anytime_expression(first.to_string(), min_weight, expansions, anytime && e.metric_order));
  if (!anytime) return result;
  // Only the weights and their budget change: the anytime's own options
  // (order, deferred, ties, improve, heuristic) stay as given.
  SearchConfiguration kept = configuration;
  kept.engine.weights = result.engine.weights;
  kept.engine.expansions = result.engine.expansions;
  return kept;
}

PreferencePlan preference_plan(const SearchConfiguration& configuration) {
  const bool preferences = configuration.engine.kind == EngineSpec::Kind::Preferences;
  const EngineSpec& e = preferences ? configuration.engine.children.front() : configuration.engine;
  PreferencePlan plan;
  if (e.kind != EngineSpec::Kind::Anytime) {
    plan.first.engine = e;
    return plan;
  }
  plan.first.engine = e.children.front();
  plan.rounds = !preferences || configuration.engine.rounds;
  plan.improve = SearchConfiguration{e};
  return plan;
}

SearchConfiguration configuration_named(std::string_view search) {
  SearchShorthands s;
  s.search = std::string(search);
  return configuration_from(s);
}

bool shaped_by_knobs(std::string_view search) {
  return search == "ehc" || search == "default" || search == "gbfs" || search == "wastar" || search == "anytime" ||
         search == "quality";
}

SearchConfiguration configuration_from(const SearchShorthands& s) {
  const DefaultSearchKnobs& k = s.knobs;
  const std::string h = heuristic_text(k.heuristic);
  const std::string deferred = k.deferred ? ", deferred=true" : "";
  std::string expression;
  const bool anytime_alias = s.search == "anytime" || s.search == "quality";
  if (s.search == "ehc" || s.search == "default" || anytime_alias) {
    expression = default_expression(k);
  } else if (s.search == "gbfs") {
    expression = "gbfs(" + h + (k.type_exploration ? ", queue=typed" : "") +
                 (s.novelty ? ", novelty=" + std::to_string(k.novelty_width) : "") + deferred + ")";
  } else if (s.search == "wastar") {
    expression = "wastar(" + h + ", w=" + format_number(k.weight) + (s.metric_order ? ", order=metric" : "") + deferred + ")";
  } else {
    expression = s.search;
  }
  SearchConfiguration configuration = parse_search_configuration(expression);
  EngineSpec& engine = configuration.engine.kind == EngineSpec::Kind::Preferences
                           ? configuration.engine.children.front()
                           : configuration.engine;
  if ((s.anytime || anytime_alias) && engine.kind != EngineSpec::Kind::Anytime) {
    engine = parse_search_configuration(anytime_expression(SearchConfiguration{engine}.to_string(), s.anytime_min_weight,
                                                           s.anytime_expansions, s.metric_order))
                 .engine;
    engine.deferred = k.deferred;
  }
  return configuration;
}

}  // namespace alplan
