// The tables and files of `alplan bench stability` (stability_bench.h).
// The primary comparison counts every perturbation (intention to treat: a
// failed repair loses to a valid one, then the measure decides); the means
// over the perturbations every strategy repaired validly (the paired set)
// are a labelled secondary table, since they leave out each strategy's
// failures, which favours the strategies that fail on the hard cases.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "benchmarks/harness/stability_bench.h"
#include "benchmarks/harness/table.h"
#include "stats/multiple_testing.h"
#include "stats/paired_comparison.h"
#include "stats/prioritized_comparison.h"
#include "stats/quantile.h"

namespace alplan::bench {
namespace {

// One perturbation: its domain, problem, kind and number.
std::string run_key(const StabilityRun& r) {
  return r.domain + "/" + std::to_string(r.problem) + "/" + r.kind + "/" + std::to_string(r.perturbation);
}

// The perturbations every strategy repaired with a valid plan.
std::set<std::string> paired_set(const std::vector<StabilityRun>& runs, std::size_t strategies) {
  std::map<std::string, std::size_t> valid;
  for (const StabilityRun& r : runs) valid[run_key(r)] += r.valid ? 1 : 0;
  std::set<std::string> paired;
  for (const auto& [key, count] : valid) {
    if (count == strategies) paired.insert(key);
  }
  return paired;
}

double mean(const std::vector<double>& values) {
  if (values.empty()) return 0.0;
  double sum = 0.0;
  for (double v : values) sum += v;
  return sum / static_cast<double>(values.size());
}

struct Aggregate {
  std::size_t runs = 0, valid = 0, same_first = 0, fallbacks = 0;
  std::vector<double> distance, added, removed, makespan, seconds;  // paired set
};

std::map<std::string, Aggregate> aggregate(const std::vector<StabilityRun>& runs, const std::set<std::string>& paired,
                                           const std::string& domain) {
  std::map<std::string, Aggregate> by_strategy;
  for (const StabilityRun& r : runs) {
    if (!domain.empty() && r.domain != domain) continue;
    Aggregate& a = by_strategy[r.strategy];
    ++a.runs;
    a.valid += r.valid ? 1 : 0;
    a.fallbacks += r.fallback.empty() ? 0 : 1;
    if (!paired.count(run_key(r))) continue;
    a.same_first += r.same_first ? 1 : 0;
    a.distance.push_back(static_cast<double>(r.distance));
    a.added.push_back(static_cast<double>(r.added));
    a.removed.push_back(static_cast<double>(r.removed));
    a.makespan.push_back(r.makespan);
    a.seconds.push_back(r.seconds);
  }
  return by_strategy;
}

void strategy_table(std::ostream& out, const std::map<std::string, Aggregate>& by_strategy,
                    const std::vector<std::string>& strategies) {
  Table table({"strategy", "valid / runs", "fallbacks", "paired", "distance mean", "added", "removed",
               "same first step", "makespan mean", "seconds median", "seconds p95"});
  for (const std::string& s : strategies) {
    const auto it = by_strategy.find(s);
    if (it == by_strategy.end()) continue;
    const Aggregate& a = it->second;
    const double paired = static_cast<double>(a.distance.size());
    table.add({s, std::to_string(a.valid) + " / " + std::to_string(a.runs), std::to_string(a.fallbacks),
               std::to_string(a.distance.size()), paired > 0 ? fixed(mean(a.distance), 2) : "-",
               paired > 0 ? fixed(mean(a.added), 2) : "-", paired > 0 ? fixed(mean(a.removed), 2) : "-",
               paired > 0 ? fixed(100.0 * static_cast<double>(a.same_first) / paired, 1) + "%" : "-",
               paired > 0 ? fixed(mean(a.makespan), 1) : "-",
               paired > 0 ? fixed(stats::nearest_rank(a.seconds, 0.5), 3) : "-",
               paired > 0 ? fixed(stats::nearest_rank(a.seconds, 0.95), 3) : "-"});
  }
  table.print_markdown(out);
}

// Paired differences against the reference on the paired set, one row per
// strategy and measure.
void comparison_table(std::ostream& out, const std::vector<StabilityRun>& runs, const std::set<std::string>& paired,
                      const std::vector<std::string>& strategies, const std::string& reference) {
  std::map<std::string, std::map<std::string, const StabilityRun*>> by_key;  // key -> strategy -> run
  for (const StabilityRun& r : runs) {
    if (paired.count(run_key(r))) by_key[run_key(r)][r.strategy] = &r;
  }
  struct Row {
    std::string strategy, measure;
    stats::PairedComparison c;
  };
  std::vector<Row> rows;
  const std::vector<std::pair<std::string, double (*)(const StabilityRun&)>> measures{
      {"distance", [](const StabilityRun& r) { return static_cast<double>(r.distance); }},
      {"makespan", [](const StabilityRun& r) { return r.makespan; }},
      {"seconds", [](const StabilityRun& r) { return r.seconds; }}};
  for (const std::string& s : strategies) {
    if (s == reference) continue;
    for (const auto& [name, value] : measures) {
      std::vector<double> ref, other;
      std::vector<std::string> problems;  // a problem's perturbations share its plan: one cluster
      for (const auto& [key, runs_of] : by_key) {
        if (!runs_of.count(reference) || !runs_of.count(s)) continue;
        ref.push_back(value(*runs_of.at(reference)));
        other.push_back(value(*runs_of.at(s)));
        problems.push_back(runs_of.at(reference)->domain + "/" + std::to_string(runs_of.at(reference)->problem));
      }
      if (!ref.empty()) rows.push_back({s, name, stats::compare_paired(ref, other, problems)});
    }
  }
  // One family: every strategy on every measure (Holm 1979).
  std::vector<double> p;
  for (const Row& r : rows) p.push_back(r.c.wilcoxon_p);
  const std::vector<double> adjusted = stats::holm_adjust(p);
  Table table({"strategy", "measure", "pairs in problems", "mean difference", "95% CI (problems resampled)",
               "Wilcoxon p (problem means)", "Holm p", "r_rb", "runs lower / higher"});
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const stats::PairedComparison& c = rows[i].c;
    table.add({rows[i].strategy, rows[i].measure, std::to_string(c.pairs) + " in " + std::to_string(c.clusters),
               fixed(c.mean_difference, 3), "[" + fixed(c.ci_low, 3) + ", " + fixed(c.ci_high, 3) + "]",
               fixed(c.wilcoxon_p, 4), fixed(adjusted[i], 4), fixed(c.rank_biserial, 2),
               std::to_string(c.nonzero - c.positive) + " / " + std::to_string(c.positive)});
  }
  table.print_markdown(out);
}

// Intention to treat (stats/prioritized_comparison.h): every perturbation,
// each strategy against the reference on success first (a valid repair
// beats none), then on the measure; Holm over the table.
void intention_to_treat_table(std::ostream& out, const std::vector<StabilityRun>& runs,
                              const std::vector<std::string>& strategies, const std::string& reference) {
  std::map<std::string, std::map<std::string, const StabilityRun*>> by_key;  // key -> strategy -> run
  for (const StabilityRun& r : runs) by_key[run_key(r)][r.strategy] = &r;
  struct Row {
    std::string strategy, measure;
    stats::NetBenefit n;
  };
  std::vector<Row> rows;
  const std::vector<std::pair<std::string, double (*)(const StabilityRun&)>> measures{
      {"repaired", [](const StabilityRun&) { return 0.0; }},  // success alone: every success ties
      {"distance", [](const StabilityRun& r) { return static_cast<double>(r.distance); }},
      {"makespan", [](const StabilityRun& r) { return r.makespan; }}};
  for (const std::string& s : strategies) {
    if (s == reference) continue;
    for (const auto& [name, value] : measures) {
      std::vector<stats::PrioritizedOutcome> ref, other;
      std::vector<std::string> problems;
      for (const auto& [key, runs_of] : by_key) {
        if (!runs_of.count(reference) || !runs_of.count(s)) continue;
        const StabilityRun& a = *runs_of.at(reference);
        const StabilityRun& b = *runs_of.at(s);
        ref.push_back({a.valid, a.valid ? value(a) : 0.0});
        other.push_back({b.valid, b.valid ? value(b) : 0.0});
        problems.push_back(a.domain + "/" + std::to_string(a.problem));
      }
      if (!ref.empty()) rows.push_back({s, name, stats::net_benefit(ref, other, problems)});
    }
  }
  std::vector<double> p;
  for (const Row& r : rows) p.push_back(r.n.scores.wilcoxon_p);
  const std::vector<double> adjusted = stats::holm_adjust(p);
  Table table({"strategy", "measure", "perturbations in problems", "wins / ties / losses", "net benefit",
               "95% CI (problems resampled)", "Wilcoxon p (problem means)", "Holm p"});
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const stats::NetBenefit& n = rows[i].n;
    table.add({rows[i].strategy, rows[i].measure,
               std::to_string(n.scores.pairs) + " in " + std::to_string(n.scores.clusters),
               std::to_string(n.wins) + " / " + std::to_string(n.ties) + " / " + std::to_string(n.losses),
               fixed(n.scores.mean_difference, 3),
               "[" + fixed(n.scores.ci_low, 3) + ", " + fixed(n.scores.ci_high, 3) + "]",
               fixed(n.scores.wilcoxon_p, 4), fixed(adjusted[i], 4)});
  }
  table.print_markdown(out);
}

