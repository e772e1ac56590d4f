// Validation time per happening: on generated long plans (a robot walking a
// corridor of N rooms, one durative move a step) and on the longest plans of
// the corpus in ../shared/benchmarks/plans.
//   build/benchmarks/validation_benchmark
#include <benchmark/benchmark.h>

#include <fstream>
#include <memory>
#include <sstream>

#include "pddl_parser/parser.h"
#include "planner/normalize.h"
#include "planner/validator.h"

namespace {

std::string read(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

const char* kCorridorDomain = R"(
(define (domain corridor) (:requirements :typing :durative-actions :fluents)
  (:types room robot)
  (:predicates (at ?r - robot ?x - room) (next ?a ?b - room))
  (:functions (length ?a ?b - room) (walked ?r - robot))
  (:durative-action move :parameters (?r - robot ?a ?b - room)
    :duration (= ?duration (length ?a ?b))
    :condition (and (at start (at ?r ?a)) (over all (next ?a ?b)))
    :effect (and (at start (not (at ?r ?a))) (at end (at ?r ?b))
                 (at end (increase (walked ?r) (length ?a ?b))))))
)";

struct Corridor {
  std::string problem;
  std::string plan;
};

Corridor corridor(int rooms) {
  Corridor c;
  c.problem = "(define (problem walk) (:domain corridor) (:objects r - robot";
  for (int i = 0; i < rooms; ++i) c.problem += " x" + std::to_string(i);
  c.problem += " - room) (:init (at r x0) (= (walked r) 0)";
  for (int i = 0; i + 1 < rooms; ++i) {
    const std::string a = "x" + std::to_string(i), b = "x" + std::to_string(i + 1);
    c.problem += " (next " + a + " " + b + ") (= (length " + a + " " + b + ") " + std::to_string(1 + i % 5) + ")";
  }
  c.problem += ") (:goal (at r x" + std::to_string(rooms - 1) + ")) (:metric minimize (walked r)))";
  double t = 0;
  char line[128];
  for (int i = 0; i + 1 < rooms; ++i) {
    const int d = 1 + i % 5;
    std::snprintf(line, sizeof line, "%.3f: (move r x%d x%d) [%d]\n", t, i, i + 1, d);
    c.plan += line;
    t += d + 0.001;
  }
  return c;
}

void validate(benchmark::State& state, const std::string& domain_text, const std::string& problem_text,
              const std::string& plan_text) {
  const auto domain = alplan::pddl::parse_domain(domain_text, "domain");
  const auto problem = alplan::pddl::parse_problem(problem_text, "problem");
  const auto plan = alplan::read_plan(plan_text, "plan");
  if (!domain.ok() || !problem.ok() || !plan.ok()) {
    state.SkipWithError("input does not parse");
    return;
  }
  alplan::PlanValidator validator(
      std::make_shared<const alplan::NormalizedTask>(alplan::normalize(*domain.ast, *problem.ast)));
  std::size_t happenings = 0;
  for (auto _ : state) {
    const alplan::ValidationResult r = validator.validate(plan.plan);
    if (!r.valid) state.SkipWithError("plan is invalid");
    happenings = r.happenings;
  }
  state.counters["happenings"] = static_cast<double>(happenings);
  state.counters["time_per_happening"] =
      benchmark::Counter(static_cast<double>(happenings), benchmark::Counter::kIsIterationInvariantRate |
                                                              benchmark::Counter::kInvert);
}

void BM_ValidateCorridor(benchmark::State& state) {
  const Corridor c = corridor(static_cast<int>(state.range(0)));
  validate(state, kCorridorDomain, c.problem, c.plan);
}
BENCHMARK(BM_ValidateCorridor)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

void BM_ValidateCorpusPlan(benchmark::State& state, const std::string& domain, const std::string& problem,
                           const std::string& plan) {
  const std::string base = std::string(ALPLAN_SHARED_DIR) + "/benchmarks/";
  validate(state, read(base + domain), read(base + problem), read(base + plan));
}
BENCHMARK_CAPTURE(BM_ValidateCorpusPlan, temporal_machine_shop_1,
                  "ipc/ipc-2011/temporal-machine-shop-temporal-satisficing/domain.pddl",
                  "ipc/ipc-2011/temporal-machine-shop-temporal-satisficing/instances/instance-1.pddl",
                  "plans/ipc-2011/temporal-machine-shop-temporal-satisficing/instance-1.popf.plan")
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_ValidateCorpusPlan, satellite_time_windows_3,
                  "ipc/ipc-2004/satellite-time-time-windows-strips/domain.pddl",
                  "ipc/ipc-2004/satellite-time-time-windows-strips/instances/instance-3.pddl",
                  "plans/ipc-2004/satellite-time-time-windows-strips/instance-3.optic.plan")
    ->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
