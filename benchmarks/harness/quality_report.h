// Plan quality as a reviewer reads it: per problem the first plan and the
// best within the limit, the time each was found, and the IPC quality score
// of each (best known / ours; ours / best where the metric is maximised)
// beside reference values from CSV files (shared/benchmarks/baseline/
// quality_ref.csv, or any file with a problem_file column and numeric
// columns); per-domain sums; and the summed score over time, as a CSV and an
// SVG chart. `bench planners` writes it (with --anytime the first and the
// best plan differ).
//
// The best known value of a problem is the best of every reference value
// and every plan of ours; a problem without any counts 0 for everyone.
#pragma once

#include <functional>
#include <iosfwd>
#include <map>
#include <string>
#include <vector>

namespace alplan::bench {

struct PlanFound {
  double seconds = 0.0;  // since the run began, grounding included
  double value = 0.0;
};

struct QualityRun {
  std::string domain;
  std::string problem;  // problem_key(): ipc/ipc-YYYY/.../instance-N.pddl
  std::vector<PlanFound> plans;  // in the order found, each better than the last; empty: unsolved
};

struct ReferenceValues {
  std::vector<std::string> names;  // columns, in the order of the files
  std::map<std::string, std::map<std::string, double>> values;  // problem -> name -> value
  // Columns named `best` (quality_ref.csv's best of its planners): read for
  // the best known value, not shown as a planner.
  std::map<std::string, double> best;
};

// Adds a CSV file's numeric columns (every column but domain_file,
// problem_file, best and times: a name ending in _s or _seconds; empty cells
// are no value). A name already taken
// becomes FILE-STEM/NAME. Throws std::runtime_error when the file cannot be
// read or has no problem_file column.
void add_reference_file(ReferenceValues& references, const std::string& csv_file);

struct QualityReportOptions {
  double time_limit = 60.0;
  std::string out_dir;  // quality.md, quality.csv, quality_over_time.csv and .svg; "" writes nothing
  std::function<bool(const std::string& problem)> maximized = [](const std::string&) { return false; };
};

// Prints the per-domain table to `out` and writes the files.
void write_quality_report(const std::vector<QualityRun>& runs, const ReferenceValues& references,
                          const QualityReportOptions& options, std::ostream& out);

// The times at which the summed score is read: 0.01 s, 0.02, 0.05, 0.1, ...
// up to the limit, the limit included.
std::vector<double> quality_time_grid(double time_limit);

}  // namespace alplan::bench