std::vector<std::string> domains_of(const std::vector<StabilityRun>& runs) {
  std::vector<std::string> domains;
  for (const StabilityRun& r : runs) {
    if (std::find(domains.begin(), domains.end(), r.domain) == domains.end()) domains.push_back(r.domain);
  }
  return domains;
}

nlohmann::json run_json(const StabilityRun& r) {
  return {{"domain", r.domain},       {"problem", r.problem},     {"perturbation", r.perturbation},
          {"kind", r.kind},           {"description", r.description}, {"cut", r.cut},
          {"old_remaining", r.old_remaining}, {"old_makespan", r.old_makespan}, {"strategy", r.strategy},
          {"repaired", r.repaired},   {"valid", r.valid},         {"distance", r.distance},
          {"added", r.added},         {"removed", r.removed},     {"same_first", r.same_first},
          {"new_steps", r.new_steps}, {"makespan", r.makespan},   {"seconds", r.seconds},
          {"planner_calls", r.planner_calls}, {"fallback", r.fallback}, {"how", r.how},
          {"proven", r.proven},       {"cross_check_status", r.cross_check_status},
          {"cross_check_distance", r.cross_check_distance ? nlohmann::json(*r.cross_check_distance) : nlohmann::json()},
          {"cross_check_note", r.cross_check_note}, {"cross_check_seconds", r.cross_check_seconds}};
}

