// Grounding time per IPC domain (its first problem), parse excluded.
//   build/benchmarks/grounding_benchmark
#include <benchmark/benchmark.h>

#include <fstream>
#include <sstream>

#include "benchmarks/harness/suite.h"
#include "pddl_parser/parser.h"
#include "planner/grounder.h"

namespace {

std::string read(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void ground_problem(benchmark::State& state, const alplan::bench::SuiteProblem& p) {
  const auto domain = alplan::pddl::parse_domain(read(p.domain_file), p.domain_file);
  const auto problem = alplan::pddl::parse_problem(read(p.problem_file), p.problem_file);
  if (!domain.ok() || !problem.ok()) {
    state.SkipWithError("parse failed");
    return;
  }
  std::size_t actions = 0;
  for (auto _ : state) {
    auto task = alplan::ground(*domain.ast, *problem.ast);
    actions = task->actions.size();
    benchmark::DoNotOptimize(task);
  }
  state.counters["actions"] = static_cast<double>(actions);
}

}  // namespace

int main(int argc, char** argv) {
  const auto suite = alplan::bench::first_problems(
      alplan::bench::load_suite(std::string(ALPLAN_SHARED_DIR) + "/benchmarks/ipc"), 1);
  for (const alplan::bench::SuiteProblem& p : suite) {
    benchmark::RegisterBenchmark(("Ground/" + p.domain).c_str(), ground_problem, p)
        ->Unit(benchmark::kMillisecond);
  }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
