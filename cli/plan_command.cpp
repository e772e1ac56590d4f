// alplan plan DOMAIN PROBLEM [--time-limit S] [--memory-limit MiB] [--anytime]
//   [--search ehc|gbfs|wastar] [--heuristic trpg|trpg-nohelpful] [--order metric|steps] [--out PLAN] [--json]
//   [--diverse K [--min-distance D]]
// Exit 0 with a plan, 10 proven unsolvable, 11 limits reached, 12 search
// exhausted without proof, 2 input error, 70 internal error (an invalid plan).
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <new>
#include <optional>
#include <sstream>
#include <string>

#include "cli/commands.h"
#include "cli/plan_output.h"
#include "cli/task_files.h"
#include "pddl_parser/writer.h"
#include "planner/diverse_plans.h"
#include "planner/grounder.h"
#include "planner/planner.h"

namespace alplan::cli {
namespace {

struct PlanOptions {
  std::string domain;
  std::string problem;
  double time_limit = 60.0;
  double memory_limit = 0.0;
  bool reserve_planning_time = false;
  double epsilon = 0.001;
  std::string alias;  // --alias NAME: a named configuration
  // --search and the flags before the configuration language, as shorthands.
  SearchShorthands search;
  std::string heuristic = "trpg";
  std::string order = "steps";
  std::optional<std::uint64_t> ehc_expansions;
  bool prune_irrelevant = true;
  bool deorder = true;
  bool eliminate_actions = true;
  // Shorthand flags given on the command line (they shape only the named
  // searches ehc, gbfs and wastar).
  std::vector<std::string> shorthands_given;
  std::string out;
  bool json = false;
  bool quiet = false;
  // --diverse K: K plans pairwise at least min_distance ground actions apart
  // (planner/diverse_plans.h) instead of one; 0: one plan, as always.
  std::size_t diverse = 0;
  std::size_t min_distance = 2;
};

std::string readable(double x) { return format_value(x); }

void print_comment(std::ostream& out, const std::string& message) { out << plan_comment(message); }

int exit_code(PlannerResult::Status s) {
  switch (s) {
    case PlannerResult::Status::Solved: return kExitOk;
    case PlannerResult::Status::Unsolvable: return kExitUnsolvable;
    case PlannerResult::Status::Exhausted: return kExitExhausted;
    case PlannerResult::Status::LimitReached: return kExitLimit;
    case PlannerResult::Status::Unsupported: return kExitInputError;
    case PlannerResult::Status::InternalError: return kExitInternalError;
  }
  return kExitInternalError;
}

// After the stream of improving plans, the best one, one "; best plan
// KEY: VALUE" line per fact, so that a tool need not parse the stream.
void print_best(const PlannerResult& result, std::ostream& out) {
  const FoundPlan& best = *result.best();
  const ValidationResult& v = best.validation;
  out << "; best plan: " << result.plans.size() << " of " << result.plans.size() << "\n"
      << "; best plan makespan: " << format_plan_time(v.makespan) << "\n"
      << "; best plan metric: " << (v.metric ? readable(*v.metric) : std::string("none")) << "\n";
  if (v.total_cost) out << "; best plan cost: " << readable(*v.total_cost) << "\n";
  if (!v.preference_violations.empty()) {
    out << "; best plan preferences violated:";
    for (const auto& [name, count] : v.preference_violations) out << " " << name << "=" << readable(count);
    out << "\n";
  }
  out << "; best plan found after: " << format_seconds(best.seconds) << " s by " << best.engine << "\n";
}

// A limit reached before the planner could report one itself (memory while
// loading or grounding, time while grounding): the same status the planner
// gives, on the same streams, and exit 11.
int limit_reached(const PlanOptions& options, const std::string& message, const char* limit) {
  if (options.json) {
    nlohmann::json j = outcome_json(status_name(PlannerResult::Status::LimitReached), message);
    j["limit"] = limit;
    std::cout << j.dump(2) << "\n";
  } else {
    print_comment(std::cout, message);
    std::cout << "; status: " << status_name(PlannerResult::Status::LimitReached) << "\n";
  }
  return kExitLimit;
}

// Bad input (exit 2): the message on stderr, and with --json an object on
// stdout too, so that a script reading stdout sees every outcome.
// `diagnostics` were printed on stderr already; the message is too unless
// they are what it sums up.
int input_error(const PlanOptions& options, const std::string& message, const std::string& diagnostics,
                bool diagnostics_say_it = false) {
  const std::string said = diagnostics_say_it ? diagnostics : diagnostics + "error: " + message + "\n";
  if (!diagnostics_say_it) std::cerr << "error: " << message << "\n";
  if (options.json) std::cout << outcome_json("input_error", message, said).dump(2) << "\n";
  return kExitInputError;
}

// The configuration the options ask for: --alias, --search (a name or an
// expression) and the shorthand flags, which shape only the named searches.
SearchConfiguration search_configuration(const PlanOptions& options) {
  SearchShorthands s = options.search;
  if (!options.alias.empty()) {
    alias_expression(options.alias);  // throws for an unknown name
    s.search = options.alias;
  }
  if (!shaped_by_knobs(s.search) && !options.shorthands_given.empty()) {
    throw SearchConfigurationError(options.shorthands_given.front() +
                                   " shapes the configurations ehc, gbfs, wastar, default and anytime; with another "
                                   "configuration write it in the expression");
  }
  s.knobs.heuristic.helpful = options.heuristic == "trpg";
  s.metric_order = options.order == "metric";
  if (options.ehc_expansions) s.knobs.ehc_expansions = *options.ehc_expansions;
  return configuration_from(s);
}

// --diverse: the plans, each headed "; plan i of K", then their pairwise
// distances; fewer than K are printed with a line saying so. Exit codes as
// for one plan: 0 with at least one, else the first search's.
int plan_diverse(const std::shared_ptr<const GroundTask>& task, const PlannerOptions& planner,
                 const PlanOptions& options, const std::string& diagnostics) {
  PlanPrinter printer(task.get());
  DiversePlanOptions diverse;
  diverse.k = options.diverse;
  diverse.min_distance = options.min_distance;
  diverse.planner = planner;
  diverse.time_limit = planner.time_limit;
  const DiversePlans found = find_diverse_plans(task, diverse);
  const std::size_t n = found.plans.size();
  std::vector<std::vector<std::size_t>> distances(n, std::vector<std::size_t>(n, 0));
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) distances[i][j] = plan_action_distance(found.plans[i].plan, found.plans[j].plan);
  }
  if (n > 0 && !options.out.empty()) std::ofstream(options.out) << printer.printed(found.plans.front()).text;
  const std::string shortfall =
      n == options.diverse ? ""
                           : "found " + std::to_string(n) + " of " + std::to_string(options.diverse) + " plans at least " +
                                 std::to_string(options.min_distance) + " actions apart " +
                                 (found.exhausted ? "(no more by removing found plans' actions)"
                                                  : "(the budget ran out)");
  if (options.json) {
    nlohmann::json plans = nlohmann::json::array();
    for (std::size_t i = 0; i < n; ++i) plans.push_back(plan_json(found.plans[i], printer.printed(found.plans[i]), i + 1));
    // The one schema, and what --diverse adds: no plan is "best" among them,
    // and every planner call's time is search time.
    nlohmann::json j = outcome_json(status_name(n > 0 ? PlannerResult::Status::Solved : found.first_status),
                                    n > 0 ? shortfall : found.message, diagnostics);
    j["plans"] = plans;
    j["seconds"]["search"] = found.seconds;
    j["requested"] = options.diverse;
    j["min_distance"] = options.min_distance;
    j["distances"] = distances;
    j["planner_calls"] = found.planner_calls;
    std::cout << j.dump(2) << "\n";
  } else {
    for (std::size_t i = 0; i < n; ++i) {
      const ValidationResult& v = found.plans[i].validation;
      std::cout << "; plan " << i + 1 << " of " << options.diverse << ": makespan " << readable(v.makespan)
                << ", value " << readable(v.value) << "\n" << printer.printed(found.plans[i]).text;
    }
    if (n > 0) std::cout << "; distances (ground actions added + removed):\n";
    for (std::size_t i = 0; i < n; ++i) {
      std::cout << ";";
      for (std::size_t d : distances[i]) std::cout << " " << d;
      std::cout << "\n";
    }
    if (!shortfall.empty()) print_comment(std::cout, shortfall);
    if (n == 0) print_comment(std::cout, found.message);
    std::cout << "; status: " << status_name(n > 0 ? PlannerResult::Status::Solved : found.first_status) << "; "
              << found.planner_calls << " searches, " << format_seconds(found.seconds) << " s\n";
  }
  return n > 0 ? kExitOk : exit_code(found.first_status);
}

