#include "benchmarks/harness/repair_bench.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "benchmarks/harness/external_replan.h"
#include "benchmarks/harness/repair_study.h"
#include "benchmarks/harness/table.h"
#include "domains/emotion_goals.h"
#include "domains/mission_run.h"
#include "domains/paper_scenarios.h"
#include "domains/pddl_files.h"
#include "pddl_parser/writer.h"
#include "planner/progress_meter.h"
#include "repair/monitor.h"
#include "repair/random_events.h"
#include "repair/reformulation.h"
#include "repair/world_simulator.h"
#include "stats/quantile.h"

namespace alplan::bench {
namespace {

namespace fs = std::filesystem;

struct RunRecord {
  std::string home, strategy;
  std::string kind;  // the failure kind drawn
  int run = 0;
  bool reached = false;
  std::size_t repairs = 0, stability = 0;
  // Repairs where the strategy could not do its own and did another's
  // (switch with no alternative executable replans): how often a strategy
  // was itself.
  std::size_t fallbacks = 0;
  int planner_calls = 0;
  std::vector<double> latencies_ms;
  std::vector<bool> reused_grounding;  // per repair
  double preparation_ms = 0.0;         // the monitor grounding the home at the start
  double perception_ms = 0.0;          // of the latencies: substitution asking perception
  std::size_t sightings = 0;           // new things the camera saw
  std::size_t void_actions = 0;        // actions that came to nothing in the world (world.h)
  std::size_t search_steps = 0;        // of the repairs: places looked in for a senior lost from sight
  // Until the senior is comforted, beyond the original plan's end; none
  // for a run that never comforts the senior (its end is the failure's).
  std::optional<double> delay;
  double makespan = 0.0, cost = 0.0;
  std::string failures, outcome;
};

// Why the robot acts, and goal generation for the stressed seniors, so
// that an emotion change gives a new goal (as in the paper's scenarios).
repair::Mission mission_for(const pddl::Domain& domain, const pddl::Problem& problem,
                            const domains::GeneratedHome& home) {
  repair::Mission mission;
  mission.exogenous_predicates = domains::exogenous_predicates();
  mission.domain = &domain;
  mission.problem = problem;
  std::vector<std::string> seniors;
  for (const domains::StressedSenior& s : home.stressed) {
    seniors.push_back(s.name);
    mission.motivation += (mission.motivation.empty() ? "" : " and ") + s.name + " is " + s.emotion;
  }
  mission.goal_generator = domains::emotion_goal_generator(seniors);
  return mission;
}

// One run's failures, as every strategy meets them.
struct DrawnFailures {
  std::string kind;
  std::vector<repair::ExogenousEvent> events;
};

RunRecord execute(const std::string& home_name, int run, const repair::Mission& mission, const pddl::Problem& problem,
                  const repair::ExecutingPlan& plan, const DrawnFailures& drawn, repair::RepairStrategy& strategy,
                  const repair::TypeOntology& ontology, const RepairBenchOptions& o) {
  const std::vector<repair::ExogenousEvent>& failures = drawn.events;
  std::vector<repair::ExogenousEvent> events = repair::timed_literal_events(problem);
  events.insert(events.end(), failures.begin(), failures.end());
  repair::WorldSimulator world(repair::initial_world(problem), events);
  repair::MonitorOptions monitor_options;
  monitor_options.reuse_grounding = o.reuse_grounding;
  monitor_options.observation = o.observation;
  const repair::Monitor monitor(monitor_options);
  const std::unique_ptr<repair::ObjectRecognizer> camera = o.camera ? o.camera(world) : nullptr;
  repair::ObjectRecognizer* eyes = camera ? camera.get() : &world;
  const repair::ExecutionReport report = monitor.run(mission, plan, world, strategy, eyes, &ontology);
  RunRecord r;
  r.home = home_name;
  r.run = run;
  r.strategy = strategy.name();
  r.kind = drawn.kind;
  r.reached = report.goal_reached;
  r.sightings = report.sightings;
  r.void_actions = report.void_actions;
  r.repairs = report.repairs.size();
  for (const repair::RepairRecord& rep : report.repairs) {
    r.latencies_ms.push_back(rep.seconds * 1000.0);
    r.perception_ms += rep.perception_seconds * 1000.0;
    r.reused_grounding.push_back(rep.reused_grounding);
    r.stability += rep.plan_distance;
    r.planner_calls += rep.planner_calls;
    r.fallbacks += rep.fallback.empty() ? 0 : 1;
    r.search_steps += rep.search ? 1 : 0;
  }
  double planned_end = 0.0;
  for (const repair::ScheduledAction& s : plan.steps) planned_end = std::max(planned_end, s.end());
  r.preparation_ms = report.preparation_seconds * 1000.0;
  r.makespan = report.end_time;
  if (report.goal_reached) r.delay = report.end_time - planned_end;
  // observe() returns a copy: keep it alive while its iterator is read.
  const repair::WorldState final_state = world.observe();
  const auto cost = final_state.values.find({"total-cost"});
  r.cost = cost == final_state.values.end() ? 0.0 : cost->second;
  std::string last;  // the parts of one event (leave a room, enter another) share a description
  for (const repair::ExogenousEvent& e : failures) {
    if (e.description != last) r.failures += (r.failures.empty() ? "" : "; ") + e.description;
    last = e.description;
  }
  r.outcome = report.outcome;
  return r;
}

std::vector<StudyRun> study_runs(const std::vector<RunRecord>& records) {
  std::vector<StudyRun> out;
  for (const RunRecord& r : records) {
    StudyRun s;
    s.home = r.home;
    s.run = r.run;
    s.strategy = r.strategy;
    s.kind = r.kind;
    s.comforted = r.reached;
    s.latencies_ms = r.latencies_ms;
    s.perception_ms = r.perception_ms;
    s.stability = static_cast<double>(r.stability);
    s.planner_calls = r.planner_calls;
    s.repairs = r.repairs;
    if (r.reached) {
      s.delay = r.delay;
      s.makespan = r.makespan;
      s.cost = r.cost;
    }
    out.push_back(std::move(s));
  }
  return out;
}

nlohmann::json to_json(const RunRecord& r) {
  return {{"home", r.home}, {"run", r.run}, {"kind", r.kind}, {"strategy", r.strategy}, {"comforted", r.reached},
          {"repairs", r.repairs}, {"latency_ms", r.latencies_ms}, {"perception_ms", r.perception_ms},
          {"reused_grounding", r.reused_grounding}, {"preparation_ms", r.preparation_ms},
          {"stability", r.stability}, {"fallbacks", r.fallbacks}, {"planner_calls", r.planner_calls},
          {"delay", r.delay ? nlohmann::json(*r.delay) : nlohmann::json()}, {"makespan", r.makespan},
          {"cost", r.cost}, {"sightings", r.sightings}, {"void_actions", r.void_actions},
          {"search_steps", r.search_steps}, {"failures", r.failures}, {"outcome", r.outcome}};
}

RunRecord record_from_json(const nlohmann::json& j) {
  RunRecord r;
  r.home = j.at("home");
  r.run = j.at("run");
  r.kind = j.at("kind");
  r.strategy = j.at("strategy");
  r.reached = j.at("comforted");
  r.repairs = j.at("repairs");
  r.latencies_ms = j.at("latency_ms").get<std::vector<double>>();
  r.perception_ms = j.at("perception_ms");
  r.reused_grounding = j.at("reused_grounding").get<std::vector<bool>>();
  r.preparation_ms = j.at("preparation_ms");
  r.stability = j.at("stability");
  r.planner_calls = j.at("planner_calls");
  r.fallbacks = j.value("fallbacks", std::size_t{0});  // runs written before it was counted have none
  if (!j.at("delay").is_null()) r.delay = j.at("delay").get<double>();
  r.makespan = j.at("makespan");
  r.cost = j.at("cost");
  r.sightings = j.at("sightings");
  r.void_actions = j.value("void_actions", std::size_t{0});  // runs written before the world checked conditions
  r.search_steps = j.value("search_steps", std::size_t{0});  // runs written before the robot searched
  r.failures = j.at("failures");
  r.outcome = j.at("outcome");
  return r;
}

void write_runs(const RepairBenchOptions& o, const std::vector<RunRecord>& records) {
  Table runs({"home", "run", "kind", "strategy", "comforted", "repairs", "latency_ms", "perception_ms", "stability",
              "planner_calls", "delay", "makespan", "cost", "sightings", "failures", "outcome"});
  nlohmann::json runs_json = nlohmann::json::array();
  for (const RunRecord& r : records) {
    std::string latencies;
    for (double l : r.latencies_ms) latencies += (latencies.empty() ? "" : " ") + fixed(l, 3);
    runs.add({r.home, std::to_string(r.run), r.kind, r.strategy, r.reached ? "yes" : "no", std::to_string(r.repairs),
              latencies, fixed(r.perception_ms, 3), std::to_string(r.stability), std::to_string(r.planner_calls),
              r.delay ? fixed(*r.delay, 3) : "", fixed(r.makespan, 3), fixed(r.cost, 1), std::to_string(r.sightings),
              r.failures, r.outcome});
    runs_json.push_back(to_json(r));
  }
  std::ofstream(fs::path(o.out_dir) / "runs.csv") << [&] { std::ostringstream s; runs.write_csv(s); return s.str(); }();
  std::ofstream(fs::path(o.out_dir) / "runs.json") << runs_json.dump(2) << "\n";
}

void write_outputs(const RepairBenchOptions& o, const std::vector<RunRecord>& records,
                   const std::vector<std::string>& order, const nlohmann::json& extra, std::ostream& out) {
  fs::create_directories(fs::path(o.out_dir) / "plots");
  write_runs(o, records);
  const std::string reference = std::find(order.begin(), order.end(), "replan") != order.end() ? "replan" : order.front();
  const StudyAnalysis study = analyse_repair_study(study_runs(records), order, reference, o.bootstrap);
  nlohmann::json all = study.json;
  all["options"] = {{"homes", o.homes}, {"runs_per_home", o.runs_per_home}, {"failures_per_run", o.failures_per_run},
                    {"seed", o.seed}, {"rooms", o.home.rooms}, {"seniors", o.home.seniors},
                    {"objects", o.home.objects}, {"iot_share", o.home.iot_share}, {"scatter", o.home.scatter},
                    {"observe", repair::to_string(o.observation.model)},
                    {"search_lost_persons", o.observation.search_lost_persons}, {"executions", records.size()}};
  all.update(extra);
  std::ofstream(fs::path(o.out_dir) / "summary.json") << all.dump(2) << "\n";
  for (const auto& [file, svg] : study.plots) std::ofstream(fs::path(o.out_dir) / "plots" / file) << svg;
  std::ostringstream head;
  head << "# Repair study\n\n" << o.homes << " generated homes x " << o.runs_per_home << " runs, seed " << o.seed
       << ", observation model " << repair::to_string(o.observation.model) << ", " << records.size()
       << " executions; every strategy meets the same failures.\n\n";
  if (o.home.scatter > 0.0) head << "- a share " << o.home.scatter << " of objects left away from their room\n";
  if (!o.observation.search_lost_persons) head << "- a senior the robot finds gone is not searched for (--no-search)\n";
  head << "- grounding reused by " << extra.value("repairs_reusing_grounding", 0) << " of " << extra.value("repairs", 0)
       << " repair attempts (the grounding made when execution starts, repair/monitor.h)\n";
  for (const auto& [key, value] : extra.items()) head << "- " << key << ": " << value.dump() << "\n";
  std::ofstream(fs::path(o.out_dir) / "summary.md") << head.str() << "\n" << study.markdown;
  out << head.str() << "\n" << study.markdown;
}

// The failures of one run: `failures_per_run` draws, their kinds joined.
DrawnFailures draw_failures(const RepairBenchOptions& o, std::uint64_t seed, const repair::ExecutingPlan& plan,
                            const pddl::Problem& problem, const repair::TypeOntology& ontology) {
  repair::RandomEventOptions events = o.events;
  events.seed = seed;
  repair::RandomEventGenerator generator(events);
  DrawnFailures drawn;
  for (int k = 0; k < o.failures_per_run; ++k) {
    const std::optional<repair::RandomFailure> f = generator.draw_failure(plan, problem, &ontology, k + 1);
    if (!f) continue;
    drawn.kind += (drawn.kind.empty() ? "" : "+") + repair::to_string(f->kind);
    drawn.events.insert(drawn.events.end(), f->events.begin(), f->events.end());
  }
  if (drawn.kind.empty()) drawn.kind = "none";
  return drawn;
}

// The paper's home: its three scenarios, per strategy.
nlohmann::json paper_home_latencies(const RepairBenchOptions& o) {
  nlohmann::json medians;
  for (const std::string& name : o.strategies) {
    std::vector<double> latencies;
    for (const domains::PaperScenario& scenario : domains::paper_scenarios()) {
      domains::ScenarioOptions so;
      so.assisted_living_dir = o.assisted_living_dir;
      so.strategy = name;
      so.strategy_options = o.strategy_options;
      so.monitor.reuse_grounding = o.reuse_grounding;
      so.monitor.observation = o.observation;
      const domains::ScenarioRun run = domains::run_paper_scenario(scenario, so);
      for (const repair::RepairRecord& r : run.report.repairs) latencies.push_back(r.seconds * 1000.0);
    }
    medians[name] = stats::nearest_rank(latencies, 0.5);
  }
  return medians;
}

// What every home's executions share: the domain with the ontology's
// types, and the strategies, built once.
struct StudySetup {
  domains::LoadedFiles paper;
  repair::TypeOntology ontology;
  pddl::Domain domain;
  std::vector<std::unique_ptr<repair::RepairStrategy>> strategies;
  std::vector<std::string> order;
};

std::unique_ptr<StudySetup> prepare_study(const RepairBenchOptions& o, const std::string& external_dir) {
  auto setup = std::make_unique<StudySetup>(StudySetup{
      domains::load_pddl(o.assisted_living_dir + "/domain.pddl", o.assisted_living_dir + "/paper-scenario-1.pddl"),
      repair::TypeOntology::from_file(o.assisted_living_dir + "/types.ttl"), pddl::Domain{}, {}, {}});
  setup->domain = repair::augment_domain(*setup->paper.domain, setup->ontology);
  repair::StrategyOptions strategy_options = o.strategy_options;
  strategy_options.planner.epsilon = o.epsilon;
  strategy_options.planner.time_limit = o.planning_time;
  // Repairs are judged by the metric (a suggestion costs 500): a first plan
  // found by step count would suggest wherever it can, whichever objects a
  // strategy brings in. A short anytime search, the same for every strategy.
  if (o.repair_anytime) {
    strategy_options.planner.search =
        with_anytime(strategy_options.planner.search, o.repair_min_weight, o.repair_expansions);
  }
  for (const std::string& name : o.strategies) {
    setup->strategies.push_back(repair::make_strategy(name, strategy_options));
    setup->order.push_back(name);
  }
  if (o.external) {
    fs::create_directories(external_dir);
    setup->strategies.push_back(std::make_unique<ExternalReplan>(
        ExternalPlannerOptions{o.alplan, external_dir, o.epsilon, o.planning_time}));
    setup->order.push_back("replan-external");
  }
  return setup;
}

// Home number h's executions: its runs, each met by every strategy.
std::vector<RunRecord> run_home(StudySetup& setup, int h, const RepairBenchOptions& o, std::ostream& progress) {
  domains::HomeOptions home_options = o.home;
  home_options.seed = o.seed + static_cast<std::uint64_t>(h);
  const domains::GeneratedHome home = domains::generate_home(home_options);
  const std::string name = "home-" + std::to_string(home_options.seed);
  const domains::LoadedFiles files =
      domains::load_pddl_text(pddl::write_domain(*setup.paper.domain), "domain.pddl", home.problem, name + ".pddl");
  // As a mission plans (domains/mission_run.h): the best plan found in a
  // short anytime search, since the metric penalises suggestions and the
  // first plan found often suggests.
  PlannerOptions initial = repair::executing_planner_options();
  initial.epsilon = o.epsilon;
  initial.search = with_anytime(initial.search, 1.0, o.initial_expansions);
  initial.time_limit = std::min(o.planning_time, o.initial_planning_time);
  const repair::PlanningOutcome planned = repair::plan_in_process(setup.domain, *files.problem, 0.0, initial);
  std::vector<RunRecord> records;
  if (!planned.plan) {
    progress << name << ": no initial plan (" << planned.message << "), skipped\n";
    return records;
  }
  const repair::Mission mission = mission_for(setup.domain, *files.problem, home);
  for (int run = 0; run < o.runs_per_home; ++run) {
    const DrawnFailures drawn = draw_failures(o, home_options.seed * 1000003u + static_cast<std::uint64_t>(run),
                                              *planned.plan, *files.problem, setup.ontology);
    progress << "[" << name << " run " << run << ", " << drawn.kind << "]";
    for (auto& strategy : setup.strategies) {
      records.push_back(
          execute(name, run, mission, *files.problem, *planned.plan, drawn, *strategy, setup.ontology, o));
      progress << " " << records.back().strategy << ":" << (records.back().reached ? "comforted" : "not");
    }
    progress << "\n";
  }
  return records;
}

nlohmann::json camera_description(const RepairBenchOptions& o) {
  return o.camera ? o.camera_info : nlohmann::json("the simulator names what it made (no perception)");
}

nlohmann::json summary_extra(const RepairBenchOptions& o, const std::vector<RunRecord>& records,
                             const nlohmann::json& paper_home, const nlohmann::json& camera) {
  nlohmann::json extra = nlohmann::json::object();
  extra["camera"] = camera;
  std::size_t repairs = 0, reused = 0;
  for (const RunRecord& r : records) {
    repairs += r.reused_grounding.size();
    reused += static_cast<std::size_t>(std::count(r.reused_grounding.begin(), r.reused_grounding.end(), true));
  }
  extra["repairs"] = repairs;
  extra["repairs_reusing_grounding"] = reused;
  if (o.paper_home) extra["paper_home_latency_median_ms"] = paper_home;
  if (o.external) {
    std::vector<double> inside, outside;
    for (const RunRecord& r : records) {
      if (r.strategy == "replan") inside.insert(inside.end(), r.latencies_ms.begin(), r.latencies_ms.end());
      if (r.strategy == "replan-external") outside.insert(outside.end(), r.latencies_ms.begin(), r.latencies_ms.end());
    }
    extra["external_over_in_process_latency_ratio"] = stats::nearest_rank(outside, 0.5) / stats::nearest_rank(inside, 0.5);
  }
  return extra;
}

int write_study(const RepairBenchOptions& o, const std::vector<RunRecord>& records, const std::vector<std::string>& order,
                const nlohmann::json& paper_home, const nlohmann::json& camera, std::ostream& out,
                std::ostream& progress) {
  if (records.empty()) {
    progress << "error: no home had an initial plan\n";
    return 2;
  }
  write_outputs(o, records, order, summary_extra(o, records, paper_home, camera), out);
  return 0;
}

// Array items: the homes, then the paper's home when it is timed.
int study_items(const RepairBenchOptions& o) { return o.homes + (o.paper_home ? 1 : 0); }

void submit_study(const RepairBenchOptions& o, std::ostream& out) {
  ArrayManifest m;
  m.kind = "repair";
  m.working_dir = fs::current_path().string();
  m.command = o.array.command;
  m.slurm = o.array.slurm;
  auto item_name = [&](int i) {
    return i < o.homes ? "home-" + std::to_string(o.seed + static_cast<std::uint64_t>(i)) : std::string("paper-home");
  };
  const int n = study_items(o);
  for (int t = 0; t < array_tasks(n, m.slurm.batch); ++t) {
    const auto [first, last] = task_items(t, n, m.slurm.batch);
    m.tasks.push_back(item_name(first) + (last - first > 1 ? " .. " + item_name(last - 1) : ""));
  }
  submit_array(o.array.dir, m, out);
}

void run_study_task(const RepairBenchOptions& o, std::ostream& progress) {
  const ArrayManifest m = read_manifest(o.array.dir);
  const int n = study_items(o);
  if (o.array.task < 0 || o.array.task >= array_tasks(n, m.slurm.batch)) {
    throw std::runtime_error("no array task " + std::to_string(o.array.task) + " in " + o.array.dir);
  }
  // Concurrent tasks must not share the external planner's files.
  const std::unique_ptr<StudySetup> setup =
      prepare_study(o, (fs::path(o.out_dir) / "external" / ("task-" + std::to_string(o.array.task))).string());
  const auto [first, last] = task_items(o.array.task, n, m.slurm.batch);
  nlohmann::json result{{"records", nlohmann::json::array()}, {"camera", camera_description(o)}};
  for (int i = first; i < last; ++i) {
    if (i == o.homes) {
      result["paper_home"] = paper_home_latencies(o);
      continue;
    }
    for (const RunRecord& r : run_home(*setup, i, o, progress)) result["records"].push_back(to_json(r));
  }
  write_task_result(o.array.dir, o.array.task, result);
}

int merge_study(const RepairBenchOptions& o, std::ostream& out, std::ostream& progress) {
  const ArrayManifest m = read_manifest(o.array.dir);
  const CollectedTasks tasks = collect_tasks(o.array.dir, m);
  if (!tasks.complete()) throw std::runtime_error("not every task has finished: run `alplan bench merge`");
  std::vector<RunRecord> records;
  nlohmann::json paper_home, camera;
  for (const auto& [t, result] : tasks.results) {
    for (const nlohmann::json& j : result.at("records")) records.push_back(record_from_json(j));
    if (result.contains("paper_home")) paper_home = result["paper_home"];
    camera = result.at("camera");  // every task trained the same camera; the last one's figures
  }
  std::vector<std::string> order = o.strategies;
  if (o.external) order.push_back("replan-external");
  return write_study(o, records, order, paper_home, camera, out, progress);
}

}  // namespace

std::vector<StudyRun> load_study_runs(const std::string& runs_json) {
  std::ifstream in(runs_json);
  if (!in) throw std::runtime_error(runs_json + ": cannot be read");
  std::vector<RunRecord> records;
  for (const nlohmann::json& j : nlohmann::json::parse(in)) records.push_back(record_from_json(j));
  return study_runs(records);
}

int run_repair_bench(const RepairBenchOptions& o, std::ostream& out, std::ostream& progress) {
  switch (o.array.role) {
    case ArrayRole::submit:
      submit_study(o, out);
      return 0;
    case ArrayRole::task:
      run_array_task(o.array.dir, o.array.task, [&] { run_study_task(o, progress); });
      return 0;
    case ArrayRole::merge:
      return merge_study(o, out, progress);
    case ArrayRole::local:
      break;
  }
  const std::unique_ptr<StudySetup> setup = prepare_study(o, (fs::path(o.out_dir) / "external").string());
  std::vector<RunRecord> records;
  ProgressMeter meter(progress, o.homes, "homes", o.progress_bar);
  for (int h = 0; h < o.homes; ++h) {
    std::ostringstream lines;  // the home's runs, printed above the bar
    std::vector<RunRecord> home = run_home(*setup, h, o, lines);
    records.insert(records.end(), home.begin(), home.end());
    std::string text = lines.str();
    if (!text.empty() && text.back() == '\n') text.pop_back();
    meter.update(h + 1, text);
  }
  meter.finish();
  const nlohmann::json paper_home = o.paper_home ? paper_home_latencies(o) : nlohmann::json();
  return write_study(o, records, setup->order, paper_home, camera_description(o), out, progress);
}

}  // namespace alplan::bench
