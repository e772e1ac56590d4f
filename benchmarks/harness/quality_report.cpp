#include "benchmarks/harness/quality_report.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <ostream>
#include <stdexcept>

#include "benchmarks/harness/baseline.h"
#include "benchmarks/harness/svg_chart.h"
#include "benchmarks/harness/table.h"

namespace alplan::bench {
namespace {

// Everything known of one problem: our plans, the references, the best.
struct ProblemQuality {
  const QualityRun* run = nullptr;
  std::optional<double> best_known;
  bool maximize = false;

  double score(std::optional<double> value) const {
    if (!value || !best_known) return 0.0;
    return quality_score(*value, *best_known, maximize);
  }
  // Our best value found by `t` seconds.
  std::optional<double> ours_at(double t) const {
    std::optional<double> v;
    for (const PlanFound& p : run->plans) {
      if (p.seconds <= t) v = p.value;
    }
    return v;
  }
  std::optional<double> first() const {
    return run->plans.empty() ? std::nullopt : std::optional<double>(run->plans.front().value);
  }
  std::optional<double> last() const {
    return run->plans.empty() ? std::nullopt : std::optional<double>(run->plans.back().value);
  }
};

std::optional<double> reference(const ReferenceValues& refs, const std::string& problem, const std::string& name) {
  const auto p = refs.values.find(problem);
  if (p == refs.values.end()) return std::nullopt;
  const auto v = p->second.find(name);
  return v == p->second.end() ? std::nullopt : std::optional<double>(v->second);
}

std::vector<ProblemQuality> assess(const std::vector<QualityRun>& runs, const ReferenceValues& refs,
                                   const QualityReportOptions& options) {
  std::vector<ProblemQuality> out;
  for (const QualityRun& run : runs) {
    ProblemQuality q;
    q.run = &run;
    q.maximize = options.maximized(run.problem);
    auto consider = [&](double v) {
      if (!q.best_known || (q.maximize ? v > *q.best_known : v < *q.best_known)) q.best_known = v;
    };
    for (const PlanFound& p : run.plans) consider(p.value);
    for (const std::string& name : refs.names) {
      if (const std::optional<double> v = reference(refs, run.problem, name)) consider(*v);
    }
    if (const auto b = refs.best.find(run.problem); b != refs.best.end()) consider(b->second);
    out.push_back(q);
  }
  return out;
}

std::string seconds_text(const QualityRun& run, bool first) {
  if (run.plans.empty()) return "";
  return fixed(first ? run.plans.front().seconds : run.plans.back().seconds, 2);
}

std::string value_text(std::optional<double> v) { return v ? fixed(*v, 3) : ""; }

Table problem_table(const std::vector<ProblemQuality>& problems, const ReferenceValues& refs) {
  std::vector<std::string> header{"domain", "problem", "first value", "first s", "best value", "best s", "plans",
                                  "best known", "score first", "score best"};
  for (const std::string& name : refs.names) header.insert(header.end(), {name, "score " + name});
  Table table(header);
  for (const ProblemQuality& q : problems) {
    const QualityRun& run = *q.run;
    std::vector<std::string> row{run.domain, std::filesystem::path(run.problem).filename().string(),
                                 value_text(q.first()), seconds_text(run, true), value_text(q.last()),
                                 seconds_text(run, false), std::to_string(run.plans.size()),
                                 value_text(q.best_known), fixed(q.score(q.first()), 3), fixed(q.score(q.last()), 3)};
    for (const std::string& name : refs.names) {
      const std::optional<double> v = reference(refs, run.problem, name);
      row.insert(row.end(), {value_text(v), v ? fixed(q.score(v), 3) : ""});
    }
    table.add(row);
  }
  return table;
}

// Score sums per domain and over all: ours first and at the limit, each
// reference; `known` counts the problems with a best known value, the most
// any planner can sum.
Table domain_table(const std::vector<ProblemQuality>& problems, const ReferenceValues& refs) {
  std::vector<std::string> header{"domain", "problems", "best known", "ours first", "ours best"};
  for (const std::string& name : refs.names) header.push_back(name);
  Table table(header);
  struct Sums {
    int problems = 0, known = 0;
    double first = 0, best = 0;
    std::vector<double> refs;
  };
  std::map<std::string, Sums> by_domain;
  Sums total;
  total.refs.assign(refs.names.size(), 0.0);
  for (const ProblemQuality& q : problems) {
    Sums& s = by_domain[q.run->domain];
    s.refs.resize(refs.names.size(), 0.0);
    for (Sums* sums : {&s, &total}) {
      ++sums->problems;
      sums->known += q.best_known.has_value();
      sums->first += q.score(q.first());
      sums->best += q.score(q.last());
      for (std::size_t i = 0; i < refs.names.size(); ++i) {
        sums->refs[i] += q.score(reference(refs, q.run->problem, refs.names[i]));
      }
    }
  }
  auto add = [&](const std::string& name, const Sums& s) {
    std::vector<std::string> row{name, std::to_string(s.problems), std::to_string(s.known), fixed(s.first, 2),
                                 fixed(s.best, 2)};
    for (double r : s.refs) row.push_back(fixed(r, 2));
    table.add(row);
  };
  for (const auto& [domain, s] : by_domain) add(domain, s);
  add("total", total);
  return table;
}

std::vector<Series> over_time(const std::vector<ProblemQuality>& problems, const ReferenceValues& refs,
                              const std::vector<double>& grid) {
  Series ours{"ours (best plan so far)", {}, false};
  for (double t : grid) {
    double sum = 0.0;
    for (const ProblemQuality& q : problems) sum += q.score(q.ours_at(t));
    ours.points.emplace_back(t, sum);
  }
  std::vector<Series> series{ours};
  for (const std::string& name : refs.names) {
    double sum = 0.0;
    for (const ProblemQuality& q : problems) sum += q.score(reference(refs, q.run->problem, name));
    series.push_back({name + " (at its limit)", {{grid.front(), sum}, {grid.back(), sum}}, true});
  }
  return series;
}

}  // namespace

void add_reference_file(ReferenceValues& references, const std::string& csv_file) {
  std::ifstream in(csv_file);
  if (!in) throw std::runtime_error(csv_file + ": cannot be read");
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = csv_cells(line);
  const auto problem_column = std::find(header.begin(), header.end(), "problem_file");
  if (problem_column == header.end()) throw std::runtime_error(csv_file + ": no problem_file column in its header");
  const std::size_t problem_at = static_cast<std::size_t>(problem_column - header.begin());
  const std::string stem = std::filesystem::path(csv_file).stem().string();
  std::vector<std::string> names(header.size());
  std::optional<std::size_t> best_at;
  for (std::size_t c = 0; c < header.size(); ++c) {
    const std::string& h = header[c];
    const bool seconds = (h.size() > 2 && h.compare(h.size() - 2, 2, "_s") == 0) ||
                         (h.size() > 8 && h.compare(h.size() - 8, 8, "_seconds") == 0);
    if (c == problem_at || h == "domain_file" || seconds) continue;
    if (header[c] == "best") {
      best_at = c;
      continue;
    }
    names[c] = header[c];
    if (std::find(references.names.begin(), references.names.end(), names[c]) != references.names.end()) {
      names[c] = stem + "/" + header[c];
    }
    references.names.push_back(names[c]);
  }
  while (std::getline(in, line)) {
    const std::vector<std::string> cells = csv_cells(line);
    if (cells.size() <= problem_at) continue;
    const std::string problem = problem_key(cells[problem_at]);
    for (std::size_t c = 0; c < cells.size() && c < header.size(); ++c) {
      const std::optional<double> v = csv_number(cells[c]);
      if (!v) continue;
      if (best_at && c == *best_at) references.best[problem] = *v;
      else if (!names[c].empty()) references.values[problem][names[c]] = *v;
    }
  }
}

std::vector<double> quality_time_grid(double time_limit) {
  std::vector<double> grid;
  for (int exponent = -2; std::pow(10.0, exponent) < time_limit; ++exponent) {
    for (double step : {1.0, 2.0, 5.0}) {
      const double t = step * std::pow(10.0, exponent);
      if (t < time_limit - 1e-9) grid.push_back(t);
    }
  }
  grid.push_back(time_limit);
  return grid;
}

void write_quality_report(const std::vector<QualityRun>& runs, const ReferenceValues& references,
                          const QualityReportOptions& options, std::ostream& out) {
  const std::vector<ProblemQuality> problems = assess(runs, references, options);
  const Table domains = domain_table(problems, references);
  out << "\nIPC quality score (best known / ours) of our first plan, of our best within the limit, and of each "
         "reference, summed per domain:\n";
  domains.print(out);
  if (options.out_dir.empty()) return;
  const std::vector<double> grid = quality_time_grid(options.time_limit);
  const std::vector<Series> series = over_time(problems, references, grid);
  std::ofstream csv(options.out_dir + "/quality.csv");
  problem_table(problems, references).write_csv(csv);
  std::ofstream md(options.out_dir + "/quality.md");
  domains.print_markdown(md);
  std::ofstream time_csv(options.out_dir + "/quality_over_time.csv");
  time_csv << "seconds,ours";
  for (std::size_t i = 1; i < series.size(); ++i) time_csv << "," << references.names[i - 1];
  time_csv << "\n";
  for (std::size_t k = 0; k < grid.size(); ++k) {
    time_csv << grid[k] << "," << fixed(series[0].points[k].second, 3);
    for (std::size_t i = 1; i < series.size(); ++i) time_csv << "," << fixed(series[i].points[0].second, 3);
    time_csv << "\n";
  }
  std::ofstream(options.out_dir + "/quality_over_time.svg")
      << step_chart_svg("Summed IPC quality score against time, " + std::to_string(problems.size()) + " problems",
                        "seconds", "score", series);
  out << "quality: " << options.out_dir
      << "/ (quality.md per domain, quality.csv per problem, quality_over_time.csv and .svg)\n";
}

}  // namespace alplan::bench
