// The planner's hot paths on three named IPC problems: evaluating the
// temporal RPG heuristic, generating successors, updating the simple
// temporal network, and whole searches (states expanded per second).
//   build/benchmarks/planner_benchmark
// and the first plan for each of the paper's scenarios and for three problems
// with continuous change (domains/continuous), grounding included.
#include <benchmark/benchmark.h>

#include <fstream>
#include <memory>
#include <sstream>

#include "pddl_parser/parser.h"
#include "planner/grounder.h"
#include "planner/planner.h"
#include "planner/search_space.h"
#include "planner/successor_generator.h"
#include "planner/task_index.h"
#include "planner/temporal_rpg.h"

namespace {

struct NamedProblem {
  const char* name;
  const char* folder;  // below benchmarks/ipc
  const char* instance;
};

// A logistics-like domain, one with deadlines, one with required concurrency.
constexpr NamedProblem kProblems[] = {
    {"parking-4", "ipc-2011/parking-temporal-satisficing", "instance-4.pddl"},
    {"satellite-tw-5", "ipc-2004/satellite-time-time-windows-strips", "instance-5.pddl"},
    {"match-cellar-5", "ipc-2011/match-cellar-temporal-satisficing", "instance-5.pddl"},
};

// Large groundings (30,546 and 6,915 actions) where evaluating the heuristic
// is nearly all of the search's time: heuristic evaluation only, their
// searches do not end.
constexpr NamedProblem kLargeProblems[] = {
    {"driver-log-2014-5", "ipc-2014/driver-log-temporal-satisficing", "instance-5.pddl"},
    {"satellite-2014-3", "ipc-2014/satellite-temporal-satisficing", "instance-3.pddl"},
};

std::string read(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::shared_ptr<const alplan::GroundTask> load(const NamedProblem& p) {
  const std::string folder = std::string(ALPLAN_SHARED_DIR) + "/benchmarks/ipc/" + p.folder;
  const auto domain = alplan::pddl::parse_domain(read(folder + "/domain.pddl"), "domain.pddl");
  const auto problem = alplan::pddl::parse_problem(read(folder + "/instances/" + p.instance), p.instance);
  if (!domain.ok() || !problem.ok()) return nullptr;
  return alplan::ground(*domain.ast, *problem.ast);
}

// The root of a search and a few states below it, so that the measures are
// not only of the initial state.
struct Sample {
  std::shared_ptr<const alplan::GroundTask> task;
  std::unique_ptr<alplan::TaskIndex> index;
  std::unique_ptr<alplan::SearchSpace> space;
  std::vector<alplan::NodeId> nodes;
};

Sample sample(const NamedProblem& p) {
  Sample s;
  s.task = load(p);
  if (!s.task) return s;
  s.index = std::make_unique<alplan::TaskIndex>(s.task);
  alplan::SearchStart start;
  start.state = alplan::SearchState(s.task->facts.size(), s.task->initial_values);
  for (alplan::FactId f : s.task->initial_facts) start.state.set_fact(f, true);
  s.space = std::make_unique<alplan::SearchSpace>(*s.index, start, 0.001);
  alplan::SearchStatistics stats;
  s.nodes.push_back(s.space->root());
  for (std::size_t i = 0; i < s.nodes.size() && s.nodes.size() < 16; ++i) {
    const alplan::PartialPlan plan = s.space->partial_plan(s.nodes[i]);
    for (alplan::Child& c : s.space->children(s.nodes[i], plan, stats)) {
      if (auto id = s.space->insert(std::move(c), stats)) s.nodes.push_back(*id);
      if (s.nodes.size() >= 16) break;
    }
  }
  return s;
}

void heuristic_evaluation(benchmark::State& state, const NamedProblem& p) {
  Sample s = sample(p);
  if (!s.task) return state.SkipWithError("parse failed");
  alplan::TemporalRpg heuristic(*s.index);
  std::vector<alplan::PartialPlan> plans;
  for (alplan::NodeId n : s.nodes) plans.push_back(s.space->partial_plan(n));
  std::size_t i = 0;
  for (auto _ : state) {
    const std::size_t k = i++ % s.nodes.size();
    benchmark::DoNotOptimize(heuristic.evaluate(s.space->node(s.nodes[k]).state, plans[k]));
  }
  state.counters["facts"] = static_cast<double>(s.task->facts.size());
  state.counters["actions"] = static_cast<double>(s.task->actions.size());
}

void successor_generation(benchmark::State& state, const NamedProblem& p) {
  Sample s = sample(p);
  if (!s.task) return state.SkipWithError("parse failed");
  alplan::SuccessorGenerator generator(*s.index);
  std::vector<alplan::Successor> out;
  std::size_t i = 0, successors = 0;
  for (auto _ : state) {
    out.clear();
    generator.generate(s.space->node(s.nodes[i++ % s.nodes.size()]).state, out);
    successors += out.size();
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["successors"] = benchmark::Counter(static_cast<double>(successors), benchmark::Counter::kAvgIterations);
}

// What a search does per successor: copy the parent's network and add the
// new step with its orderings (three predecessors and a deadline).
void stn_update(benchmark::State& state) {
  const auto n = static_cast<std::uint32_t>(state.range(0));
  alplan::SimpleTemporalNetwork network;
  for (std::uint32_t k = 1; k < n; ++k) {
    std::vector<alplan::TemporalEdge> edges{{k - 1, k, 0.001}};
    if (k >= 4) edges.push_back({k - 4, k, 2.5});
    network.add_node(edges);
  }
  for (auto _ : state) {
    alplan::SimpleTemporalNetwork copy = network;
    const bool ok = copy.add_node({{n - 1, n, 0.001}, {n / 2, n, 1.0}, {n - 3, n, 4.0}, {n, 0, -1e6}});
    benchmark::DoNotOptimize(ok);
  }
}

// The same, when the new constraint pushes earlier steps later (the case
// that needs propagation).
void stn_update_with_propagation(benchmark::State& state) {
  const auto n = static_cast<std::uint32_t>(state.range(0));
  alplan::SimpleTemporalNetwork network;
  for (std::uint32_t k = 1; k < n; ++k) network.add_node({{k - 1, k, 0.001}});
  for (auto _ : state) {
    alplan::SimpleTemporalNetwork copy = network;
    const bool ok = copy.add_node({{0, n, 10.0}, {n, n / 2, 0.001}});
    benchmark::DoNotOptimize(ok);
  }
}

void states_expanded(benchmark::State& state, const NamedProblem& p) {
  auto task = load(p);
  if (!task) return state.SkipWithError("parse failed");
  std::size_t expanded = 0;
  for (auto _ : state) {
    alplan::PlannerOptions options;
    options.search = alplan::alias("gbfs");
    options.time_limit = 30.0;
    alplan::PlannerResult result = alplan::Planner(task, options).plan();
    if (result.status != alplan::PlannerResult::Status::Solved) return state.SkipWithError("not solved");
    expanded += result.statistics.expanded;
  }
  state.counters["expanded"] = benchmark::Counter(static_cast<double>(expanded), benchmark::Counter::kAvgIterations);
  state.counters["expanded/s"] = benchmark::Counter(static_cast<double>(expanded), benchmark::Counter::kIsRate);
}

// The target: a plan for the paper's scenario in under 10 ms,
// grounding included (the problem is parsed once).
void paper_scenario(benchmark::State& state) {
  const std::string dir = std::string(ALPLAN_SOURCE_DIR) + "/domains/assisted_living/";
  const std::string name = "paper-scenario-" + std::to_string(state.range(0)) + ".pddl";
  const auto domain = alplan::pddl::parse_domain(read(dir + "domain.pddl"), "domain.pddl");
  const auto problem = alplan::pddl::parse_problem(read(dir + name), name);
  if (!domain.ok() || !problem.ok()) return state.SkipWithError("parse failed");
  for (auto _ : state) {
    alplan::PlannerOptions options;
    options.epsilon = 0.002;
    alplan::PlannerResult result = alplan::Planner(alplan::ground(*domain.ast, *problem.ast), options).plan();
    if (result.status != alplan::PlannerResult::Status::Solved) return state.SkipWithError("not solved");
    benchmark::DoNotOptimize(result);
  }
}

// Continuous change (domains/continuous): a first plan, grounding included;
// expansions per second show what the linear programs cost the search.
void continuous_first_plan(benchmark::State& state, const char* domain_name, const char* problem_name) {
  const std::string dir = std::string(ALPLAN_SOURCE_DIR) + "/domains/continuous/" + domain_name + "/";
  const std::string name = std::string(problem_name) + ".pddl";
  const auto domain = alplan::pddl::parse_domain(read(dir + "domain.pddl"), "domain.pddl");
  const auto problem = alplan::pddl::parse_problem(read(dir + name), name);
  if (!domain.ok() || !problem.ok()) return state.SkipWithError("parse failed");
  std::size_t expanded = 0;
  for (auto _ : state) {
    alplan::PlannerOptions options;
    options.time_limit = 30.0;
    alplan::PlannerResult result = alplan::Planner(alplan::ground(*domain.ast, *problem.ast), options).plan();
    if (result.status != alplan::PlannerResult::Status::Solved) return state.SkipWithError("not solved");
    expanded += result.statistics.expanded;
  }
  state.counters["expanded/s"] = benchmark::Counter(static_cast<double>(expanded), benchmark::Counter::kIsRate);
}

}  // namespace

int main(int argc, char** argv) {
  for (const NamedProblem& p : kProblems) {
    benchmark::RegisterBenchmark((std::string("HeuristicEvaluation/") + p.name).c_str(), heuristic_evaluation, p)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark((std::string("SuccessorGeneration/") + p.name).c_str(), successor_generation, p)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark((std::string("StatesExpanded/") + p.name).c_str(), states_expanded, p)
        ->Unit(benchmark::kMillisecond);
  }
  for (const NamedProblem& p : kLargeProblems) {
    benchmark::RegisterBenchmark((std::string("HeuristicEvaluation/") + p.name).c_str(), heuristic_evaluation, p)
        ->Unit(benchmark::kMicrosecond);
  }
  benchmark::RegisterBenchmark("StnUpdate", stn_update)->Arg(16)->Arg(64)->Arg(256)->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("StnUpdateWithPropagation", stn_update_with_propagation)
      ->Arg(16)->Arg(64)->Arg(256)->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("PaperScenarioFirstPlan", paper_scenario)->DenseRange(1, 3)->Unit(benchmark::kMillisecond);
  for (const auto& [domain, problem] : {std::pair{"generator", "p03"}, std::pair{"rover-energy", "p02"},
                                        std::pair{"tank", "p02"}}) {
    benchmark::RegisterBenchmark((std::string("ContinuousFirstPlan/") + domain + "-" + problem).c_str(),
                                 continuous_first_plan, domain, problem)
        ->Unit(benchmark::kMillisecond);
  }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
