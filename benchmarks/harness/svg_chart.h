// A bar chart as a standalone SVG file: one bar per label, the value printed
// on it. Enough for the harness's per-metric plots without a plotting stack.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace alplan::bench {

struct Bar {
  std::string label;
  double value = 0.0;
};

std::string bar_chart_svg(const std::string& title, const std::string& unit, const std::vector<Bar>& bars);

// One row of a forest plot: an estimate with its interval.
struct IntervalRow {
  std::string label;
  double estimate = 0.0, low = 0.0, high = 0.0;
  bool highlighted = false;  // drawn in a stronger colour (significant)
};

// A forest plot: each row's estimate as a dot, its interval as a whisker,
// and a vertical line at zero; for differences with confidence intervals.
std::string forest_plot_svg(const std::string& title, const std::string& unit, const std::vector<IntervalRow>& rows);

// One line of a line chart: points (x, y) joined as a step function (the
// value holds until the next point), as anytime quality over time is.
struct Series {
  std::string label;
  std::vector<std::pair<double, double>> points;
  bool dashed = false;  // a reference drawn as a level, not measured over time
};

// A line chart with a logarithmic x axis (x > 0) and a linear y axis from 0,
// a legend under it.
std::string step_chart_svg(const std::string& title, const std::string& x_unit, const std::string& y_unit,
                           const std::vector<Series>& series);

}  // namespace alplan::bench
