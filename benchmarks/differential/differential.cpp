#include "benchmarks/differential/differential.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <ostream>
#include <set>
#include <sstream>
#include <mutex>
#include <thread>

#include <nlohmann/json.hpp>

#include "oracle/judge.h"
#include "oracle/load.h"
#include "planner/grounder.h"
#include "planner/planner.h"

namespace alplan::differential {
namespace {

using Clock = std::chrono::steady_clock;

struct PlannerOutcome {
  std::string status;
  std::string message;
  std::string plan;
};

PlannerOutcome run_planner(const oracle::LoadedTask& task, const DifferentialOptions& options) {
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

std::string plan_text(const oracle::TimedPlan& plan) {
  return plan.steps.empty() ? "; the empty plan: the goal holds from the start\n" : oracle::write_timed_plan(plan, 4);
}

// Whether a plan of one step or none solves the task (then it is trivial).
bool solved_in_one_step(const oracle::LoadedTask& task, const DifferentialOptions& options, std::uint64_t& judgements) {
  BruteForceOptions one = options.brute_force;
  one.max_steps = 1;
  const BruteForceResult r = brute_force_plan(task.domain, task.problem, one);
  judgements += r.judgements;
  return r.plan.has_value();
}

// The planner's plan as it printed it, judged exactly (the planner
// promises plans that need no slack): nothing when valid, else the kind of
// disagreement, with the plan and the reason in `d`.
std::optional<std::string> judge_plan(const oracle::LoadedTask& task, const std::string& plan,
                                      const DifferentialOptions& options, Disagreement& d) {
  oracle::JudgeOptions exact;
  exact.exact = true;
  exact.tolerance = options.brute_force.epsilon;
  const oracle::TimedPlanRead read = oracle::read_timed_plan(plan);
  oracle::Verdict v;
  if (read.ok()) {
    v = oracle::Judge(task.domain, task.problem, exact).judge(read.plan);
  } else {
    v.failure = oracle::Failure::BadPlan;
    v.reason = read.error;
  }
  d.plan = plan;
  if (!v.judged()) {
    d.message = v.reason;
    return "unjudged_plan";
  }
  if (!v.valid()) {
    d.message = std::string(oracle::to_string(v.failure)) + ": " + v.reason;
    return "invalid_plan";
  }
  return std::nullopt;
}

// Runs the planner with `options`, records its answer in `d` and
// `outcome`, and judges its plan: nothing when the answer stands, else the
// kind of disagreement (a crash, an internal error, a refusal, a plan the
// reference semantics rejects or cannot judge).
std::optional<std::string> plan_and_judge(const oracle::LoadedTask& task, const DifferentialOptions& options,
                                          PlannerOutcome& planner, Disagreement& d, TaskOutcome& outcome) {
  try {
    planner = run_planner(task, options);
  } catch (const std::exception& e) {
    d.message = e.what();
    return "crash";
  }
  d.planner_status = planner.status;
  d.message = planner.message;
  outcome.planner_plan = planner.plan;
  if (planner.status == "internal_error" || planner.status == "unsupported") return planner.status;
  if (planner.status == "solved") return judge_plan(task, planner.plan, options, d);
  return std::nullopt;
}

// The options of the planner's second run: the generous time, and nodes
// in the same proportion.
DifferentialOptions generous(const DifferentialOptions& options) {
  DifferentialOptions g = options;
  g.planner_time_limit = options.retry_time_limit;
  const double factor = options.retry_time_limit / options.planner_time_limit;
  g.planner_node_limit = static_cast<std::size_t>(static_cast<double>(options.planner_node_limit) * factor);
  return g;
}

// Whether every plan the brute force finds in its bound passes VAL only by
// the order in which it claims a happening's facts (oracle/ownership.h):
// the symmetric rule, which the planner's footprints follow, refuses them
// all and its search was not cut short.
bool only_val_order_gives_a_plan(const oracle::LoadedTask& task, const DifferentialOptions& options,
                                 std::uint64_t& judgements) {
  BruteForceOptions symmetric = options.brute_force;
  symmetric.symmetric_mutex = true;
  const BruteForceResult strict = brute_force_plan(task.domain, task.problem, symmetric);
  judgements += strict.judgements;
  return !strict.plan && !strict.cut_short;
}

// Every plan in the bound needs two interfering happenings closer than
// epsilon (under the symmetric rule too, so that this class and the one
// above do not overlap): a planner separating them by epsilon cannot
// produce one (oracle/judge.h, epsilon_separation).
bool only_sub_epsilon_gives_a_plan(const oracle::LoadedTask& task, const DifferentialOptions& options,
                                   std::uint64_t& judgements) {
  BruteForceOptions strict = options.brute_force;
  strict.symmetric_mutex = true;
  strict.epsilon_separated = true;
  const BruteForceResult separated = brute_force_plan(task.domain, task.problem, strict);
  judgements += separated.judgements;
  return !separated.plan && !separated.cut_short;
}

TaskOutcome disagree(TaskOutcome outcome, Disagreement d, const std::string& kind) {
  d.kind = kind;
  outcome.cls = kind;
  outcome.disagreement = std::move(d);
  return outcome;
}

}  // namespace

TaskOutcome check_task(const std::string& domain, const std::string& problem, const DifferentialOptions& options) {
  TaskOutcome outcome;
  Disagreement d;
  d.domain = domain;
  d.problem = problem;
  const oracle::LoadedTask task = oracle::load_task_text(domain, problem);
  if (!task.ok()) {
    d.message = task.error;
    return disagree(outcome, d, "generator_error");
  }
  PlannerOutcome planner;
  if (std::optional<std::string> kind = plan_and_judge(task, options, planner, d, outcome)) {
    return disagree(outcome, d, *kind);
  }
  const BruteForceResult brute = brute_force_plan(task.domain, task.problem, options.brute_force);
  outcome.judgements += brute.judgements;
  if (!brute.error.empty()) {
    d.message = "the reference semantics cannot judge the task: " + brute.error;
    return disagree(outcome, d, "unjudged_task");
  }
  const bool grounded_away = planner.message.find("the goal can never hold") != std::string::npos;
  if (brute.plan) outcome.witness = plan_text(*brute.plan);
  if (brute.plan) {
    outcome.non_trivial = !solved_in_one_step(task, options, outcome.judgements);
    if (planner.status == "solved") {
      outcome.cls = "agree_solved";
      return outcome;
    }
    if (planner.status == "limit_reached" && options.retry_time_limit > options.planner_time_limit) {
      // A plan exists: the planner gets the generous limit before a miss is
      // called (the first limit keeps the tasks without plans cheap).
      if (std::optional<std::string> kind = plan_and_judge(task, generous(options), planner, d, outcome)) {
        return disagree(outcome, d, *kind);
      }
      if (planner.status == "solved") {
        outcome.cls = "agree_solved_late";
        return outcome;
      }
    }
    d.plan = plan_text(*brute.plan);
    // Plans VAL accepts only by its order of claims: counted apart, never
    // as agreement.
    if (planner.status != "unsolvable" && only_val_order_gives_a_plan(task, options, outcome.judgements)) {
      outcome.cls = "missed_val_order_only";
      return outcome;
    }
    if (planner.status != "unsolvable" && only_sub_epsilon_gives_a_plan(task, options, outcome.judgements)) {
      outcome.cls = "missed_sub_epsilon_only";
      return outcome;
    }
    return disagree(outcome, d, planner.status == "unsolvable" ? "false_unsolvable" : "missed_plan");
  }
  if (planner.status == "solved") {
    outcome.non_trivial = !solved_in_one_step(task, options, outcome.judgements);
    outcome.cls = brute.cut_short ? "solved_brute_force_cut_short" : "planner_only_solved";
    return outcome;
  }
  if (brute.cut_short) {
    outcome.cls = "undecided";
    return outcome;
  }
  outcome.non_trivial = !grounded_away;
  outcome.cls = planner.status == "unsolvable" ? "agree_unsolvable" : "agree_unsolved";
  return outcome;
}

namespace {

void write_task(const Disagreement& d, const std::string& dir) {
  if (dir.empty()) return;
  const std::filesystem::path folder = std::filesystem::path(dir) / ("fuzz-" + std::to_string(d.seed));
  std::filesystem::create_directories(folder);
  std::ofstream(folder / "domain.pddl") << d.domain;
  std::ofstream(folder / "problem.pddl") << d.problem;
  std::ofstream(folder / "plan.txt") << d.plan;
  std::ofstream(folder / "finding.txt") << d.kind << "\nplanner: " << d.planner_status << "\n" << d.message << "\n";
}

}  // namespace

namespace {

struct Checked {
  GeneratedTask task;
  TaskOutcome outcome;
};

void record(const DifferentialOptions& options, Checked& c, DifferentialReport& report) {
  const TaskOutcome& outcome = c.outcome;
  ++report.tasks;
  report.judgements += outcome.judgements;
  if (!options.all_dir.empty()) {
    const std::filesystem::path folder = std::filesystem::path(options.all_dir) / c.task.name;
    std::filesystem::create_directories(folder);
    std::ofstream(folder / "domain.pddl") << c.task.domain;
    std::ofstream(folder / "problem.pddl") << c.task.problem;
    std::ofstream(folder / "class.txt") << outcome.cls << (outcome.non_trivial ? " non-trivial" : "") << "\n";
    if (!outcome.planner_plan.empty()) std::ofstream(folder / "planner.plan") << outcome.planner_plan;
    if (!outcome.witness.empty()) std::ofstream(folder / "witness.plan") << outcome.witness;
  }
  ClassCounts& counts = report.by_class[outcome.cls];
  ++counts.tasks;
  counts.non_trivial += outcome.non_trivial ? 1 : 0;
  counts.seconds += outcome.seconds;
  for (const std::string& f : c.task.features) {
    ++report.by_feature[f].tasks;
    report.by_feature[f].non_trivial += outcome.non_trivial ? 1 : 0;
  }
  if (!outcome.disagreement) return;
  const Disagreement& d = *outcome.disagreement;
  write_task(d, options.out_dir);
  report.disagreements.push_back(d);
}

}  // namespace

std::uint64_t task_seed(std::uint64_t run_seed, std::uint64_t k) { return (run_seed << 32) + k; }

DifferentialReport run_differential(const DifferentialOptions& options, std::ostream& progress) {
  DifferentialReport report;
  report.bound = describe_bound(options.brute_force);
  std::ostringstream limits;
  limits << options.planner_time_limit << " s and " << options.planner_node_limit << " nodes per task";
  if (options.retry_time_limit > options.planner_time_limit) {
    limits << "; where the brute force finds a plan and that was not enough, a second run of "
           << options.retry_time_limit << " s before the plan is called missed";
  }
  report.planner_limits = limits.str();
  const Clock::time_point began = Clock::now();
  std::map<std::uint64_t, Checked> checked;  // by task number; a run may name a million tasks and stop at a minute
  std::mutex lock;
  std::atomic<std::uint64_t> next{0};
  // Each worker takes the next task until none is left or time is up; the
  // report reads the tasks in order, so it does not depend on the threads.
  auto work = [&] {
    while (true) {
      const std::uint64_t k = next++;
      if (k >= (options.task_seed ? 1 : options.tasks)) return;
      if (std::chrono::duration<double>(Clock::now() - began).count() > options.seconds) return;
      Checked c;
      const std::uint64_t seed = options.task_seed ? *options.task_seed : task_seed(options.seed, k);
      c.task = generate_task(seed, options.generator);
      const Clock::time_point task_began = Clock::now();
      c.outcome = check_task(c.task.domain, c.task.problem, options);
      if (c.outcome.disagreement) {
        Disagreement& d = *c.outcome.disagreement;
        d.seed = seed;
        d.features = c.task.features;
        {
          const std::lock_guard<std::mutex> guard(lock);
          progress << "task " << d.seed << ": " << d.kind << " (planner: " << d.planner_status << ")" << std::endl;
        }
        if (options.shrink) d = shrink(d, options);
      }
      c.outcome.seconds = std::chrono::duration<double>(Clock::now() - task_began).count();
      const std::lock_guard<std::mutex> guard(lock);
      checked.emplace(k, std::move(c));
    }
  };
  std::vector<std::thread> workers;
  for (int j = 1; j < std::max(1, options.jobs); ++j) workers.emplace_back(work);
  work();
  for (std::thread& w : workers) w.join();
  for (auto& [k, c] : checked) record(options, c, report);
  report.seconds = std::chrono::duration<double>(Clock::now() - began).count();
  return report;
}

namespace {

// How a report's classes add up: agreement, undecided, misses VAL's order
// alone explains, misses only a sub-epsilon gap explains, disagreements.
struct Totals {
  std::uint64_t non_trivial = 0, undecided = 0, disagreements = 0, order_only = 0, sub_epsilon_only = 0;
};

Totals totals_of(const DifferentialReport& r) {
  static const std::set<std::string> agreeing = {"agree_solved", "agree_solved_late", "planner_only_solved",
                                                 "agree_unsolvable", "agree_unsolved", "solved_brute_force_cut_short"};
  Totals t;
  for (const auto& [cls, c] : r.by_class) {
    t.non_trivial += c.non_trivial;
    if (cls == "undecided") t.undecided += c.tasks;
    else if (cls == "missed_val_order_only") t.order_only += c.tasks;
    else if (cls == "missed_sub_epsilon_only") t.sub_epsilon_only += c.tasks;
    else if (!agreeing.count(cls)) t.disagreements += c.tasks;
  }
  return t;
}

}  // namespace

void print_report(const DifferentialReport& r, std::ostream& out) {
  out << "tasks: " << r.tasks << " in " << r.seconds << " s; " << r.judgements
      << " plans judged by the reference semantics\nbrute force bound: " << r.bound << "\n";
  if (!r.planner_limits.empty()) out << "planner limits: " << r.planner_limits << "\n";
  const Totals t = totals_of(r);
  for (const auto& [cls, c] : r.by_class) out << "  " << cls << ": " << c.tasks << " (" << c.non_trivial << " non-trivial)\n";
  auto share = [&](std::uint64_t n) { return r.tasks ? 100.0 * static_cast<double>(n) / static_cast<double>(r.tasks) : 0.0; };
  out << "undecided: " << t.undecided << " (" << share(t.undecided) << " %), never counted as agreement\n";
  if (t.order_only > 0) {
    out << "missed where only VAL's order of claims gives a plan: " << t.order_only
        << ", neither agreement nor disagreement\n";
  }
  if (t.sub_epsilon_only > 0) {
    out << "missed where every plan needs interfering happenings closer than epsilon: " << t.sub_epsilon_only
        << ", neither agreement nor disagreement\n";
  }
  out << "non-trivial: " << t.non_trivial << " (" << share(t.non_trivial) << " %)\n";
  out << "seconds by class (one thread's time):";
  for (const auto& [cls, c] : r.by_class) out << " " << cls << " " << std::llround(c.seconds);
  out << "\nby planted structure (tasks, non-trivial):\n";
  for (const auto& [feature, c] : r.by_feature) out << "  " << feature << ": " << c.tasks << ", " << c.non_trivial << "\n";
  out << "disagreements: " << t.disagreements << "\n";
  for (const Disagreement& d : r.disagreements) {
    out << "\n== task " << d.seed << ": " << d.kind << " (planner: " << d.planner_status << ")\n";
    if (!d.message.empty()) out << d.message << "\n";
    if (!d.plan.empty()) out << "plan:\n" << d.plan;
  }
}

void write_report_json(const DifferentialReport& r, std::ostream& out) {
  const Totals t = totals_of(r);
  nlohmann::json j;
  j["tasks"] = r.tasks;
  j["seconds"] = r.seconds;
  j["judgements"] = r.judgements;
  j["bound"] = r.bound;
  j["planner_limits"] = r.planner_limits;
  j["undecided"] = t.undecided;
  j["non_trivial"] = t.non_trivial;
  j["missed_val_order_only"] = t.order_only;
  j["missed_sub_epsilon_only"] = t.sub_epsilon_only;
  j["disagreements"] = t.disagreements;
  auto counts = [](const std::map<std::string, ClassCounts>& m) {
    nlohmann::json o = nlohmann::json::object();
    for (const auto& [name, c] : m) o[name] = {{"tasks", c.tasks}, {"non_trivial", c.non_trivial}, {"seconds", c.seconds}};
    return o;
  };
  j["classes"] = counts(r.by_class);
  j["features"] = counts(r.by_feature);
  j["findings"] = nlohmann::json::array();
  for (const Disagreement& d : r.disagreements) {
    j["findings"].push_back({{"task_seed", d.seed}, {"kind", d.kind}, {"planner_status", d.planner_status},
                             {"message", d.message}, {"plan", d.plan}, {"features", d.features}});
  }
  out << j.dump(2) << "\n";
}

}  // namespace alplan::differential
