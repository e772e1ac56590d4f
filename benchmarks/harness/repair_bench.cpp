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
#include "benchmarks/harness/svg_chart.h"
#include "benchmarks/harness/table.h"
#include "domains/emotion_goals.h"
#include "domains/mission_run.h"
#include "domains/paper_scenarios.h"
#include "domains/pddl_files.h"
#include "pddl_parser/writer.h"
#include "repair/monitor.h"
#include "repair/random_events.h"
#include "repair/reformulation.h"
#include "repair/world_simulator.h"

namespace alplan::bench {
namespace {

namespace fs = std::filesystem;

struct RunRecord {
  std::string home, strategy;
  int run = 0;
  bool reached = false;
  std::size_t repairs = 0, stability = 0;
  int planner_calls = 0;
  std::vector<double> latencies_ms;
  std::vector<bool> reused_grounding;  // per repair
  double preparation_ms = 0.0;         // the monitor grounding the home at the start
  // Until the senior is comforted, beyond the original plan's end; none
  // for a run that never comforts the senior (its end is the failure's).
  std::optional<double> delay;
  double makespan = 0.0, cost = 0.0;
  std::string failures, outcome;
};

double percentile(std::vector<double> values, double p) {
  if (values.empty()) return std::nan("");
  std::sort(values.begin(), values.end());
  const double rank = p * static_cast<double>(values.size() - 1);
  const auto low = static_cast<std::size_t>(std::floor(rank));
  const auto high = std::min(values.size() - 1, low + 1);
  return values[low] + (rank - static_cast<double>(low)) * (values[high] - values[low]);
}

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

RunRecord execute(const std::string& home_name, int run, const repair::Mission& mission, const pddl::Problem& problem,
                  const repair::ExecutingPlan& plan, const std::vector<repair::ExogenousEvent>& failures,
                  repair::RepairStrategy& strategy, const repair::TypeOntology& ontology, bool reuse_grounding) {
  std::vector<repair::ExogenousEvent> events = repair::timed_literal_events(problem);
  events.insert(events.end(), failures.begin(), failures.end());
  repair::WorldSimulator world(repair::initial_world(problem), events);
  repair::MonitorOptions monitor_options;
  monitor_options.reuse_grounding = reuse_grounding;
  const repair::Monitor monitor(monitor_options);
  const repair::ExecutionReport report = monitor.run(mission, plan, world, strategy, &world, &ontology);
  RunRecord r;
  r.home = home_name;
  r.run = run;
  r.strategy = strategy.name();
  r.reached = report.goal_reached;
  r.repairs = report.repairs.size();
  for (const repair::RepairRecord& rep : report.repairs) {
    r.latencies_ms.push_back(rep.seconds * 1000.0);
    r.reused_grounding.push_back(rep.reused_grounding);
    r.stability += rep.plan_distance;
    r.planner_calls += rep.planner_calls;
  }
  double planned_end = 0.0;
  for (const repair::ScheduledAction& s : plan.steps) planned_end = std::max(planned_end, s.end());
  r.preparation_ms = report.preparation_seconds * 1000.0;
  r.makespan = report.end_time;
  if (report.goal_reached) r.delay = report.end_time - planned_end;
  const auto cost = world.observe().values.find({"total-cost"});
  r.cost = cost == world.observe().values.end() ? 0.0 : cost->second;
  std::string last;  // the parts of one event (leave a room, enter another) share a description
  for (const repair::ExogenousEvent& e : failures) {
    if (e.description != last) r.failures += (r.failures.empty() ? "" : "; ") + e.description;
    last = e.description;
  }
  r.outcome = report.outcome;
  return r;
}

struct Summary {
  std::string strategy;
  std::size_t runs = 0, reached = 0, repairs = 0, reused_grounding = 0;
  std::vector<double> latencies, delays, makespans, costs, preparations;
  double stability = 0.0, planner_calls = 0.0;
};

std::vector<Summary> summarise(const std::vector<RunRecord>& records, const std::vector<std::string>& order) {
  std::vector<Summary> out;
  for (const std::string& name : order) {
    Summary s;
    s.strategy = name;
    for (const RunRecord& r : records) {
      if (r.strategy != name) continue;
      ++s.runs;
      s.repairs += r.repairs;
      s.latencies.insert(s.latencies.end(), r.latencies_ms.begin(), r.latencies_ms.end());
      s.reused_grounding += static_cast<std::size_t>(std::count(r.reused_grounding.begin(), r.reused_grounding.end(), true));
      if (r.preparation_ms > 0.0) s.preparations.push_back(r.preparation_ms);
      s.stability += static_cast<double>(r.stability);
      s.planner_calls += r.planner_calls;
      if (!r.reached) continue;
      ++s.reached;
      s.delays.push_back(*r.delay);
      s.makespans.push_back(r.makespan);
      s.costs.push_back(r.cost);
    }
    out.push_back(s);
  }
  return out;
}

double mean(const std::vector<double>& v) {
  if (v.empty()) return std::nan("");
  double sum = 0.0;
  for (double x : v) sum += x;
  return sum / static_cast<double>(v.size());
}

void write_outputs(const RepairBenchOptions& o, const std::vector<RunRecord>& records,
                   const std::vector<Summary>& summary, const nlohmann::json& extra, std::ostream& out) {
  Table runs({"home", "run", "strategy", "comforted", "repairs", "latency_ms", "stability", "planner_calls",
              "delay", "makespan", "cost", "failures", "outcome"});
  nlohmann::json runs_json = nlohmann::json::array();
  for (const RunRecord& r : records) {
    std::string latencies;
    for (double l : r.latencies_ms) latencies += (latencies.empty() ? "" : " ") + fixed(l, 3);
    runs.add({r.home, std::to_string(r.run), r.strategy, r.reached ? "yes" : "no", std::to_string(r.repairs),
              latencies, std::to_string(r.stability), std::to_string(r.planner_calls), r.delay ? fixed(*r.delay, 3) : "",
              fixed(r.makespan, 3), fixed(r.cost, 1), r.failures, r.outcome});
    runs_json.push_back({{"home", r.home}, {"run", r.run}, {"strategy", r.strategy}, {"comforted", r.reached},
                         {"repairs", r.repairs}, {"latency_ms", r.latencies_ms},
                         {"reused_grounding", r.reused_grounding}, {"preparation_ms", r.preparation_ms},
                         {"stability", r.stability},
                         {"planner_calls", r.planner_calls}, {"delay", r.delay ? nlohmann::json(*r.delay) : nlohmann::json()},
                         {"makespan", r.makespan},
                         {"cost", r.cost}, {"failures", r.failures}, {"outcome", r.outcome}});
  }
  Table table({"strategy", "comforted", "repairs", "latency median ms", "latency p95 ms", "stability/run",
               "delay", "makespan", "cost", "planner calls/run", "grounding reused"});
  nlohmann::json summary_json = nlohmann::json::array();
  std::map<std::string, std::vector<Bar>> plots;
  for (const Summary& s : summary) {
    const double runs_count = std::max<double>(1.0, static_cast<double>(s.runs));
    const double success = static_cast<double>(s.reached) / runs_count;
    const double median = percentile(s.latencies, 0.5), p95 = percentile(s.latencies, 0.95);
    table.add({s.strategy, std::to_string(s.reached) + "/" + std::to_string(s.runs), std::to_string(s.repairs),
               fixed(median, 3), fixed(p95, 3), fixed(s.stability / runs_count, 2), fixed(mean(s.delays), 1),
               fixed(mean(s.makespans), 1), fixed(mean(s.costs), 1), fixed(s.planner_calls / runs_count, 2),
               std::to_string(s.reused_grounding) + "/" + std::to_string(s.repairs)});
    summary_json.push_back({{"strategy", s.strategy}, {"runs", s.runs}, {"comforted", s.reached},
                            {"success_rate", success}, {"repairs", s.repairs}, {"latency_median_ms", median},
                            {"latency_p95_ms", p95}, {"stability_per_run", s.stability / runs_count},
                            {"delay_mean", mean(s.delays)}, {"makespan_mean", mean(s.makespans)},
                            {"cost_mean", mean(s.costs)}, {"planner_calls_per_run", s.planner_calls / runs_count},
                            {"repairs_reusing_grounding", s.reused_grounding},
                            {"preparation_median_ms", s.preparations.empty() ? nlohmann::json() : nlohmann::json(percentile(s.preparations, 0.5))}});
    plots["success-rate"].push_back({s.strategy, success});
    plots["latency-median-ms"].push_back({s.strategy, median});
    plots["latency-p95-ms"].push_back({s.strategy, p95});
    plots["stability"].push_back({s.strategy, s.stability / runs_count});
    plots["delay"].push_back({s.strategy, mean(s.delays)});
    plots["makespan"].push_back({s.strategy, mean(s.makespans)});
    plots["cost"].push_back({s.strategy, mean(s.costs)});
    plots["planner-calls"].push_back({s.strategy, s.planner_calls / runs_count});
  }
  fs::create_directories(fs::path(o.out_dir) / "plots");
  std::ofstream(fs::path(o.out_dir) / "runs.csv") << [&] { std::ostringstream s; runs.write_csv(s); return s.str(); }();
  std::ofstream(fs::path(o.out_dir) / "runs.json") << runs_json.dump(2) << "\n";
  nlohmann::json all = {{"strategies", summary_json}, {"options", {{"homes", o.homes}, {"runs_per_home", o.runs_per_home},
                        {"failures_per_run", o.failures_per_run}, {"seed", o.seed}, {"rooms", o.home.rooms},
                        {"seniors", o.home.seniors}, {"objects", o.home.objects}}}};
  all.update(extra);
  std::ofstream(fs::path(o.out_dir) / "summary.json") << all.dump(2) << "\n";
  const std::map<std::string, std::string> units{{"success-rate", "fraction of runs"}, {"latency-median-ms", "ms"},
      {"latency-p95-ms", "ms"}, {"stability", "actions removed + added per run"}, {"delay", "time units"},
      {"makespan", "time units"}, {"cost", "total-cost"}, {"planner-calls", "per run"}};
  for (const auto& [metric, bars] : plots) {
    std::ofstream(fs::path(o.out_dir) / "plots" / (metric + ".svg")) << bar_chart_svg(metric, units.at(metric), bars);
  }
  std::ofstream md(fs::path(o.out_dir) / "summary.md");
  table.print_markdown(md);
  for (const auto& [key, value] : extra.items()) md << "\n" << key << ": " << value.dump() << "\n";
  table.print(out);
  for (const auto& [key, value] : extra.items()) out << key << ": " << value.dump() << "\n";
}

}  // namespace

int run_repair_bench(const RepairBenchOptions& o, std::ostream& out, std::ostream& progress) {
  const domains::LoadedFiles paper = domains::load_pddl(o.assisted_living_dir + "/domain.pddl",
                                                        o.assisted_living_dir + "/paper-scenario-1.pddl");
  const repair::TypeOntology ontology = repair::TypeOntology::from_file(o.assisted_living_dir + "/types.ttl");
  const pddl::Domain domain = repair::augment_domain(*paper.domain, ontology);
  repair::StrategyOptions strategy_options = o.strategy_options;
  strategy_options.planner.epsilon = o.epsilon;
  strategy_options.planner.time_limit = o.planning_time;
  std::vector<std::unique_ptr<repair::RepairStrategy>> strategies;
  std::vector<std::string> order;
  for (const std::string& name : o.strategies) {
    strategies.push_back(repair::make_strategy(name, strategy_options));
    order.push_back(name);
  }
  if (o.external) {
    fs::create_directories(fs::path(o.out_dir) / "external");
    strategies.push_back(std::make_unique<ExternalReplan>(
        ExternalPlannerOptions{o.alplan, (fs::path(o.out_dir) / "external").string(), o.epsilon, o.planning_time}));
    order.push_back("replan-external");
  }
  std::vector<RunRecord> records;
  for (int h = 0; h < o.homes; ++h) {
    domains::HomeOptions home_options = o.home;
    home_options.seed = o.seed + static_cast<std::uint64_t>(h);
    const domains::GeneratedHome home = domains::generate_home(home_options);
    const std::string name = "home-" + std::to_string(home_options.seed);
    const domains::LoadedFiles files =
        domains::load_pddl_text(pddl::write_domain(*paper.domain), "domain.pddl", home.problem, name + ".pddl");
    PlannerOptions initial;
    initial.epsilon = o.epsilon;
    initial.time_limit = o.planning_time;
    const repair::PlanningOutcome planned = repair::plan_in_process(domain, *files.problem, 0.0, initial);
    if (!planned.plan) {
      progress << name << ": no initial plan (" << planned.message << "), skipped\n";
      continue;
    }
    const repair::Mission mission = mission_for(domain, *files.problem, home);
    for (int run = 0; run < o.runs_per_home; ++run) {
      repair::RandomEventOptions events = o.events;
      events.seed = home_options.seed * 1000003u + static_cast<std::uint64_t>(run);
      repair::RandomEventGenerator generator(events);
      std::vector<repair::ExogenousEvent> failures;
      for (int k = 0; k < o.failures_per_run; ++k) {
        for (repair::ExogenousEvent& e : generator.draw(*planned.plan, *files.problem, &ontology, k + 1)) {
          failures.push_back(e);
        }
      }
      for (auto& strategy : strategies) {
        records.push_back(execute(name, run, mission, *files.problem, *planned.plan, failures, *strategy, ontology,
                                  o.reuse_grounding));
        const RunRecord& r = records.back();
        progress << "[" << name << " run " << run << "] " << r.strategy << ": " << (r.reached ? "comforted" : "not comforted")
                 << ", " << r.repairs << " repairs\n";
      }
    }
  }
  nlohmann::json extra = nlohmann::json::object();
  // The paper's home: its three scenarios, per strategy.
  for (const std::string& name : o.strategies) {
    std::vector<double> latencies;
    for (const domains::PaperScenario& scenario : domains::paper_scenarios()) {
      domains::ScenarioOptions so;
      so.assisted_living_dir = o.assisted_living_dir;
      so.strategy = name;
      so.strategy_options = o.strategy_options;
      so.monitor.reuse_grounding = o.reuse_grounding;
      const domains::ScenarioRun run = domains::run_paper_scenario(scenario, so);
      for (const repair::RepairRecord& r : run.report.repairs) latencies.push_back(r.seconds * 1000.0);
    }
    extra["paper_home_latency_median_ms"][name] = percentile(latencies, 0.5);
  }
  const std::vector<Summary> summary = summarise(records, order);
  if (o.external) {
    std::vector<double> inside, outside;
    for (const RunRecord& r : records) {
      if (r.strategy == "replan") inside.insert(inside.end(), r.latencies_ms.begin(), r.latencies_ms.end());
      if (r.strategy == "replan-external") outside.insert(outside.end(), r.latencies_ms.begin(), r.latencies_ms.end());
    }
    extra["external_over_in_process_latency_ratio"] = percentile(outside, 0.5) / percentile(inside, 0.5);
  }
  write_outputs(o, records, summary, extra, out);
  return 0;
}

}  // namespace alplan::bench
