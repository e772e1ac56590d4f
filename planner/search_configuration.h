// Search configurations as components (Fast Downward's option parser and
// aliases): a small expression language names the engines, their heuristic,
// their open lists and their pruning, and how they are combined.
//
//   configuration := engine
//   engine        := ehc(HEURISTIC, expansions=N, time_share=F, goal_orders=B, children=makespan|listed)
//                  | gbfs(HEURISTIC, queue=plain|typed, novelty=0|1|2, deferred=B, preferred=B, goal_orders=B,
//                         ties=fifo|makespan)
//                  | wastar(HEURISTIC, w=W, order=steps|metric, deferred=B, preferred=B, ties=fifo|makespan)
//                  | complete(ENGINE)               a gbfs or wastar that misses no plan
//                  | portfolio(ENGINE, ..., turns=expansions|evaluations)  leaf engines taking turns
//                  | then(ENGINE, ENGINE, ...)      phases: the next runs when one gives up
//                  | anytime(ENGINE, weights=[W, ...], expansions=N, order=steps|metric, ties=fifo|makespan,
//                            improve=neighbourhood(by=states|actions, depth=D, max_depth=M))
//                  | preferences(ENGINE, rounds=B)  PDDL 3 (preference_search.h); outermost only
//   HEURISTIC     := trpg(helpful=B, repetitions=B, balance=B) | blind | lmcut
//
// Leaf engines and portfolios also take `expansions=N` and `time_share=F`
// (of the time limit): past either the phase gives up and the next of a
// `then` runs. A name alone stands for its call with defaults (`gbfs` is
// `gbfs(trpg)`); booleans are true/false. Named configurations (aliases):
// `default` (EHC, falling back to a portfolio of greedy searches and
// weighted A*, then a complete search), `anytime` (the default, then weighted
// A* with falling weights under the best plan's value), `quality` (what to
// ask for when plan quality matters; today `anytime`), `gbfs`, `wastar`,
// `ehc` (the default: EHC and its fallback, as `--search ehc` always meant),
// `complete`, and `pddl3` (`preferences` around the default). On a task
// without PDDL 3, `preferences(E)` is E; on a task with PDDL 3 any
// configuration E is planned as `preferences(E)`. planner/README.md
// documents each component.
//
// Which engine may prune what (and so which may prove unsolvability):
// - `goal_orders` prunes states holding a goal that another still-false
//   goal must precede (goal_orders.h): the orders come from a compression of
//   durative actions into classical steps, a heuristic for temporal tasks,
//   so an engine using them never proves anything.
// - Every engine but a complete one prunes on the guiding relaxation's dead
//   ends, drops a node whose state a stored node has with a schedule that
//   looks no worse (TemporalSignature), and never runs an action twice at
//   once; a complete one prunes only dead ends the sound relaxation confirms,
//   compares schedules exactly and lets actions overlap themselves
//   (SearchSpaceOptions), so its exhaustion proves that no plan exists.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace alplan {

struct HeuristicSpec {
  enum class Kind { Trpg, Blind, LmCut };
  Kind kind = Kind::Trpg;
  bool helpful = true;      // trpg: helpful actions
  bool repetitions = true;  // trpg: repetitions of constant producers
  bool balance = true;      // trpg: resource balance with continuous change
  bool operator==(const HeuristicSpec&) const = default;
};

struct EngineSpec {
  // Neighbourhood is never written alone: anytime's improve= makes one
  // (search_pipeline.cpp) from neighbourhood_depth.
  enum class Kind { Ehc, Gbfs, Wastar, Portfolio, Then, Anytime, Preferences, Neighbourhood };
  Kind kind = Kind::Ehc;
  HeuristicSpec heuristic;
  // A phase's budget: past so many expansions (0: no bound), or this share
  // of the time limit (1: the whole), it gives up.
  std::uint64_t expansions = 0;
  double time_share = 1.0;
  bool goal_orders = false;  // ehc, gbfs
  // ehc: helpful children tried shortest makespan first (EhcOptions)
  bool makespan_first = true;
  bool typed = false;        // gbfs: a type-based queue beside the others
  int novelty = 0;           // gbfs: order by novelty of this width within h (0: by h)
  bool deferred = false;     // gbfs, wastar: evaluate when expanded
  bool preferred = true;     // gbfs, wastar: a queue of helpful children
  double weight = 3.0;       // wastar
  bool metric_order = false; // wastar, anytime: order by the metric, not steps
  bool complete = false;     // gbfs, wastar: miss no plan
  bool makespan_ties = false; // gbfs, wastar, anytime: ties in f and h to the smaller makespan bound (BestFirstOptions)
  // A portfolio member's turns (gbfs, wastar): after its first
  // `share_after` expansions it takes its turn only while its expansions are
  // under `share` times the portfolio's (1: an equal turn always). Counted
  // in expansions, so the same on every machine.
  double share = 1.0;
  std::uint64_t share_after = 0;
  // portfolio: turns by evaluations (the engine that has evaluated least
  // goes next) instead of one expansion each.
  bool share_evaluations = false;
  // preferences: in anytime mode, rounds that enforce one more preference each
  bool rounds = true;
  std::vector<double> weights;           // anytime
  // anytime: improve=neighbourhood(by=states|actions, depth=D, max_depth=M)
  // searches around each new best plan (plan_neighbourhood_search.h) before
  // the weighted A* phases, again while it improves; depth 0: none.
  int neighbourhood_depth = 0;
  int neighbourhood_max_depth = 4;
  bool neighbourhood_actions = false;  // by=actions
  // anytime: its weights search with `heuristic` instead of the heuristic
  // of the first search's first engine (heuristic=H).
  bool own_heuristic = false;
  std::vector<EngineSpec> children;      // portfolio, then; anytime: the first search; preferences: its engine
  bool operator==(const EngineSpec&) const = default;
};