StabilityRun run_from_json(const nlohmann::json& j) {
  StabilityRun r;
  r.domain = j.at("domain");
  r.problem = j.at("problem");
  r.perturbation = j.at("perturbation");
  r.kind = j.at("kind");
  r.description = j.at("description");
  r.cut = j.at("cut");
  r.old_remaining = j.at("old_remaining");
  r.old_makespan = j.at("old_makespan");
  r.strategy = j.at("strategy");
  r.repaired = j.at("repaired");
  r.valid = j.at("valid");
  r.distance = j.at("distance");
  r.added = j.at("added");
  r.removed = j.at("removed");
  r.same_first = j.at("same_first");
  r.new_steps = j.at("new_steps");
  r.makespan = j.at("makespan");
  r.seconds = j.at("seconds");
  r.planner_calls = j.at("planner_calls");
  r.fallback = j.at("fallback");
  r.how = j.at("how");
  // Runs written before the cross-check existed have none of its fields.
  r.proven = j.value("proven", false);
  r.cross_check_status = j.value("cross_check_status", std::string());
  if (j.contains("cross_check_distance") && !j.at("cross_check_distance").is_null()) {
    r.cross_check_distance = j.at("cross_check_distance").get<std::size_t>();
  }
  r.cross_check_note = j.value("cross_check_note", std::string());
  r.cross_check_seconds = j.value("cross_check_seconds", 0.0);
  return r;
}

}  // namespace