// The planner's result in the one schema (plan_output.h).
nlohmann::json result_json(const PlannerResult& result, PlanPrinter& printer, const std::string& diagnostics,
                           double grounding) {
  nlohmann::json plans = nlohmann::json::array();
  for (std::size_t i = 0; i < result.plans.size(); ++i) {
    plans.push_back(plan_json(result.plans[i], printer.printed(result.plans[i]), i + 1));
  }
  const SearchStatistics& s = result.statistics;
  nlohmann::json j = outcome_json(status_name(result.status), result.message, diagnostics);
  if (!result.limit.empty()) j["limit"] = result.limit;
  if (result.best()) {
    j["best"] = plan_json(*result.best(), printer.printed(*result.best()), result.plans.size());
    j["best_index"] = result.plans.size();
  }
  j["plans"] = plans;
  j["statistics"] = {{"expanded", s.expanded}, {"evaluated", s.evaluated}, {"generated", s.generated},
                     {"duplicates", s.duplicates}, {"unschedulable", s.unschedulable}, {"dead_ends", s.dead_ends}};
  j["seconds"] = {{"grounding", grounding}, {"setup", result.times.setup}, {"search", result.times.search},
                  {"validation", result.times.validation}};
  return j;
}

// Loads, grounds and plans; `phase` names the step under way, so that a
// limit reached anywhere can say where. `task` receives the grounded task,
// for the caller to decide when it is freed.
int plan_files(const PlanOptions& options, const char*& phase, std::shared_ptr<const GroundTask>& task,
               std::shared_ptr<void>& search_memory) {
  const auto began = std::chrono::steady_clock::now();
  phase = "loading the files";
  // With --json the diagnostics also go into the JSON on stdout.
  std::ostringstream captured;
  const auto files = load_task_files(options.domain, options.problem, options.json ? captured : std::cerr,
                                     {!options.quiet});
  if (options.json) std::cerr << captured.str();
  const std::string diagnostics = captured.str();
  if (!files) return input_error(options, "the input files have errors", diagnostics, true);
  phase = "grounding";
  GroundingOptions grounding_options{{options.domain, options.problem, {}}, std::nullopt};
  if (std::isfinite(options.time_limit)) {
    grounding_options.deadline = began + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                             std::chrono::duration<double>(options.time_limit));
  }
  try {
    task = ground(*files->domain, *files->problem, grounding_options);
  } catch (const GroundingError& e) {
    return input_error(options, e.what(), diagnostics);
  }
  const double grounding = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  if (grounding >= options.time_limit) return limit_reached(options, "the time limit was reached while grounding", "time");
  phase = "search";
  PlannerOptions planner_options;
  try {
    planner_options.search = search_configuration(options);
  } catch (const SearchConfigurationError& e) {
    return input_error(options, e.what(), diagnostics);
  }
  planner_options.prune_irrelevant = options.prune_irrelevant;
  planner_options.deorder = options.deorder;
  planner_options.eliminate_actions = options.eliminate_actions;
  planner_options.epsilon = options.epsilon;
  planner_options.reserve_planning_time = options.reserve_planning_time;
  planner_options.time_limit = std::max(0.0, options.time_limit - grounding);
  // Under an address-space limit (ours or the caller's, as `bench planners`
  // sets it) the search stops at 90% of it: a refused allocation would
  // unwind and free the search node by node, seconds past the time limit.
  rlimit address_space{};
  if (getrlimit(RLIMIT_AS, &address_space) == 0 && address_space.rlim_cur != RLIM_INFINITY) {
    planner_options.address_space_limit = static_cast<std::size_t>(0.9 * static_cast<double>(address_space.rlim_cur));
  }
  if (options.diverse > 0) return plan_diverse(task, planner_options, options, diagnostics);
  PlanPrinter printer(task.get());
  auto on_plan = [&](const FoundPlan& p) {
    if (options.json) return;
    const PrintedPlan& printed = printer.printed(p);
    const std::string length = printed.sequential ? std::to_string(p.plan.steps.size()) + " steps"
                                                  : "makespan " + readable(p.validation.makespan);
    std::cout << "; plan found after " << format_seconds(p.seconds) << " s by " << p.engine << ", " << length
              << ", value " << readable(p.validation.value) << "\n"
              << printed.text << std::flush;
  };
  const PlannerResult result = Planner(task, planner_options).plan(on_plan);
  search_memory = result.search_memory;
  phase = "writing the result";
  if (result.best() && !options.out.empty()) std::ofstream(options.out) << printer.printed(*result.best()).text;
  if (options.json) {
    std::cout << result_json(result, printer, diagnostics, grounding).dump(2) << "\n";
  } else {
    if (planner_options.search.engine.kind == EngineSpec::Kind::Anytime && result.best()) print_best(result, std::cout);
    // A solved task has a message only when how it was solved needs saying
    // (happenings closer than epsilon).
    if (result.status != PlannerResult::Status::Solved || !result.message.empty()) print_comment(std::cout, result.message);
    std::cout << "; status: " << status_name(result.status) << "; expanded " << result.statistics.expanded
              << ", evaluated " << result.statistics.evaluated << ", grounding "
              << format_seconds(grounding) << " s, search " << format_seconds(result.times.search)
              << " s\n";
  }
  if (result.status == PlannerResult::Status::InternalError || result.status == PlannerResult::Status::Unsupported) {
    std::cerr << "error: " << result.message << "\n";
  }
  return exit_code(result.status);
}

