#include "benchmarks/harness/planner_bench.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <mutex>
#include <ostream>
#include <set>
#include <sstream>
#include <thread>

#include "benchmarks/harness/baseline.h"
#include "benchmarks/harness/planner_comparison.h"
#include "benchmarks/harness/quality_report.h"
#include "benchmarks/harness/run_status.h"
#include "benchmarks/harness/slurm_array.h"
#include "benchmarks/harness/suite.h"
#include "benchmarks/harness/table.h"
#include "planner/progress_meter.h"

namespace alplan::bench {
namespace {

struct Run {
  SuiteProblem problem;
  std::string status;  // solved, unsolvable, exhausted, limit, error, invalid
  double seconds = 0;  // wall time of the process
  double first_plan = 0;
  long max_rss_kib = 0;
  double makespan = 0;
  double value = 0;
  std::string message;
  std::string plan_file;  // where our plan went (relative to the results folder when there is one)
  std::vector<PlanFound> plans;  // every plan the run printed, in order (anytime: each better)
  std::string engine;  // what found the best plan and what shortened it ("..., deordered, actions eliminated")
  std::map<std::string, ExternalRun> external;  // the other planners' runs, by name
};

// plans/N.plan for ours, plans/N.NAME.plan for another planner.
std::string plan_path(const std::string& dir, std::size_t index, const std::string& planner = "") {
  return dir + "/" + std::to_string(index) + (planner.empty() ? "" : "." + planner) + ".plan";
}

Run run_ours(const SuiteProblem& p, const PlannerBenchOptions& options, const std::string& plan_file);

// Ours, then each other planner, on problem `index` of the suite.
Run run_one(const SuiteProblem& p, const PlannerBenchOptions& options, const std::string& dir, std::size_t index) {
  Run run = run_ours(p, options, plan_path(dir, index));
  run.plan_file = plan_path(options.out_dir.empty() ? dir : "plans", index);
  for (const ExternalPlanner& planner : options.external) {
    run.external[planner.name] =
        run_external_planner(planner, p, plan_path(dir, index, planner.name), options.limits, options.alplan);
  }
  return run;
}

Run run_ours(const SuiteProblem& p, const PlannerBenchOptions& options, const std::string& plan_file) {
  Run run;
  run.problem = p;
  std::vector<std::string> argv{options.alplan, "plan", "--json", "-q", "--search", options.search,
                                "--time-limit", std::to_string(options.limits.seconds),
                                "--out", plan_file, p.domain_file, p.problem_file};
  if (options.anytime) argv.push_back("--anytime");
  if (!options.order.empty()) argv.insert(argv.end(), {"--order", options.order});
  argv.insert(argv.begin() + 2, options.plan_args.begin(), options.plan_args.end());
  // The child enforces the time limit itself and the runner kills it a
  // little later; memory is limited by the runner.
  RunLimits limits = options.limits;
  limits.seconds += 5;
  std::filesystem::remove(plan_file);
  const RunResult r = run_process(argv, limits);
  const nlohmann::json j = nlohmann::json::parse(r.out, nullptr, false);
  run.status = planner_run_status(r, j);
  run.seconds = r.wall_seconds;
  run.max_rss_kib = r.max_rss_kib;
  if (run.status == "error") run.message = r.err.substr(0, 300);
  if (run.status != "solved") return run;
  const nlohmann::json& best = j["best"];
  run.makespan = best["makespan"];
  run.value = best["value"];  // VAL's value: the metric, as the baseline reports it
  run.engine = best["search"].get<std::string>();
  const nlohmann::json& plans = j["plans"];
  const double grounding = j["seconds"]["grounding"].get<double>();
  run.first_plan = plans.front()["found_after_seconds"].get<double>() + grounding;
  for (const nlohmann::json& found : plans) {
    run.plans.push_back({found["found_after_seconds"].get<double>() + grounding, found["value"].get<double>()});
  }
  // Our validator, again, as a separate process on the written file.
  const RunResult v = run_process({options.alplan, "validate", p.domain_file, p.problem_file, plan_file}, {60, 4096});
  if (v.exit_code != 0) {
    run.status = "invalid";
    run.message = v.out.substr(0, 300);
  }
  return run;
}

nlohmann::json to_json(const ExternalRun& r) {
  return {{"status", r.status}, {"seconds", r.seconds}, {"max_rss_kib", r.max_rss_kib}, {"value", r.value},
          {"message", r.message}};
}

nlohmann::json plans_json(const std::vector<PlanFound>& plans) {
  nlohmann::json list = nlohmann::json::array();
  for (const PlanFound& p : plans) list.push_back({{"seconds", p.seconds}, {"value", p.value}});
  return list;
}

nlohmann::json to_json(const Run& run) {
  nlohmann::json external = nlohmann::json::object();
  for (const auto& [name, r] : run.external) external[name] = to_json(r);
  return {{"domain_file", run.problem.domain_file}, {"problem_file", run.problem.problem_file},
          {"domain", run.problem.domain}, {"number", run.problem.number}, {"status", run.status},
          {"seconds", run.seconds}, {"first_plan", run.first_plan}, {"max_rss_kib", run.max_rss_kib},
          {"makespan", run.makespan}, {"value", run.value}, {"message", run.message},
          {"plan_file", run.plan_file}, {"plans", plans_json(run.plans)}, {"engine", run.engine},
          {"external", external}};
}

Run run_from_json(const nlohmann::json& j) {
  Run run;
  run.problem.domain_file = j.at("domain_file");
  run.problem.problem_file = j.at("problem_file");
  run.problem.domain = j.at("domain");
  run.problem.number = j.at("number");
  run.status = j.at("status");
  run.seconds = j.at("seconds");
  run.first_plan = j.at("first_plan");
  run.max_rss_kib = j.at("max_rss_kib");
  run.makespan = j.at("makespan");
  run.value = j.at("value");
  run.message = j.at("message");
  run.plan_file = j.value("plan_file", "");
  run.engine = j.value("engine", "");
  for (const nlohmann::json& p : j.value("plans", nlohmann::json::array())) {
    run.plans.push_back({p.at("seconds").get<double>(), p.at("value").get<double>()});
  }
  for (const auto& [name, e] : j.value("external", nlohmann::json::object()).items()) {
    ExternalRun r;
    r.status = e.at("status");
    r.seconds = e.at("seconds");
    r.max_rss_kib = e.at("max_rss_kib");
    r.value = e.at("value");
    r.message = e.at("message");
    run.external[name] = r;
  }
  return run;
}

std::string plans_dir(const PlannerBenchOptions& options) {
  return options.out_dir.empty() ? std::filesystem::temp_directory_path().string() + "/alplan-plans"
                                 : options.out_dir + "/plans";
}

std::string progress_line(const Run& run, std::size_t done, std::size_t total) {
  std::ostringstream line;
  line << "[" << done << "/" << total << "] " << run.problem.domain << " "
       << std::filesystem::path(run.problem.problem_file).filename().string() << ": " << run.status;
  if (run.status == "solved") line << " value " << run.value << " in " << fixed(run.first_plan, 2) << " s";
  for (const auto& [name, r] : run.external) {
    line << "; " << name << ": " << r.status;
    if (r.status == "solved") line << " value " << r.value;
  }
  return line.str();
}

// Every run here, `jobs` at a time.
std::vector<Run> run_locally(const std::vector<SuiteProblem>& suite, const PlannerBenchOptions& options,
                             std::ostream& progress) {
  std::vector<Run> runs(suite.size());
  std::atomic<std::size_t> next{0};
  std::atomic<std::size_t> done{0};
  std::mutex print;
  ProgressMeter meter(progress, static_cast<double>(suite.size()), "problems", options.progress_bar);
  auto worker = [&] {
    for (std::size_t i = next++; i < suite.size(); i = next++) {
      runs[i] = run_one(suite[i], options, plans_dir(options), i);
      const std::lock_guard<std::mutex> lock(print);
      ++done;
      meter.update(static_cast<double>(done), progress_line(runs[i], done, suite.size()));
    }
  };
  std::vector<std::thread> threads;
  for (int j = 0; j < std::max(1, options.jobs); ++j) threads.emplace_back(worker);
  for (std::thread& t : threads) t.join();
  return runs;
}

std::string problem_name(const SuiteProblem& p) {
  return p.domain + "/" + std::filesystem::path(p.problem_file).filename().string();
}

void submit(const std::vector<SuiteProblem>& suite, const PlannerBenchOptions& options, std::ostream& out) {
  ArrayManifest m;
  m.kind = "planners";
  m.working_dir = std::filesystem::current_path().string();
  m.command = options.array.command;
  m.slurm = options.array.slurm;
  const int n = static_cast<int>(suite.size());
  for (int t = 0; t < array_tasks(n, m.slurm.batch); ++t) {
    const auto [first, last] = task_items(t, n, m.slurm.batch);
    std::string name = problem_name(suite[static_cast<std::size_t>(first)]);
    if (last - first > 1) name += " .. " + problem_name(suite[static_cast<std::size_t>(last - 1)]);
    m.tasks.push_back(name);
  }
  submit_array(options.array.dir, m, out);
}

// One array task: its share of the suite, one run at a time.
void run_task(const std::vector<SuiteProblem>& suite, const PlannerBenchOptions& options, std::ostream& progress) {
  const ArrayManifest m = read_manifest(options.array.dir);
  const int n = static_cast<int>(suite.size());
  if (options.array.task < 0 || options.array.task >= array_tasks(n, m.slurm.batch)) {
    throw std::runtime_error("no array task " + std::to_string(options.array.task) + " in " + options.array.dir);
  }
  const auto [first, last] = task_items(options.array.task, n, m.slurm.batch);
  nlohmann::json runs = nlohmann::json::array();
  for (int i = first; i < last; ++i) {
    const Run run = run_one(suite[static_cast<std::size_t>(i)], options, plans_dir(options), static_cast<std::size_t>(i));
    progress << progress_line(run, static_cast<std::size_t>(i - first + 1), static_cast<std::size_t>(last - first))
             << "\n" << std::flush;
    runs.push_back(to_json(run));
  }
  write_task_result(options.array.dir, options.array.task, runs);
}

// The finished tasks' runs, in the suite's order.
std::vector<Run> merged_runs(const std::vector<SuiteProblem>& suite, const PlannerBenchOptions& options) {
  const ArrayManifest m = read_manifest(options.array.dir);
  const CollectedTasks tasks = collect_tasks(options.array.dir, m);
  if (!tasks.complete()) throw std::runtime_error("not every task has finished: run `alplan bench merge`");
  std::vector<Run> runs;
  for (const auto& [t, result] : tasks.results) {
    for (const nlohmann::json& j : result) runs.push_back(run_from_json(j));
  }
  if (runs.size() != suite.size()) {
    throw std::runtime_error(std::to_string(runs.size()) + " runs in " + options.array.dir + " for a suite of " +
                             std::to_string(suite.size()) + " problems: the suite changed since it was submitted");
  }
  return runs;
}

double time_score(double seconds, double limit) {
  if (seconds <= 1.0) return 1.0;
  return std::max(0.0, 1.0 - std::log(seconds) / std::log(limit));
}

struct Scores {
  int solved = 0, attempted = 0;
  double quality = 0, time = 0;
};

struct MetricSums {
  int both = 0;
  double ours = 0, reference = 0;
  bool maximize = false;
};

int report_planner_bench(const std::vector<Run>& runs, const PlannerBenchOptions& options,
                         const ReferenceValues& references, std::ostream& out);

}  // namespace

namespace {

// What the ledger keeps of a run on a test set: how many problems ended how.
nlohmann::json status_counts(const std::vector<Run>& runs) {
  std::map<std::string, int> counts;
  for (const Run& run : runs) ++counts[run.status];
  return {{"problems", runs.size()}, {"statuses", counts}};
}

// Each chosen problem's instance number: the N of instance-N, else (a list
// file's problems) its position among its domain's problems in the suite.
std::vector<int> instance_numbers(const std::vector<SuiteProblem>& all, const std::vector<SuiteProblem>& chosen) {
  std::vector<int> numbers;
  for (const SuiteProblem& p : chosen) {
    if (p.number > 0) {
      numbers.push_back(p.number);
      continue;
    }
    int position = 0;
    for (const SuiteProblem& q : all) {
      if (q.domain != p.domain) continue;
      ++position;
      if (q.problem_file == p.problem_file) break;
    }
    numbers.push_back(position);
  }
  return numbers;
}

// The ledger's entry for a run over these problems, where they hold a test
// set (test_set_ledger.h); none otherwise. Throws TestSetRefused.
std::optional<TestSetRun> open_test_set_run(const std::vector<SuiteProblem>& all, const std::vector<SuiteProblem>& suite,
                                            const PlannerBenchOptions& options) {
  const std::optional<std::string> test_set = instance_test_set(instance_numbers(all, suite));
  if (!test_set) return std::nullopt;
  return TestSetRun({*test_set, "bench planners", command_line(), options.out_dir}, options.test_set);
}

// The baseline's quality_ref.csv and the --reference files (quality_report.h).
ReferenceValues reference_values(const PlannerBenchOptions& options);

}  // namespace

int run_planner_bench(const PlannerBenchOptions& options, std::ostream& out, std::ostream& progress) {
  const std::vector<SuiteProblem> all = load_suite(options.suite);
  std::vector<SuiteProblem> suite = problems_in_range(first_problems(all, options.first), options.from, options.to);
  if (!options.domains.empty()) {
    std::erase_if(suite, [&](const SuiteProblem& p) {
      return std::none_of(options.domains.begin(), options.domains.end(),
                          [&](const std::string& prefix) { return p.domain.rfind(prefix, 0) == 0; });
    });
    if (suite.empty()) throw std::runtime_error("--domains: no domain of the suite begins with any of them");
  }
  // A reference file that cannot be read fails here, not after the runs
  // (a test-set run would be spent with nothing recorded).
  const ReferenceValues references = reference_values(options);
  switch (options.array.role) {
    case ArrayRole::submit: {
      // The array's tasks and merge are one run: recorded when submitted,
      // and its tasks and merge must run the submitted binary.
      std::optional<TestSetRun> ledger = open_test_set_run(all, suite, options);
      std::filesystem::create_directories(plans_dir(options));
      submit(suite, options, out);
      if (ledger) ledger->finish({{"submitted", "a Slurm array: its result is what bench merge prints"}});
      return 0;
    }
    case ArrayRole::task:
      check_array_build(options.out_dir, options.test_set);
      std::filesystem::create_directories(plans_dir(options));
      run_array_task(options.array.dir, options.array.task, [&] { run_task(suite, options, progress); });
      return 0;
    case ArrayRole::merge:
      check_array_build(options.out_dir, options.test_set);
      return report_planner_bench(merged_runs(suite, options), options, references, out);
    case ArrayRole::local:
      break;
  }
  std::optional<TestSetRun> ledger = open_test_set_run(all, suite, options);
  std::filesystem::create_directories(plans_dir(options));
  const std::vector<Run> runs = run_locally(suite, options, progress);
  const int invalid = report_planner_bench(runs, options, references, out);
  if (ledger) {
    nlohmann::json result = status_counts(runs);
    result["invalid"] = invalid;
    ledger->finish(result);
    progress << "recorded in the test-set ledger: " << ledger->ledger() << " (" << ledger->id() << ")\n";
  }
  return invalid;
}

namespace {

// Coverage, quality and time per domain and in total, ours beside the references'.
Table summary_table(const std::map<std::string, std::map<std::string, Scores>>& scores, const Baseline& baseline) {
  std::vector<std::string> planners{"ours"};
  planners.insert(planners.end(), baseline.planners.begin(), baseline.planners.end());
  std::vector<std::string> columns{"domain"};
  for (const char* measure : {"coverage", "quality", "time"}) {
    columns.push_back(std::string(measure) + " ours");
    columns.insert(columns.end(), baseline.titles.begin(), baseline.titles.end());
  }
  Table summary(columns);
  std::map<std::string, Scores> total;
  for (const auto& [domain, by_planner] : scores) {
    std::vector<std::string> row{domain};
    auto cell = [&](const std::string& planner, auto field) {
      auto it = by_planner.find(planner);
      if (it == by_planner.end()) return std::string("-");
      return field(it->second);
    };
    for (const std::string& p : planners) {
      row.push_back(cell(p, [](const Scores& s) { return std::to_string(s.solved) + "/" + std::to_string(s.attempted); }));
    }
    for (const std::string& p : planners) row.push_back(cell(p, [](const Scores& s) { return fixed(s.quality, 2); }));
    for (const std::string& p : planners) row.push_back(cell(p, [](const Scores& s) { return fixed(s.time, 2); }));
    summary.add(row);
    for (const auto& [planner, s] : by_planner) {
      total[planner].solved += s.solved;
      total[planner].attempted += s.attempted;
      total[planner].quality += s.quality;
      total[planner].time += s.time;
    }
  }
  std::vector<std::string> row{"total"};
  for (const std::string& p : planners) row.push_back(std::to_string(total[p].solved) + "/" + std::to_string(total[p].attempted));
  for (const std::string& p : planners) row.push_back(fixed(total[p].quality, 2));
  for (const std::string& p : planners) row.push_back(fixed(total[p].time, 2));
  summary.add(row);
  return summary;
}

// Per domain, the summed metric of ours and of the reference's best on the
// problems both solved: a direct comparison where quality scores hide how far
// apart two values are.
Table metric_table(const std::map<std::string, MetricSums>& sums) {
  Table table({"domain", "both solved", "metric", "ours", "best reference"});
  for (const auto& [domain, m] : sums) {
    table.add({domain, std::to_string(m.both), m.maximize ? "maximised" : "minimised", fixed(m.ours, 3),
               fixed(m.reference, 3)});
  }
  return table;
}

// A run's line of runs.csv (ours, then each other planner's status, time,
// value and plan file) and the other planners' part of runs.json.
struct RunRow {
  std::vector<std::string> cells;
  nlohmann::json external = nlohmann::json::object();
};

RunRow run_row(const Run& run, std::size_t index, const std::vector<ExternalPlanner>& others,
               const std::string& plans_folder) {
  const bool solved = run.status == "solved";
  RunRow row{{run.problem.domain, std::filesystem::path(run.problem.problem_file).filename().string(), run.status,
              solved ? fixed(run.first_plan, 2) : "", fixed(run.seconds, 2),
              fixed(static_cast<double>(run.max_rss_kib) / 1024.0, 0), solved ? fixed(run.makespan, 3) : "",
              solved ? fixed(run.value, 3) : "", run.plan_file}};
  for (const ExternalPlanner& p : others) {
    const auto r = run.external.find(p.name);
    if (r == run.external.end()) {
      row.cells.insert(row.cells.end(), {"", "", "", ""});
      continue;
    }
    const std::string file = plan_path(plans_folder, index, p.name);
    row.cells.insert(row.cells.end(), {r->second.status, fixed(r->second.seconds, 2),
                                       r->second.status == "solved" ? fixed(r->second.value, 3) : "", file});
    row.external[p.name] = to_json(r->second);
    row.external[p.name]["plan_file"] = file;
  }
  return row;
}

// The quality of first and best plans against the baseline's quality_ref.csv
// and the reference files given (quality_report.h).
ReferenceValues reference_values(const PlannerBenchOptions& options) {
  ReferenceValues references;
  const std::string quality_ref = options.baseline + "/quality_ref.csv";
  if (!options.baseline.empty() && std::filesystem::exists(quality_ref)) add_reference_file(references, quality_ref);
  for (const std::string& file : options.references) add_reference_file(references, file);
  return references;
}

void report_quality(const std::vector<Run>& runs, const Baseline& baseline, const PlannerBenchOptions& options,
                    const ReferenceValues& references, std::ostream& out) {
  std::vector<QualityRun> quality;
  for (const Run& run : runs) {
    quality.push_back({run.problem.domain, problem_key(run.problem.problem_file),
                       run.status == "solved" ? run.plans : std::vector<PlanFound>{}});
  }
  QualityReportOptions report;
  report.time_limit = options.limits.seconds;
  report.out_dir = options.out_dir;
  report.maximized = [&](const std::string& problem) { return baseline.maximized(problem); };
  write_quality_report(quality, references, report, out);
}

int report_planner_bench(const std::vector<Run>& runs, const PlannerBenchOptions& options,
                         const ReferenceValues& references, std::ostream& out) {
  std::vector<ProblemRuns> others;
  for (const Run& run : runs) others.push_back({run.problem.problem_file, run.external});
  const Baseline baseline = compared_planners(options.baseline, options.external, others);
  const std::set<std::string> externals = [&] {
    std::set<std::string> names;
    for (const ExternalPlanner& p : options.external) names.insert(p.name);
    return names;
  }();
  const std::vector<std::string> warnings = comparison_warnings(baseline, options.limits.seconds, options.jobs);
  for (const std::string& w : warnings) out << "warning: " << w << "\n";
  // Scores per domain, ours and the references' on the same problems.
  std::map<std::string, std::map<std::string, Scores>> scores;
  std::map<std::string, MetricSums> sums;
  int invalid = 0;
  nlohmann::json rows = nlohmann::json::array();
  std::vector<std::string> run_columns{"domain", "problem", "status", "first plan s", "wall s", "peak MiB", "makespan",
                                      "value", "plan"};
  for (const ExternalPlanner& p : options.external) {
    run_columns.insert(run_columns.end(), {p.name + " status", p.name + " wall s", p.name + " value", p.name + " plan"});
  }
  Table runs_table(run_columns);
  // Plan files as runs.csv names them: relative to the results folder.
  const std::string plans_folder = options.out_dir.empty() ? plans_dir(options) : "plans";
  for (std::size_t run_index = 0; run_index < runs.size(); ++run_index) {
    const Run& run = runs[run_index];
    const std::string key = problem_key(run.problem.problem_file);
    const auto refs = baseline.runs.find(key);
    const bool in_baseline = refs != baseline.runs.end();
    invalid += run.status == "invalid";
    // The reference value: the best any compared planner reached.
    const bool maximize = baseline.maximized(key);
    std::optional<double> reference;
    auto consider = [&](double value) {
      if (!reference || baseline.better(key, value, *reference)) reference = value;
    };
    if (auto b = baseline.best.find(key); b != baseline.best.end()) consider(b->second);
    if (run.status == "solved") consider(run.value);
    if (in_baseline) {
      for (const auto& [planner, r] : refs->second) {
        if (r.valid) consider(r.value);
      }
    }
    Scores& ours = scores[run.problem.domain]["ours"];
    ++ours.attempted;
    if (run.status == "solved") {
      ++ours.solved;
      ours.quality += quality_score(run.value, *reference, maximize);
      ours.time += time_score(run.first_plan, options.limits.seconds);
    }
    if (in_baseline) {
      // A baseline's planner counts where the baseline has the problem;
      // another planner run here ran on every problem.
      const bool in_reference = std::any_of(refs->second.begin(), refs->second.end(),
                                             [&](const auto& entry) { return !externals.count(entry.first); });
      for (const std::string& planner : baseline.planners) {
        if (!externals.count(planner) && !in_reference) continue;
        Scores& s = scores[run.problem.domain][planner];
        ++s.attempted;
        auto r = refs->second.find(planner);
        if (r == refs->second.end() || !r->second.valid) continue;
        ++s.solved;
        s.quality += quality_score(r->second.value, *reference, maximize);
        s.time += time_score(r->second.seconds, options.limits.seconds);
      }
      // The metric where we and the best reference both have a valid plan.
      const auto best_reference = baseline.best.find(key);
      if (run.status == "solved" && best_reference != baseline.best.end()) {
        MetricSums& m = sums[run.problem.domain];
        ++m.both;
        m.ours += run.value;
        m.reference += best_reference->second;
        m.maximize = maximize;
      }
    }
    const RunRow row = run_row(run, run_index, options.external, plans_folder);
    const nlohmann::json& external = row.external;
    runs_table.add(row.cells);
    rows.push_back({{"domain", run.problem.domain}, {"problem", key}, {"status", run.status},
                    {"first_plan_seconds", run.first_plan}, {"wall_seconds", run.seconds},
                    {"max_rss_kib", run.max_rss_kib}, {"makespan", run.makespan}, {"value", run.value},
                    {"reference", reference ? nlohmann::json(*reference) : nlohmann::json()},
                    {"message", run.message}, {"plan_file", run.plan_file}, {"plans", plans_json(run.plans)},
                    {"engine", run.engine}, {"external", external}});
  }
  const Table summary = summary_table(scores, baseline);
  summary.print(out);
  const Table metric = metric_table(sums);
  if (!sums.empty()) {
    out << "\n";
    metric.print(out);
  }
  report_quality(runs, baseline, options, references, out);
  out << "\ninvalid plans: " << invalid << "\n";
  // How well the planner keeps its limit: the process's wall time beyond it
  // (the runner kills at the limit + 5 s, so no overrun shows more).
  const Run* worst = nullptr;
  for (const Run& run : runs) {
    if (!worst || run.seconds > worst->seconds) worst = &run;
  }
  const double overrun = worst ? std::max(0.0, worst->seconds - options.limits.seconds) : 0.0;
  if (worst) out << "worst overrun of the time limit: " << fixed(overrun, 2) << " s (" << problem_name(worst->problem) << ")\n";
  out << "scores (IPC 2008-2014): quality = the best value any planner here reached / ours (ours / best where the "
         "metric is maximised), time = 1 for a first plan within 1 s, else 1 - log(t) / log("
      << fixed(options.limits.seconds, 0) << "), 0 unsolved; each summed over a domain's problems\n";
  if (!options.out_dir.empty()) {
    std::ofstream csv(options.out_dir + "/runs.csv");
    runs_table.write_csv(csv);
    std::ofstream md(options.out_dir + "/summary.md");
    summary.print_markdown(md);
    std::ofstream scsv(options.out_dir + "/summary.csv");
    summary.write_csv(scsv);
    if (!sums.empty()) {
      std::ofstream mmd(options.out_dir + "/metric.md");
      metric.print_markdown(mmd);
    }
    std::ofstream json(options.out_dir + "/runs.json");
    json << nlohmann::json{{"time_limit", options.limits.seconds}, {"memory_mib", options.limits.memory_mib},
                           {"anytime", options.anytime}, {"search", options.search},
                           {"order", options.order}, {"plan_args", options.plan_args},
                           {"worst_overrun_seconds", overrun}, {"warnings", warnings}, {"runs", rows}}
                .dump(2)
         << "\n";
    out << "results: " << options.out_dir << "/ (summary.md, summary.csv, runs.csv, runs.json"
        << (sums.empty() ? "" : ", metric.md") << ", plans/: runs.csv's plan columns name each problem's plan)\n";
  }
  return invalid;
}

}  // namespace
}  // namespace alplan::bench
