#include "benchmarks/harness/external_replan.h"

#include <chrono>
#include <fstream>
#include <sstream>

#include "benchmarks/harness/process_runner.h"
#include "pddl_parser/writer.h"
#include "planner/grounder.h"
#include "planner/plan.h"
#include "repair/reformulation.h"

namespace alplan::bench {

repair::RepairResult ExternalReplan::repair(const repair::RepairRequest& request) {
  const auto began = std::chrono::steady_clock::now();
  repair::RepairResult result;
  result.planner_calls = 1;
  const std::string stem = options_.work_dir + "/repair-" + std::to_string(++calls_);
  const pddl::Problem shifted =
      repair::reformulate(*request.domain, *request.problem, request.observed, request.in_progress, request.now,
                          request.now);
  {
    std::ofstream domain(stem + "-domain.pddl"), problem(stem + "-problem.pddl");
    domain << pddl::write_domain(*request.domain);
    problem << pddl::write_problem(shifted);
  }
  std::ostringstream epsilon;
  epsilon << options_.epsilon;
  const RunResult run = run_process({options_.alplan, "plan", stem + "-domain.pddl", stem + "-problem.pddl", "--out",
                                     stem + ".plan", "--epsilon", epsilon.str(), "-q", "--time-limit",
                                     std::to_string(options_.time_limit)},
                                    RunLimits{options_.time_limit + 5.0, 4096.0});
  std::ifstream plan_file(stem + ".plan");
  std::ostringstream text;
  text << plan_file.rdbuf();
  PlanReadResult read = read_plan(text.str(), stem + ".plan");
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  if (run.exit_code != 0 || !read.ok()) {
    result.how = "the external planner found no plan (exit " + std::to_string(run.exit_code) + ")";
    return result;
  }
  for (PlanStep& step : read.plan.steps) step.time = step.time.value_or(0.0) + request.now;
  // Bound to a task in this process, for the monitor; not part of the latency.
  const pddl::Problem unshifted =
      repair::reformulate(*request.domain, *request.problem, request.observed, request.in_progress, request.now);
  result.plan = repair::bind_plan(ground(*request.domain, unshifted), read.plan, options_.epsilon);
  result.repaired = true;
  result.problem = *request.problem;
  result.how = "replanned in another process: " + repair::describe_remedy(*result.plan, request.now);
  return result;
}

}  // namespace alplan::bench
