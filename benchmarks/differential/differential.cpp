#include "benchmarks/differential/differential.h"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <ostream>

#include "pddl_parser/checker.h"
#include "pddl_parser/parser.h"
#include "planner/grounder.h"
#include "planner/normalize.h"
#include "planner/planner.h"
#include "planner/validator.h"

namespace alplan::differential {
namespace {

using Clock = std::chrono::steady_clock;

struct ParsedTask {
  std::shared_ptr<const pddl::Domain> domain;
  std::shared_ptr<const pddl::Problem> problem;
  std::string error;
};

ParsedTask parse(const RandomTask& task) {
  ParsedTask parsed;
  const pddl::DomainParseResult d = pddl::parse_domain(task.domain, "domain.pddl");
  const pddl::ProblemParseResult p = pddl::parse_problem(task.problem, "problem.pddl");
  std::vector<pddl::Diagnostic> diagnostics = d.diagnostics;
  diagnostics.insert(diagnostics.end(), p.diagnostics.begin(), p.diagnostics.end());
  if (d.ok() && p.ok()) {
    const std::vector<pddl::Diagnostic> domain_checks = pddl::check_domain(*d.ast, "domain.pddl");
    const std::vector<pddl::Diagnostic> problem_checks = pddl::check_problem(*d.ast, *p.ast, "problem.pddl");
    diagnostics.insert(diagnostics.end(), domain_checks.begin(), domain_checks.end());
    diagnostics.insert(diagnostics.end(), problem_checks.begin(), problem_checks.end());
  }
  // Warnings count too: the generator declares what it uses.
  if (!d.ok() || !p.ok() || !diagnostics.empty()) {
    for (const pddl::Diagnostic& diagnostic : diagnostics) parsed.error += diagnostic.to_string() + "\n";
    return parsed;
  }
  parsed.domain = d.ast;
  parsed.problem = p.ast;
  return parsed;
}

struct PlannerOutcome {
  std::string status;
  std::string message;
  std::string plan;
};

PlannerOutcome run_planner(const ParsedTask& task, const DifferentialOptions& options) {
  PlannerOutcome outcome;
  const std::shared_ptr<const GroundTask> ground_task = ground(*task.domain, *task.problem);
  PlannerOptions planner;
  planner.time_limit = options.planner_time_limit;
  planner.node_limit = options.planner_node_limit;
  planner.epsilon = options.brute_force.epsilon;
  const PlannerResult result = Planner(ground_task, planner).plan();
  outcome.status = status_name(result.status);
  outcome.message = result.message;
  if (const FoundPlan* best = result.best()) outcome.plan = best->text;
  return outcome;
}

void write_task(const Disagreement& d, const std::string& dir) {
  if (dir.empty()) return;
  const std::filesystem::path folder = std::filesystem::path(dir) / ("fuzz-" + std::to_string(d.seed));
  std::filesystem::create_directories(folder);
  std::ofstream(folder / "domain.pddl") << d.domain;
  std::ofstream(folder / "problem.pddl") << d.problem;
  std::ofstream(folder / "plan.txt") << d.plan;
  std::ofstream(folder / "finding.txt") << d.kind << "\nplanner: " << d.planner_status << "\n" << d.message << "\n";
}

std::string plan_text(const Plan& plan) {
  return plan.steps.empty() ? "; the empty plan: the goal holds from the start\n" : write_plan(plan, 3);
}

// One task: the planner, then (where it found nothing) the brute force.
void check_task(std::uint64_t seed, const DifferentialOptions& options, DifferentialReport& report) {
  const RandomTask task = random_task(seed, options.generator);
  Disagreement d;
  d.seed = seed;
  d.domain = task.domain;
  d.problem = task.problem;
  const ParsedTask parsed = parse(task);
  if (!parsed.domain) {
    d.kind = "generator_error";
    d.message = parsed.error;
    report.disagreements.push_back(d);
    return;
  }
  PlannerOutcome planner;
  try {
    planner = run_planner(parsed, options);
  } catch (const std::exception& e) {
    d.kind = "crash";
    d.message = e.what();
    report.disagreements.push_back(d);
    return;
  }
  d.planner_status = planner.status;
  d.message = planner.message;
  if (planner.status == "solved") {
    ++report.planner_solved;
    // The planner validated its plan; a validator of our own reads the text,
    // exactly (the planner promises plans that need no slack).
    PlanValidator validator(std::make_shared<const NormalizedTask>(normalize(*parsed.domain, *parsed.problem)),
                            {options.brute_force.epsilon, false, 0.0});
    const ValidationResult v = validator.validate(read_plan(planner.plan, "planner plan").plan);
    if (!v.valid) {
      d.kind = "invalid_plan";
      d.message = v.violation ? v.violation->message() : "invalid";
      d.plan = planner.plan;
      report.disagreements.push_back(d);
    }
    return;
  }
  if (planner.status == "internal_error" || planner.status == "unsupported") {
    d.kind = planner.status;
    report.disagreements.push_back(d);
    return;
  }
  if (planner.status == "unsolvable") ++report.planner_unsolvable;
  if (planner.status == "exhausted") ++report.planner_exhausted;
  if (planner.status == "limit_reached") ++report.planner_limit;
  ++report.brute_force_runs;
  const BruteForceResult brute = brute_force_plan(*parsed.domain, *parsed.problem, options.brute_force);
  report.validations += brute.validations;
  if (brute.cut_short) ++report.brute_force_cut_short;
  if (!brute.plan) return;
  ++report.brute_force_solved;
  d.kind = planner.status == "unsolvable" ? "false_unsolvable" : "missed_plan";
  d.plan = plan_text(*brute.plan);
  report.disagreements.push_back(d);
}

}  // namespace

DifferentialReport run_differential(const DifferentialOptions& options, std::ostream& progress) {
  DifferentialReport report;
  const Clock::time_point began = Clock::now();
  for (std::uint64_t k = 0; k < options.tasks; ++k) {
    const double elapsed = std::chrono::duration<double>(Clock::now() - began).count();
    if (elapsed > options.seconds) break;
    const std::size_t before = report.disagreements.size();
    check_task(options.seed + k, options, report);
    ++report.tasks;
    for (std::size_t i = before; i < report.disagreements.size(); ++i) {
      const Disagreement& d = report.disagreements[i];
      progress << "task " << d.seed << ": " << d.kind << " (planner: " << d.planner_status << ")\n";
      write_task(d, options.out_dir);
    }
  }
  report.seconds = std::chrono::duration<double>(Clock::now() - began).count();
  return report;
}

void print_report(const DifferentialReport& r, std::ostream& out) {
  out << "tasks: " << r.tasks << " in " << r.seconds << " s\n"
      << "planner: " << r.planner_solved << " solved, " << r.planner_unsolvable << " unsolvable, "
      << r.planner_exhausted << " exhausted, " << r.planner_limit << " at a limit\n"
      << "brute force (where the planner found no plan): " << r.brute_force_runs << " runs, "
      << r.brute_force_solved << " solved, " << r.brute_force_cut_short << " cut short, " << r.validations
      << " plans validated\n"
      << "disagreements: " << r.disagreements.size() << "\n";
  for (const Disagreement& d : r.disagreements) {
    out << "\n== task " << d.seed << ": " << d.kind << " (planner: " << d.planner_status << ")\n";
    if (!d.message.empty()) out << d.message << "\n";
    if (!d.plan.empty()) out << "plan:\n" << d.plan;
  }
}

}  // namespace alplan::differential
