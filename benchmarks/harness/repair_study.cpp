#include "benchmarks/harness/repair_study.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

#include "benchmarks/harness/svg_chart.h"
#include "benchmarks/harness/table.h"
#include "stats/multiple_testing.h"
#include "stats/prioritized_comparison.h"
#include "stats/quantile.h"

namespace alplan::bench {
namespace {

struct Metric {
  const char* name;
  const char* unit;
  bool higher_is_better;
  // Defined only for runs that comforted the senior (delay, makespan, cost,
  // metric): compared with every run counted by a net benefit, success
  // first (intention to treat), and on the runs both comforted only as a
  // labelled secondary comparison.
  bool comforted_only;
  std::function<std::optional<double>(const StudyRun&)> value;
};

double sum(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s += x;
  return s;
}

const std::vector<Metric>& metrics() {
  static const std::vector<Metric> all{
      {"success", "share of runs comforted", true, false, [](const StudyRun& r) { return r.comforted ? 1.0 : 0.0; }},
      {"latency_ms", "ms of repair per run", false, false, [](const StudyRun& r) { return sum(r.latencies_ms); }},
      // A run that comforted no one changed no plan it could finish: its 0
      // is no stability, so the run counts as a failure first.
      {"stability", "actions removed + added", false, true,
       [](const StudyRun& r) -> std::optional<double> {
         if (!r.comforted) return std::nullopt;
         return r.stability;
       }},
      {"delay", "time units after the planned end", false, true, [](const StudyRun& r) { return r.delay; }},
      {"makespan", "time units", false, true, [](const StudyRun& r) { return r.makespan; }},
      {"cost", "total-cost", false, true, [](const StudyRun& r) { return r.cost; }},
      // The generated homes' metric: (+ (total-time) (total-cost)).
      {"metric", "total-time + total-cost", false, true,
       [](const StudyRun& r) -> std::optional<double> {
         if (!r.makespan || !r.cost) return std::nullopt;
         return *r.makespan + *r.cost;
       }},
      {"planner_calls", "per run", false, false,
       [](const StudyRun& r) { return static_cast<double>(r.planner_calls); }},
  };
  return all;
}

double mean_of(const std::vector<double>& v) { return v.empty() ? std::nan("") : sum(v) / static_cast<double>(v.size()); }

nlohmann::json number_or_null(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(); }

// The runs of one kind ("all": every run).
std::vector<const StudyRun*> of_kind(const std::vector<StudyRun>& runs, const std::string& kind) {
  std::vector<const StudyRun*> out;
  for (const StudyRun& r : runs) {
    if (kind == "all" || r.kind == kind) out.push_back(&r);
  }
  return out;
}

struct Cell {  // one strategy within one kind
  std::size_t runs = 0, comforted = 0;
  std::vector<double> latencies, perception, stability, delay, makespan, cost, calls;
};

Cell summarise(const std::vector<const StudyRun*>& runs, const std::string& strategy) {
  Cell c;
  for (const StudyRun* r : runs) {
    if (r->strategy != strategy) continue;
    ++c.runs;
    c.comforted += r->comforted ? 1 : 0;
    c.latencies.insert(c.latencies.end(), r->latencies_ms.begin(), r->latencies_ms.end());
    if (!r->latencies_ms.empty()) c.perception.push_back(r->perception_ms);
    c.stability.push_back(r->stability);
    c.calls.push_back(r->planner_calls);
    if (r->delay) c.delay.push_back(*r->delay);
    if (r->makespan) c.makespan.push_back(*r->makespan);
    if (r->cost) c.cost.push_back(*r->cost);
  }
  return c;
}

// The runs of `strategy` and of the reference, paired by (home, run).
std::vector<std::pair<const StudyRun*, const StudyRun*>> pairs_of(const std::vector<const StudyRun*>& runs,
                                                                  const std::string& reference,
                                                                  const std::string& strategy) {
  std::map<std::pair<std::string, int>, const StudyRun*> base;
  for (const StudyRun* r : runs) {
    if (r->strategy == reference) base[{r->home, r->run}] = r;
  }
  std::vector<std::pair<const StudyRun*, const StudyRun*>> out;
  for (const StudyRun* r : runs) {
    if (r->strategy != strategy) continue;
    const auto it = base.find({r->home, r->run});
    if (it != base.end()) out.push_back({it->second, r});
  }
  return out;
}

// The metric's values of `strategy` and of the reference, paired by run;
// a run's home is its cluster, since runs of one home are not independent.
// A run without a value (not comforted) drops its pair: for the
// comforted-only metrics this is the common set, the secondary comparison.
stats::PairedComparison compare(const std::vector<const StudyRun*>& runs, const std::string& reference,
                         const std::string& strategy, const Metric& metric, const stats::BootstrapOptions& bootstrap) {
  std::vector<double> a, b;
  std::vector<std::string> homes;
  for (const auto& [ref, other] : pairs_of(runs, reference, strategy)) {
    a.push_back(metric.value(*ref).value_or(std::nan("")));
    b.push_back(metric.value(*other).value_or(std::nan("")));
    homes.push_back(other->home);
  }
  return stats::compare_paired(a, b, homes, bootstrap);
}

// Every pair counted (intention to treat): comforting beats not comforting,
// and where both comforted the lower value wins (stats/prioritized_comparison.h).
stats::NetBenefit net_benefit(const std::vector<const StudyRun*>& runs, const std::string& reference,
                              const std::string& strategy, const Metric& metric,
                              const stats::BootstrapOptions& bootstrap) {
  std::vector<stats::PrioritizedOutcome> a, b;
  std::vector<std::string> homes;
  auto outcome = [&](const StudyRun& r) {
    const std::optional<double> v = metric.value(r);
    return stats::PrioritizedOutcome{r.comforted && v.has_value(), v.value_or(0.0)};
  };
  for (const auto& [ref, other] : pairs_of(runs, reference, strategy)) {
    a.push_back(outcome(*ref));
    b.push_back(outcome(*other));
    homes.push_back(other->home);
  }
  return stats::net_benefit(a, b, homes, bootstrap);
}

// A net benefit is positive where the strategy does better; a difference
// is better in the metric's own direction.
std::string verdict(const stats::PairedComparison& c, bool higher_is_better) {
  if (c.pairs == 0) return "no pairs";
  if (!c.significant()) return "tie";
  return (c.mean_difference > 0) == higher_is_better ? "better" : "worse";
}

std::string verdict(const stats::PairedComparison& c, const Metric& m) { return verdict(c, m.higher_is_better); }

// The primary comparison's verdict: by net benefit for comforted-only metrics.
std::string primary_verdict(const stats::PairedComparison& c, const Metric& m) {
  return verdict(c, m.comforted_only ? true : m.higher_is_better);
}

std::string interval(const stats::PairedComparison& c, int decimals) {
  return "[" + fixed(c.ci_low, decimals) + ", " + fixed(c.ci_high, decimals) + "]";
}

std::string p_text(double p) {
  if (p < 0.001) return "<0.001";
  return fixed(p, 3);
}

int decimals_for(const Metric& m) { return std::string(m.name) == "success" || m.comforted_only ? 3 : 2; }

int secondary_decimals(const Metric& m) { return std::string(m.name) == "success" ? 3 : 2; }

}  // namespace


namespace {

template <class T>
using ByKindStrategyMetric = std::map<std::string, std::map<std::string, std::map<std::string, T>>>;

struct Study {
  const std::vector<StudyRun>& runs;
  const std::vector<std::string>& strategies;
  const std::string& reference;
  const stats::BootstrapOptions& bootstrap;
  std::vector<std::string> kinds;  // as drawn, then "all"
  // The primary comparisons, one Holm family per kind: a paired difference
  // for the metrics every run has, a net benefit (its scores; the mean is
  // the net benefit) for the comforted-only ones, whose wins, ties and
  // losses are in net_benefits.
  ByKindStrategyMetric<stats::PairedComparison> comparisons;
  ByKindStrategyMetric<stats::NetBenefit> net_benefits;
  // Secondary: comforted-only metrics on the runs both comforted, their own
  // Holm family per kind.
  ByKindStrategyMetric<stats::PairedComparison> common_set;
};

void summary_tables(const Study& s, StudyAnalysis& out, std::ostringstream& md) {
  Table table({"failure kind", "strategy", "runs", "comforted", "latency median ms", "latency p95 ms",
               "perception median ms", "stability", "delay", "makespan", "cost", "planner calls"});
  for (const std::string& kind : s.kinds) {
    const std::vector<const StudyRun*> runs = of_kind(s.runs, kind);
    for (const std::string& strategy : s.strategies) {
      const Cell c = summarise(runs, strategy);
      if (c.runs == 0) continue;
      const double median = stats::nearest_rank(c.latencies, 0.5), p95 = stats::nearest_rank(c.latencies, 0.95);
      table.add({kind, strategy, std::to_string(c.runs),
                 std::to_string(c.comforted) + " (" + fixed(100.0 * static_cast<double>(c.comforted) / static_cast<double>(c.runs), 0) + "%)",
                 fixed(median, 3), fixed(p95, 3), fixed(stats::nearest_rank(c.perception, 0.5), 3), fixed(mean_of(c.stability), 2),
                 fixed(mean_of(c.delay), 1), fixed(mean_of(c.makespan), 1), fixed(mean_of(c.cost), 1), fixed(mean_of(c.calls), 2)});
      out.json["kinds"][kind]["strategies"][strategy] = {
          {"runs", c.runs}, {"comforted", c.comforted},
          {"success_rate", static_cast<double>(c.comforted) / static_cast<double>(c.runs)},
          {"latency_median_ms", number_or_null(median)}, {"latency_p95_ms", number_or_null(p95)},
          {"perception_median_ms", number_or_null(stats::nearest_rank(c.perception, 0.5))},
          {"stability_mean", number_or_null(mean_of(c.stability))}, {"delay_mean", number_or_null(mean_of(c.delay))},
          {"makespan_mean", number_or_null(mean_of(c.makespan))}, {"cost_mean", number_or_null(mean_of(c.cost))},
          {"planner_calls_mean", number_or_null(mean_of(c.calls))}};
    }
  }
  md << "## Per failure kind and strategy\n\nMeans over the runs; delay, makespan and cost over the runs that comforted "
        "the senior; latency over every repair attempt (substitute's includes its perception call).\n\n";
  table.print_markdown(md);
}

void holm_adjust_family(const std::vector<stats::PairedComparison*>& family) {
  std::vector<double> p;
  for (const stats::PairedComparison* c : family) p.push_back(c->wilcoxon_p);
  const std::vector<double> adjusted = stats::holm_adjust(p);
  for (std::size_t i = 0; i < family.size(); ++i) family[i]->wilcoxon_p_adjusted = adjusted[i];
}

// Every strategy against the reference on every metric of one failure
// kind: the primary comparisons are one family of tests, their signed-rank
// p-values Holm-adjusted together, so that a kind's table as a whole keeps
// the 5% error rate; the secondary (common-set) ones are another.
void compare_kind(Study& s, const std::string& kind) {
  const std::vector<const StudyRun*> runs = of_kind(s.runs, kind);
  std::vector<stats::PairedComparison*> primary, secondary;
  for (const std::string& strategy : s.strategies) {
    if (strategy == s.reference) continue;
    for (const Metric& m : metrics()) {
      if (m.comforted_only) {
        const stats::NetBenefit n = net_benefit(runs, s.reference, strategy, m, s.bootstrap);
        if (n.scores.pairs == 0) continue;
        s.net_benefits[kind][strategy][m.name] = n;
        primary.push_back(&(s.comparisons[kind][strategy][m.name] = n.scores));
        const stats::PairedComparison c = compare(runs, s.reference, strategy, m, s.bootstrap);
        if (c.pairs > 0) secondary.push_back(&(s.common_set[kind][strategy][m.name] = c));
        continue;
      }
      const stats::PairedComparison c = compare(runs, s.reference, strategy, m, s.bootstrap);
      if (c.pairs == 0) continue;
      primary.push_back(&(s.comparisons[kind][strategy][m.name] = c));
    }
  }
  holm_adjust_family(primary);
  holm_adjust_family(secondary);
}

std::string effect_text(double x) { return std::isfinite(x) ? fixed(x, 2) : "n/a"; }

nlohmann::json comparison_json(const stats::PairedComparison& c, const std::string& verdict_text) {
  return {{"pairs", c.pairs}, {"differing", c.nonzero}, {"homes", c.clusters},
          {"differing_homes", c.nonzero_clusters}, {"positive_homes", c.positive_clusters},
          {"mean_difference", c.mean_difference}, {"ci_low", c.ci_low}, {"ci_high", c.ci_high},
          {"wilcoxon_p", c.wilcoxon_p}, {"wilcoxon_p_holm", c.wilcoxon_p_adjusted}, {"sign_p", c.sign_p},
          {"rank_biserial", number_or_null(c.rank_biserial)}, {"d_z", number_or_null(c.d_z)},
          {"verdict", verdict_text}};
}

std::vector<std::string> comparison_cells(const stats::PairedComparison& c, int decimals) {
  return {std::to_string(c.pairs), std::to_string(c.clusters), fixed(c.mean_difference, decimals),
          interval(c, decimals), p_text(c.wilcoxon_p), p_text(c.wilcoxon_p_adjusted), p_text(c.sign_p),
          effect_text(c.rank_biserial), effect_text(c.d_z)};
}

void primary_table(Study& s, StudyAnalysis& out, std::ostringstream& md) {
  Table table({"failure kind", "strategy", "metric", "compared by", "runs", "homes", "differing runs: wins / ties / losses",
               "difference or net benefit", "95% CI", "Wilcoxon p", "Holm p", "sign p", "r_rb", "d_z", "verdict"});
  for (const std::string& kind : s.kinds) {
    for (const std::string& strategy : s.strategies) {
      for (const Metric& m : metrics()) {
        const auto k = s.comparisons[kind].find(strategy);
        if (k == s.comparisons[kind].end() || !k->second.count(m.name)) continue;
        const stats::PairedComparison& c = k->second.at(m.name);
        const std::string v = primary_verdict(c, m);
        std::vector<std::string> cells = comparison_cells(c, decimals_for(m));
        std::string differing = std::to_string(c.nonzero);
        nlohmann::json json = comparison_json(c, v);
        if (m.comforted_only) {
          const stats::NetBenefit& n = s.net_benefits[kind][strategy].at(m.name);
          differing = std::to_string(n.wins) + " / " + std::to_string(n.ties) + " / " + std::to_string(n.losses);
          json["compared_by"] = "net benefit, every run (intention to treat)";
          json["wins"] = n.wins;
          json["ties"] = n.ties;
          json["losses"] = n.losses;
        } else {
          json["compared_by"] = "difference, every run";
        }
        std::vector<std::string> row{kind, strategy, m.name, m.comforted_only ? "net benefit" : "difference",
                                     cells[0], cells[1], differing};
        row.insert(row.end(), cells.begin() + 2, cells.end());
        row.push_back(v);
        table.add(row);
        out.json["kinds"][kind]["against_" + s.reference][strategy][m.name] = json;
      }
    }
  }
  md << "\n## Against " << s.reference << ", every run (the primary comparison)\n\nEvery run of every strategy "
        "counts. Success, latency and planner calls: strategy minus "
     << s.reference
     << " on the same run, the mean over runs. Stability, delay, makespan, cost and metric mean something only "
        "where the senior was comforted, so they are compared by a net benefit (intention to treat; Buyse 2010, "
        "stats/prioritized_comparison.h): each pair is won by the strategy that comforted where the other did not, "
        "else, both comforted, by the lower value; the net benefit is P(the strategy wins) - P(" << s.reference
     << " wins), in [-1, 1], positive where the strategy does better. Runs of one home are not independent, so the "
        "home is the unit of inference: a 95% percentile cluster bootstrap interval (homes resampled with all their "
        "runs, "
     << s.bootstrap.resamples
     << " resamples); the Wilcoxon signed-rank and sign tests, two-sided, on the per-home means; Holm p: the "
        "Wilcoxon p adjusted (Holm 1979) over every row of the failure kind in this table; effect sizes on the "
        "per-home means: r_rb, the matched-pairs rank-biserial correlation (Kerby 2014), and d_z, their mean over "
        "their standard deviation (n/a: one home, or every home differs by the same non-zero amount). A verdict "
        "other than tie needs the interval to exclude zero and Holm p < 0.05.\n\n";
  table.print_markdown(md);
}

void common_set_table(Study& s, StudyAnalysis& out, std::ostringstream& md) {
  Table table({"failure kind", "strategy", "metric", "runs both comforted", "homes", "differing runs", "mean difference",
               "95% CI", "Wilcoxon p", "Holm p", "sign p", "r_rb", "d_z", "verdict"});
  for (const std::string& kind : s.kinds) {
    for (const std::string& strategy : s.strategies) {
      for (const Metric& m : metrics()) {
        const auto k = s.common_set[kind].find(strategy);
        if (k == s.common_set[kind].end() || !k->second.count(m.name)) continue;
        const stats::PairedComparison& c = k->second.at(m.name);
        const std::vector<std::string> cells = comparison_cells(c, secondary_decimals(m));
        std::vector<std::string> row{kind, strategy, m.name, cells[0], cells[1], std::to_string(c.nonzero)};
        row.insert(row.end(), cells.begin() + 2, cells.end());
        row.push_back(verdict(c, m));
        table.add(row);
        out.json["kinds"][kind]["against_" + s.reference + "_common_set"][strategy][m.name] =
            comparison_json(c, verdict(c, m));
      }
    }
  }
  md << "\n## Secondary: stability, delay, makespan, cost and metric on the runs both comforted\n\nStrategy minus "
     << s.reference
     << " on the runs where both comforted the senior: a strategy that fails on the hard runs is compared only on "
        "the easy ones here, so this table is secondary to the one above and its verdicts are not the study's. "
        "Statistics as above; Holm over this table's rows of one failure kind.\n\n";
  table.print_markdown(md);
}

void comparison_tables(Study& s, StudyAnalysis& out, std::ostringstream& md) {
  for (const std::string& kind : s.kinds) compare_kind(s, kind);
  primary_table(s, out, md);
  common_set_table(s, out, md);
}

void wins_table(const Study& s, StudyAnalysis& out, std::ostringstream& md) {
  const std::vector<std::string> shown{"success", "metric", "cost", "delay", "stability", "latency_ms"};
  std::vector<std::string> header{"failure kind"};
  header.insert(header.end(), shown.begin(), shown.end());
  Table table(header);
  for (const std::string& kind : s.kinds) {
    std::vector<std::string> row{kind};
    for (const std::string& name : shown) {
      const Metric& m = *std::find_if(metrics().begin(), metrics().end(), [&](const Metric& x) { return name == x.name; });
      std::string better, worse;
      const auto k = s.comparisons.find(kind);
      for (const std::string& strategy : s.strategies) {
        if (k == s.comparisons.end() || !k->second.count(strategy) || !k->second.at(strategy).count(name)) continue;
        const stats::PairedComparison& c = k->second.at(strategy).at(name);
        const std::string v = primary_verdict(c, m);
        const std::string entry = strategy + " (" + fixed(c.mean_difference, decimals_for(m)) + ")";
        if (v == "better") better += (better.empty() ? "" : ", ") + entry;
        if (v == "worse") worse += (worse.empty() ? "" : ", ") + entry;
        out.json["wins"][kind][name][strategy] = v;
      }
      std::string cell = better.empty() ? "tie with " + s.reference : "**" + better + "**";
      if (!worse.empty()) cell += "; worse: " + worse;
      row.push_back(cell);
    }
    table.add(row);
  }
  md << "\n## Where each strategy wins\n\nAgainst " << s.reference
     << ", per failure kind, from the primary comparison: the strategies significantly better (in brackets the "
        "mean difference, or for stability, delay, cost and metric the net benefit, every run counted), and those "
        "significantly worse; everything else ties.\n\n";
  table.print_markdown(md);
}

// Fox et al. 2006: repair keeps plans more stable than replanning. In
// actions on the runs both comforted (the common set), and, every run
// counted, the net benefit with success first: the finding needs both.
void stability_finding(const Study& s, StudyAnalysis& out, std::ostringstream& md) {
  md << "\n## Plan stability (Fox et al. 2006)\n\n";
  const auto all = s.comparisons.find("all");
  const auto common = s.common_set.find("all");
  for (const std::string& strategy : {std::string("adapt"), std::string("patch")}) {
    if (all == s.comparisons.end() || !all->second.count(strategy) || common == s.common_set.end() ||
        !common->second.count(strategy)) {
      continue;
    }
    const stats::PairedComparison& c = common->second.at(strategy).at("stability");
    const stats::PairedComparison& n = all->second.at(strategy).at("stability");
    const bool holds = c.significant() && c.mean_difference < 0 && n.significant() && n.mean_difference > 0;
    md << "- " << strategy << " against " << s.reference << ": " << fixed(c.mean_difference, 2)
       << " actions removed + added per run where both comforted, 95% CI " << interval(c, 2) << ", Wilcoxon p "
       << p_text(c.wilcoxon_p) << " (Holm " << p_text(c.wilcoxon_p_adjusted) << ") over " << c.clusters
       << " homes' means, " << c.pairs << " runs (" << c.nonzero << " differ: " << strategy << " changes fewer actions in "
       << c.nonzero - c.positive << ", more in " << c.positive << "); every run counted, net benefit "
       << fixed(n.mean_difference, 3) << " " << interval(n, 3) << " (Holm " << p_text(n.wilcoxon_p_adjusted)
       << "): " << (holds ? "more stable, as Fox et al. found" : "not more stable here") << ".\n";
    out.json["fox2006"][strategy] = {{"mean_difference", c.mean_difference}, {"ci_low", c.ci_low},
                                     {"ci_high", c.ci_high}, {"wilcoxon_p", c.wilcoxon_p},
                                     {"wilcoxon_p_holm", c.wilcoxon_p_adjusted}, {"net_benefit", n.mean_difference},
                                     {"net_benefit_ci_low", n.ci_low}, {"net_benefit_ci_high", n.ci_high},
                                     {"net_benefit_holm", n.wilcoxon_p_adjusted}, {"holds", holds}};
  }
}

void forest_plots(const Study& s, StudyAnalysis& out) {
  for (const Metric& m : metrics()) {
    std::vector<IntervalRow> rows;
    for (const std::string& kind : s.kinds) {
      const auto k = s.comparisons.find(kind);
      if (k == s.comparisons.end()) continue;
      for (const std::string& strategy : s.strategies) {
        if (!k->second.count(strategy) || !k->second.at(strategy).count(m.name)) continue;
        const stats::PairedComparison& c = k->second.at(strategy).at(m.name);
        rows.push_back({kind + " / " + strategy, c.mean_difference, c.ci_low, c.ci_high, c.significant()});
      }
    }
    const std::string title = m.comforted_only ? std::string(m.name) + ": net benefit against " + s.reference +
                                                     ", every run, 95% CI"
                                               : std::string(m.name) + ": strategy minus " + s.reference + ", 95% CI";
    out.plots[std::string(m.name) + "-vs-" + s.reference + ".svg"] =
        forest_plot_svg(title, m.comforted_only ? "P(win) - P(loss)" : m.unit, rows);
  }
  std::vector<Bar> success;
  const std::vector<const StudyRun*> every = of_kind(s.runs, "all");
  for (const std::string& strategy : s.strategies) {
    const Cell c = summarise(every, strategy);
    if (c.runs) success.push_back({strategy, static_cast<double>(c.comforted) / static_cast<double>(c.runs)});
  }
  out.plots["success-rate.svg"] = bar_chart_svg("success rate, all failure kinds", "share of runs comforted", success);
}

}  // namespace

StudyAnalysis analyse_repair_study(const std::vector<StudyRun>& runs, const std::vector<std::string>& strategies,
                                   const std::string& reference, const stats::BootstrapOptions& bootstrap) {
  Study s{runs, strategies, reference, bootstrap, {}, {}, {}, {}};
  for (const StudyRun& r : runs) {
    if (std::find(s.kinds.begin(), s.kinds.end(), r.kind) == s.kinds.end()) s.kinds.push_back(r.kind);
  }
  s.kinds.push_back("all");
  StudyAnalysis out;
  out.json = nlohmann::json::object();
  std::ostringstream md;
  summary_tables(s, out, md);
  comparison_tables(s, out, md);
  wins_table(s, out, md);
  stability_finding(s, out, md);
  forest_plots(s, out);
  out.markdown = md.str();
  return out;
}

}  // namespace alplan::bench