struct SearchConfiguration {
  EngineSpec engine;
  // Writes the configuration back as an expression `parse` reads to the same.
  std::string to_string() const;
};

// A malformed expression: the message names the place (a character offset)
// and what was expected.
class SearchConfigurationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

SearchConfiguration parse_search_configuration(std::string_view expression);
// The heuristic as the configuration language writes it: trpg, lmcut, ...
std::string heuristic_text(const HeuristicSpec& heuristic);
// The expression of a named configuration; throws for an unknown name.
std::string alias_expression(std::string_view name);
std::vector<std::string> alias_names();
SearchConfiguration alias(std::string_view name);

// The default configuration with its historical knobs (the flags of
// `alplan plan` before this language; they stay as shorthands).
struct DefaultSearchKnobs {
  std::uint64_t ehc_expansions = 20000;
  double ehc_time_share = 0.25;
  bool type_exploration = true;
  bool fallback_deferred = true;
  bool fallback_novelty = true;
  int novelty_width = 2;
  bool goal_orders = true;
  double weight = 3.0;
  double complete_share = 0.02;              // the complete member's share of the portfolio's expansions
  std::uint64_t complete_share_after = 1000;  // after its first expansions at an equal turn
  bool deferred = false;  // every greedy and weighted A* search evaluates when it expands
  // The plain greedy search and weighted A* break ties in h by makespan
  // (ties=makespan); the typed and novelty members keep first in, first out.
  bool makespan_ties = true;
  HeuristicSpec heuristic;
};
std::string default_expression(const DefaultSearchKnobs& knobs = {});

// Whether the first plan `engine` returns is optimal for the metric: A*,
// that is complete(wastar(H, w=1, order=metric)) with one open list
// (preferred=false: a queue of helpful children would pop nodes out of f
// order), evaluation when generated (deferred=false: a deferred child waits
// under its parent's estimate, which may exceed its own), and H a heuristic
// whose cost never overestimates the metric still to come: blind (0) or
// lmcut (lmcut_heuristic.h). trpg's relaxed-plan cost can overestimate.
// A caller that says "optimal" or "minimal" asks this first.
bool proves_cost_optimal(const EngineSpec& engine);

// Wraps a first search into anytime mode: weighted A* with weights from
// `weights` down to `min_weight`, each capped at `expansions` (0: none).
std::string anytime_expression(const std::string& first, double min_weight = 1.0, std::uint64_t expansions = 0,
                               bool metric_order = false);

// `configuration` in anytime mode: followed by weighted A* with the weights
// 5, 3, 2, 1.5, 1 down to `min_weight`, each capped at `expansions` (0: until
// it finds a better plan or proves there is none). An anytime configuration
// keeps its first search and takes these weights and cap.
SearchConfiguration with_anytime(const SearchConfiguration& configuration, double min_weight = 1.0,
                                 std::uint64_t expansions = 0);

// How a PDDL 3 task is planned under a configuration (preference_search.h):
// `first` finds each round's plan; in anytime mode (the engine, or the one
// inside `preferences`, is `anytime`) the rounds follow, unless rounds=false,
// and then `improve`, the anytime engine itself, on the best selection.
struct PreferencePlan {
  SearchConfiguration first;
  bool rounds = false;
  std::optional<SearchConfiguration> improve;
};
PreferencePlan preference_plan(const SearchConfiguration& configuration);

// The flags of `alplan plan` before this language, kept as shorthands (and
// the Python module's keywords): `search` names ehc, gbfs or wastar (shaped
// by the knobs, as the flags shaped them), or any alias or expression (the
// knobs then do not apply); `anytime` wraps the result in anytime mode.
struct SearchShorthands {
  std::string search = "ehc";
  DefaultSearchKnobs knobs;
  bool novelty = false;       // gbfs ordered by novelty of knobs.novelty_width
  bool metric_order = false;  // wastar and the anytime phases order by the metric
  bool anytime = false;
  double anytime_min_weight = 1.0;
  std::uint64_t anytime_expansions = 0;
};
SearchConfiguration configuration_from(const SearchShorthands& shorthands);
// configuration_from with only `search` given.
SearchConfiguration configuration_named(std::string_view search);
// Whether `search` is one of the names the knobs shape.
bool shaped_by_knobs(std::string_view search);

}  // namespace alplan