int run(const PlanOptions& options) {
  if (options.memory_limit > 0) {
    const rlim_t bytes = static_cast<rlim_t>(options.memory_limit * 1024 * 1024);
    const rlimit limit{bytes, bytes};
    setrlimit(RLIMIT_AS, &limit);
  }
  // Memory can run out in any phase (the limit may also come from outside,
  // as `bench planners` sets it): every phase's bad_alloc is a limit, exit
  // 11, never an abort. Unwinding has freed the phase's memory by the time
  // the handler reports it.
  const char* phase = "starting";
  std::shared_ptr<const GroundTask> task;
  std::shared_ptr<void> search_memory;
  int code = kExitOk;
  try {
    code = plan_files(options, phase, task, search_memory);
  } catch (const std::bad_alloc&) {
    task.reset();
    search_memory.reset();
    std::cerr << "error: memory limit reached while " << phase << "\n";
    code = limit_reached(options, std::string("the memory limit was reached while ") + phase, "memory");
  } catch (const GroundingTimeout& e) {
    code = limit_reached(options, e.what(), "time");
  }
  // The process ends here. Freeing a large grounded task piece by piece
  // takes a good part of a second (0.2 s for driver-log's 134,000 actions),
  // a search the limit stopped seconds (planner.h), which a time limit
  // would have to count; the operating system reclaims them at once.
  std::cout.flush();
  std::cerr.flush();
  std::_Exit(code);
}

}  // namespace