StabilityBenchResult read_stability_runs(const std::string& runs_json, std::vector<std::string>& strategies) {
  std::ifstream in(runs_json);
  if (!in) throw std::runtime_error(runs_json + ": cannot be read");
  const nlohmann::json j = nlohmann::json::parse(in);
  StabilityBenchResult result;
  for (const nlohmann::json& r : j.at("runs")) {
    result.runs.push_back(run_from_json(r));
    if (std::find(strategies.begin(), strategies.end(), result.runs.back().strategy) == strategies.end()) {
      strategies.push_back(result.runs.back().strategy);
    }
  }
  result.skipped = j.at("skipped").get<std::vector<std::string>>();
  return result;
}

std::string stability_summary(const StabilityBenchResult& result, const StabilityBenchOptions& options) {
  std::ostringstream out;
  const std::set<std::string> paired = paired_set(result.runs, options.strategies.size());
  const std::string reference = options.strategies.front();
  out << "# Plan stability: " << paired.size() << " perturbations every strategy repaired validly\n\n"
      << "Distance: actions added plus actions removed against the old plan's remaining steps (Fox et al. 2006). "
      << "Means, makespans and times over the paired perturbations; valid over all runs.\n\n## All domains\n\n";
  strategy_table(out, aggregate(result.runs, paired, ""), options.strategies);
  out << "\n### Against " << reference << ", every perturbation (intention to treat; the primary comparison)\n\n"
      << "Each perturbation compared on success first (a valid repair beats none), then on the measure (lower is "
      << "better): a win, a tie or a loss for the strategy; net benefit = P(win) - P(loss) (Buyse 2010).\n\n";
  intention_to_treat_table(out, result.runs, options.strategies, reference);
  out << "\n### Against " << reference << " on the perturbations every strategy repaired (secondary: leaves out "
      << "each strategy's failures; difference = strategy minus " << reference << ")\n\n";
  comparison_table(out, result.runs, paired, options.strategies, reference);
  for (const std::string& domain : domains_of(result.runs)) {
    out << "\n## " << domain << "\n\n";
    strategy_table(out, aggregate(result.runs, paired, domain), options.strategies);
  }
  out << stable_cross_check_section(result);
  if (!result.skipped.empty()) {
    out << "\n## Skipped\n\n";
    for (const std::string& s : result.skipped) out << "- " << s << "\n";
  }
  return out.str();
}

void write_stability_results(const StabilityBenchResult& result, const StabilityBenchOptions& options,
                             const std::string& out_dir) {
  std::filesystem::create_directories(out_dir);
  Table csv({"domain", "problem", "perturbation", "kind", "strategy", "repaired", "valid", "distance", "added",
             "removed", "same_first", "old_remaining", "new_steps", "cut", "old_makespan", "makespan", "seconds",
             "planner_calls", "fallback", "proven", "cross_check_status", "cross_check_distance",
             "cross_check_seconds", "description"});
  nlohmann::json runs = nlohmann::json::array();
  for (const StabilityRun& r : result.runs) {
    csv.add({r.domain, std::to_string(r.problem), std::to_string(r.perturbation), r.kind, r.strategy,
             r.repaired ? "yes" : "no", r.valid ? "yes" : "no", std::to_string(r.distance), std::to_string(r.added),
             std::to_string(r.removed), r.same_first ? "yes" : "no", std::to_string(r.old_remaining),
             std::to_string(r.new_steps), fixed(r.cut, 3), fixed(r.old_makespan, 3), fixed(r.makespan, 3),
             fixed(r.seconds, 4), std::to_string(r.planner_calls), r.fallback, r.proven ? "yes" : "no",
             r.cross_check_status, r.cross_check_distance ? std::to_string(*r.cross_check_distance) : "",
             r.cross_check_status.empty() ? "" : fixed(r.cross_check_seconds, 3), r.description});
    runs.push_back(run_json(r));
  }
  std::ofstream(out_dir + "/runs.csv") << [&] {
    std::ostringstream text;
    csv.write_csv(text);
    return text.str();
  }();
  std::ofstream(out_dir + "/runs.json") << nlohmann::json{{"runs", runs}, {"skipped", result.skipped}}.dump(1)
                                        << "\n";
  std::ofstream(out_dir + "/summary.md") << stability_summary(result, options);
}

}  // namespace alplan::bench
