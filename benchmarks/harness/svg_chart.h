// A bar chart as a standalone SVG file: one bar per label, the value printed
// on it. Enough for the harness's per-metric plots without a plotting stack.
#pragma once

#include <string>
#include <vector>

namespace alplan::bench {

struct Bar {
  std::string label;
  double value = 0.0;
};

std::string bar_chart_svg(const std::string& title, const std::string& unit, const std::vector<Bar>& bars);

}  // namespace alplan::bench