void add_plan_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<PlanOptions>();
  CLI::App* cmd = app.add_subcommand("plan", "Plan with the in-process temporal planner");
  cmd->add_option("DOMAIN", options->domain, "Domain file")->required();
  cmd->add_option("PROBLEM", options->problem, "Problem file")->required();
  cmd->add_option("--time-limit", options->time_limit, "Seconds for grounding and search")->check(CLI::NonNegativeNumber);
  cmd->add_option("--memory-limit", options->memory_limit, "MiB of address space")->check(CLI::NonNegativeNumber);
  cmd->add_flag("--anytime", options->search.anytime, "Keep improving the plan until the time limit");
  cmd->add_option("--epsilon", options->epsilon, "Separation of dependent happenings (OPTIC's 0.001 by default)")
      ->check(CLI::PositiveNumber);
  cmd->add_flag("--reserve-planning-time", options->reserve_planning_time,
                "Start no step before the time limit has passed (deadlines shrink by the planning budget)");
  CLI::Option* search_option = cmd->add_option("--search", options->search.search,
                  "A search configuration: ehc (the default: EHC falling back to a portfolio, then a complete "
                  "search), gbfs, wastar, an alias, or an expression such as "
                  "'then(ehc(trpg), complete(wastar(trpg, w=1)))' (planner/README.md)");
  cmd->add_option("--alias", options->alias,
                  "A named configuration: default, anytime, ehc, gbfs, wastar, complete, pddl3 (planner/README.md)")
      ->excludes(search_option);  // two configurations: one would be dropped without a word
  cmd->footer(
      "Exit codes: 0 a plan; 2 bad input or an unsupported construct; 10 no plan exists (proven); 11 a time, node "
      "or memory limit reached before a plan; 12 the search space exhausted without a proof; 70 an internal error "
      "(a plan the validator rejected). Note: Fast Downward's 11 means proven unsolvable; ours is 10.");
  // The flags before the configuration language: shorthands shaping ehc, gbfs and wastar.
  auto shorthand_options = std::make_shared<std::vector<CLI::Option*>>();
  auto shorthand = [&](CLI::Option* o) {
    shorthand_options->push_back(o);
    return o;
  };
  shorthand(cmd->add_option("--heuristic", options->heuristic, "trpg (temporal relaxed planning graph) or trpg-nohelpful")
                ->check(CLI::IsMember({"trpg", "trpg-nohelpful"})));
  shorthand(cmd->add_option("--weight", options->search.knobs.weight, "Weight of h in wastar")->check(CLI::Number));
  cmd->add_option("--order", options->order,
                  "How wastar (and anytime search) orders nodes: metric (cost and makespan so far and to come, "
                  "for a minimised metric that only grows) or steps (default)")
      ->check(CLI::IsMember({"metric", "steps"}));
  shorthand(cmd->add_option("--ehc-expansions", options->ehc_expansions,
                            "EHC gives up after this many expansions and GBFS and wastar take turns (default 20000)"));
  shorthand(cmd->add_option("--ehc-time-share", options->search.knobs.ehc_time_share,
                            "EHC also gives up after this share of the time limit (default 0.25; 1: only the "
                            "expansions count)")
                ->check(CLI::Range(0.0, 1.0)));
  shorthand(cmd->add_flag("--deferred", options->search.knobs.deferred,
                          "GBFS and wastar evaluate a node when they expand it, not when they generate it"));
  shorthand(cmd->add_flag("--type-exploration,!--no-type-exploration", options->search.knobs.type_exploration,
                          "GBFS also expands every fourth node drawn at random by (h, g) (Xie et al. 2014; seeded, "
                          "reproducible; in EHC's fallback a typed GBFS runs beside the plain one; default on)"));
  shorthand(cmd->add_flag("--novelty,!--no-novelty", options->search.novelty,
                          "GBFS orders its queues by novelty within h, then h (best-first width search, Lipovetzky & "
                          "Geffner 2017)"));
  shorthand(cmd->add_option("--novelty-width", options->search.knobs.novelty_width,
                            "Engines ordered by novelty count new facts (1) or new pairs of facts too (2, default)")
                ->check(CLI::Range(1, 2)));
  shorthand(cmd->add_flag("--fallback-novelty,!--no-fallback-novelty", options->search.knobs.fallback_novelty,
                          "The typed GBFS of EHC's fallback orders its queues by novelty within h, then h (default on)"));
  shorthand(cmd->add_flag("--fallback-deferred,!--no-fallback-deferred", options->search.knobs.fallback_deferred,
                          "EHC's fallback adds a GBFS with deferred evaluation to the GBFS and wastar taking turns "
                          "(default on)"));
  shorthand(cmd->add_flag("--goal-orders,!--no-goal-orders", options->search.knobs.goal_orders,
                          "EHC and the plain GBFS of its fallback prune states holding a goal that another, still "
                          "false, must precede (orders from h^2 mutexes, Koehler & Hoffmann 2000; default on)"));
  cmd->add_flag("!--no-deorder", options->deorder,
                "Print plans as the search scheduled them, not lifted to the order their causal links need");
  cmd->add_flag("!--no-action-elimination", options->eliminate_actions,
                "Keep every action of a plan found, not only those it is valid and no worse without "
                "(greedy action elimination, Nakhost & Muller 2010)");
  cmd->add_flag("!--no-relevance", options->prune_irrelevant,
                "Search every ground action, not only those that can contribute to the goal");
  shorthand(cmd->add_flag("!--no-repetitions", options->search.knobs.heuristic.repetitions,
                          "Without continuous change: do not count how often a constant producer must repeat to meet "
                          "a numeric condition"));
  shorthand(cmd->add_flag("!--no-resource-balance", options->search.knobs.heuristic.balance,
                          "With continuous change: do not count the recharges and refuels the relaxed plan's "
                          "consumption needs"));
  cmd->add_option("--out", options->out, "Write the best plan to this file");
  cmd->add_flag("--json", options->json, "Print the result as JSON");
  CLI::Option* diverse = cmd->add_option("--diverse", options->diverse,
                  "Print up to K plans pairwise at least --min-distance ground actions apart, then their distances "
                  "(planner/diverse_plans.h)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--min-distance", options->min_distance,
                  "With --diverse: the fewest ground actions (added + removed) any two plans differ by (default 2)")
      ->needs(diverse);
  cmd->add_flag("-q,--quiet", options->quiet, "Do not print warnings about the input");
  cmd->callback([options, shorthand_options, &exit_code] {
    for (const CLI::Option* o : *shorthand_options) {
      if (o->count() > 0) options->shorthands_given.push_back(o->get_name());
    }
    exit_code = run(*options);
  });
}

}  // namespace alplan::cli
