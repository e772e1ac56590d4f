// One in-process repair, as `alplan bench repair` times it (reformulate,
// ground, plan from the observed state, bind the plan), and its stages, on
// the default generated home (seed 1) and on the paper's home:
//   build/benchmarks/repair_benchmark
// The failure: the stressed senior has moved to another room, so the whole
// plan must be made again; at time 0 (the planner validates from the
// initial state) and at time 1 (from an observed state, as in execution).
#include <benchmark/benchmark.h>

#include <memory>

#include "domains/home_generator.h"
#include "domains/mission_run.h"
#include "domains/pddl_files.h"
#include "pddl_parser/writer.h"
#include "planner/grounder.h"
#include "planner/grounding_cache.h"
#include "repair/reformulation.h"
#include "repair/repair_strategy.h"
#include "repair/type_ontology.h"
#include "repair/world_simulator.h"

namespace {

using namespace alplan;

const std::string kAssistedLiving = std::string(ALPLAN_SOURCE_DIR) + "/domains/assisted_living";

struct Fixture {
  pddl::Domain domain;  // with the ontology's types
  pddl::Problem problem;
  repair::ExecutingPlan plan;
  Violation failure;
  repair::WorldState observed;
  repair::RepairRequest request(double now) const {
    repair::RepairRequest r;
    r.now = now;
    r.domain = &domain;
    r.problem = &problem;
    r.plan = &plan;
    r.failure = &failure;
    r.observed = observed;
    r.robot_location = "kitchen1";
    return r;
  }
};

// The senior's room, and another private room to move to.
void move_senior(repair::WorldState& world, const std::string& senior) {
  std::string from;
  for (const repair::AtomKey& a : world.atoms) {
    if (a.size() == 3 && a[0] == "be" && a[1] == senior) from = a[2];
  }
  const std::string to = from == "bedroom1" ? "bedroom2" : "bedroom1";
  world.set({"be", senior, from}, false);
  world.set({"be", senior, to}, true);
}

Fixture fixture(const std::string& problem_text) {
  const domains::LoadedFiles paper =
      domains::load_pddl(kAssistedLiving + "/domain.pddl", kAssistedLiving + "/paper-scenario-1.pddl");
  const repair::TypeOntology ontology = repair::TypeOntology::from_file(kAssistedLiving + "/types.ttl");
  Fixture f;
  f.domain = repair::augment_domain(*paper.domain, ontology);
  f.problem = problem_text.empty()
                  ? *paper.problem
                  : *domains::load_pddl_text(pddl::write_domain(*paper.domain), "domain.pddl", problem_text,
                                             "home.pddl").problem;
  const repair::PlanningOutcome planned = repair::plan_in_process(f.domain, f.problem, 0.0, PlannerOptions{});
  if (!planned.plan) throw std::runtime_error("no initial plan: " + planned.message);
  f.plan = *planned.plan;
  f.failure.kind = Violation::Kind::UnsatisfiedPrecondition;
  f.observed = repair::initial_world(f.problem);
  move_senior(f.observed, "senior1");
  return f;
}

const Fixture& generated_home() {
  static const Fixture f = fixture(domains::generate_home(domains::HomeOptions{}).problem);
  return f;
}

const Fixture& paper_home() {
  static const Fixture f = fixture("");
  return f;
}

void replan(benchmark::State& state, const Fixture& f, double now) {
  const std::unique_ptr<repair::RepairStrategy> strategy = repair::make_strategy("replan", {});
  const repair::RepairRequest request = f.request(now);
  for (auto _ : state) {
    const repair::RepairResult result = strategy->repair(request);
    if (!result.repaired) state.SkipWithError("no repair");
    benchmark::DoNotOptimize(result);
  }
}

// The monitor's way: the home is ground once when execution starts, and a
// replan reuses that grounding when the observed world fits it -- here an
// object the plan carries has become unavailable.
void replan_reusing_grounding(benchmark::State& state, const Fixture& f, double now) {
  const std::unique_ptr<repair::RepairStrategy> strategy = repair::make_strategy("replan", {});
  GroundingOptions options;
  options.names.exogenous_predicates = domains::exogenous_predicates();
  GroundingCache cache(options);
  cache.ground(f.domain, f.problem);
  repair::RepairRequest request = f.request(now);
  request.grounding = &cache;
  // An object whose loss leaves the senior a remedy (another of its kind).
  const GroundTask& task = *f.plan.task;
  for (const GroundAction& a : task.actions) {
    if (task.lifted->actions[a.schema].name != "carry") continue;
    request.observed = repair::initial_world(f.problem);
    request.observed.set({"available", task.lifted->objects[a.args[1]]}, false);
    if (strategy->repair(request).repaired) break;
  }
  for (auto _ : state) {
    const repair::RepairResult result = strategy->repair(request);
    if (!result.repaired || !result.reused_grounding) state.SkipWithError("no repair, or grounding not reused");
    benchmark::DoNotOptimize(result);
  }
}

void BM_ReplanReusedGrounding(benchmark::State& state) { replan_reusing_grounding(state, generated_home(), 1.0); }
void BM_ReplanReusedGroundingPaperHome(benchmark::State& state) {
  replan_reusing_grounding(state, paper_home(), 1.0);
}

void BM_ReplanGeneratedHome(benchmark::State& state) { replan(state, generated_home(), 0.0); }
void BM_ReplanGeneratedHomeLater(benchmark::State& state) { replan(state, generated_home(), 1.0); }
void BM_ReplanPaperHome(benchmark::State& state) { replan(state, paper_home(), 0.0); }

// The stages of one replan on the generated home.
void BM_Reformulate(benchmark::State& state) {
  const Fixture& f = generated_home();
  for (auto _ : state) {
    benchmark::DoNotOptimize(repair::reformulate(f.domain, f.problem, f.observed, {}, 0.0));
  }
}

void BM_Ground(benchmark::State& state) {
  const Fixture& f = generated_home();
  const pddl::Problem problem = repair::reformulate(f.domain, f.problem, f.observed, {}, 0.0);
  for (auto _ : state) benchmark::DoNotOptimize(ground(f.domain, problem));
}

void BM_PlanOnGroundTask(benchmark::State& state) {
  const Fixture& f = generated_home();
  const auto task = ground(f.domain, repair::reformulate(f.domain, f.problem, f.observed, {}, 0.0));
  for (auto _ : state) benchmark::DoNotOptimize(Planner(task, PlannerOptions{}).plan_from(initial_start(*task)));
}

}  // namespace

BENCHMARK(BM_ReplanGeneratedHome)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ReplanGeneratedHomeLater)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ReplanPaperHome)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ReplanReusedGrounding)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ReplanReusedGroundingPaperHome)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Reformulate)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Ground)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PlanOnGroundTask)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
