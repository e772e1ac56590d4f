#include "benchmarks/harness/planner_bench.h"

#include <nlohmann/json.hpp>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <ostream>
#include <thread>

#include "benchmarks/harness/baseline.h"
#include "benchmarks/harness/run_status.h"
#include "benchmarks/harness/suite.h"
#include "benchmarks/harness/table.h"

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
};

Run run_one(const SuiteProblem& p, const PlannerBenchOptions& options, const std::string& plan_file) {
  Run run;
  run.problem = p;
  std::vector<std::string> argv{options.alplan, "plan", "--json", "-q", "--search", options.search,
                                "--time-limit", std::to_string(options.limits.seconds),
                                "--out", plan_file, p.domain_file, p.problem_file};
  if (options.anytime) argv.push_back("--anytime");
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
  const nlohmann::json& plans = j["plans"];
  run.first_plan = plans.front()["found_after_seconds"].get<double>() + j["seconds"]["grounding"].get<double>();
  // Our validator, again, as a separate process on the written file.
  const RunResult v = run_process({options.alplan, "validate", p.domain_file, p.problem_file, plan_file}, {60, 4096});
  if (v.exit_code != 0) {
    run.status = "invalid";
    run.message = v.out.substr(0, 300);
  }
  return run;
}

double time_score(double seconds, double limit) {
  if (seconds <= 1.0) return 1.0;
  return std::max(0.0, 1.0 - std::log(seconds) / std::log(limit));
}

struct Scores {
  int solved = 0, attempted = 0;
  double quality = 0, time = 0;
};

}  // namespace

int run_planner_bench(const PlannerBenchOptions& options, std::ostream& out, std::ostream& progress) {
  const std::vector<SuiteProblem> suite = first_problems(load_suite(options.suite), options.first);
  const Baseline baseline = options.baseline.empty() ? Baseline{} : Baseline::load(options.baseline);
  const std::string plans_dir = options.out_dir.empty() ? std::filesystem::temp_directory_path().string() + "/alplan-plans"
                                                        : options.out_dir + "/plans";
  std::filesystem::create_directories(plans_dir);

  std::vector<Run> runs(suite.size());
  std::atomic<std::size_t> next{0};
  std::atomic<std::size_t> done{0};
  std::mutex print;
  auto worker = [&] {
    for (std::size_t i = next++; i < suite.size(); i = next++) {
      const std::string plan_file = plans_dir + "/" + std::to_string(i) + ".plan";
      runs[i] = run_one(suite[i], options, plan_file);
      const std::lock_guard<std::mutex> lock(print);
      progress << "[" << ++done << "/" << suite.size() << "] " << suite[i].domain << " "
               << std::filesystem::path(suite[i].problem_file).filename().string() << ": " << runs[i].status;
      if (runs[i].status == "solved") progress << " value " << runs[i].value << " in " << fixed(runs[i].first_plan, 2) << " s";
      progress << "\n" << std::flush;
    }
  };
  std::vector<std::thread> threads;
  for (int j = 0; j < std::max(1, options.jobs); ++j) threads.emplace_back(worker);
  for (std::thread& t : threads) t.join();

  // Scores per domain, ours and the references' on the same problems.
  const std::vector<std::string> planners{"ours", "optic", "popf"};
  std::map<std::string, std::map<std::string, Scores>> scores;
  int invalid = 0;
  nlohmann::json rows = nlohmann::json::array();
  Table runs_table({"domain", "problem", "status", "first plan s", "wall s", "peak MiB", "makespan", "value"});
  for (const Run& run : runs) {
    const std::string key = problem_key(run.problem.problem_file);
    const auto refs = baseline.runs.find(key);
    const bool in_baseline = refs != baseline.runs.end();
    invalid += run.status == "invalid";
    // The reference value: the best any compared planner reached.
    double reference = std::numeric_limits<double>::infinity();
    if (auto b = baseline.best.find(key); b != baseline.best.end() && b->second > 0) reference = b->second;
    if (run.status == "solved") reference = std::min(reference, run.value);
    if (in_baseline) {
      for (const auto& [planner, r] : refs->second) {
        if (r.valid) reference = std::min(reference, r.value);
      }
    }
    Scores& ours = scores[run.problem.domain]["ours"];
    ++ours.attempted;
    if (run.status == "solved") {
      ++ours.solved;
      ours.quality += run.value > 0 ? reference / run.value : 1.0;
      ours.time += time_score(run.first_plan, options.limits.seconds);
    }
    if (in_baseline) {
      for (const std::string& planner : {std::string("optic"), std::string("popf")}) {
        Scores& s = scores[run.problem.domain][planner];
        ++s.attempted;
        auto r = refs->second.find(planner);
        if (r == refs->second.end() || !r->second.valid) continue;
        ++s.solved;
        s.quality += r->second.value > 0 ? reference / r->second.value : 1.0;
        s.time += time_score(r->second.seconds, options.limits.seconds);
      }
    }
    runs_table.add({run.problem.domain, std::filesystem::path(run.problem.problem_file).filename().string(),
                    run.status, run.status == "solved" ? fixed(run.first_plan, 2) : "", fixed(run.seconds, 2),
                    fixed(static_cast<double>(run.max_rss_kib) / 1024.0, 0),
                    run.status == "solved" ? fixed(run.makespan, 3) : "", run.status == "solved" ? fixed(run.value, 3) : ""});
    rows.push_back({{"domain", run.problem.domain}, {"problem", key}, {"status", run.status},
                    {"first_plan_seconds", run.first_plan}, {"wall_seconds", run.seconds},
                    {"max_rss_kib", run.max_rss_kib}, {"makespan", run.makespan}, {"value", run.value},
                    {"reference", std::isfinite(reference) ? nlohmann::json(reference) : nlohmann::json()},
                    {"message", run.message}});
  }
  Table summary({"domain", "coverage ours", "OPTIC", "POPF", "quality ours", "OPTIC", "POPF", "time ours", "OPTIC", "POPF"});
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
  summary.print(out);
  out << "\ninvalid plans: " << invalid << "\n";
  if (!options.out_dir.empty()) {
    std::ofstream csv(options.out_dir + "/runs.csv");
    runs_table.write_csv(csv);
    std::ofstream md(options.out_dir + "/summary.md");
    summary.print_markdown(md);
    std::ofstream scsv(options.out_dir + "/summary.csv");
    summary.write_csv(scsv);
    std::ofstream json(options.out_dir + "/runs.json");
    json << nlohmann::json{{"time_limit", options.limits.seconds}, {"memory_mib", options.limits.memory_mib},
                           {"anytime", options.anytime}, {"search", options.search}, {"runs", rows}}
                .dump(2)
         << "\n";
  }
  return invalid;
}

}  // namespace alplan::bench
