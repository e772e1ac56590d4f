#include "benchmarks/harness/svg_chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace alplan::bench {
namespace {

std::string escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '&') out += "&amp;";
    else out += c;
  }
  return out;
}

std::string number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, std::fabs(x) >= 100 ? "%.0f" : std::fabs(x) >= 1 ? "%.2f" : "%.3f", x);
  return buffer;
}

}  // namespace

std::string bar_chart_svg(const std::string& title, const std::string& unit, const std::vector<Bar>& bars) {
  const int bar_width = 70, gap = 30, left = 60, top = 50, height = 240;
  const int width = left + static_cast<int>(bars.size()) * (bar_width + gap) + gap;
  double top_value = 0.0;
  for (const Bar& b : bars) top_value = std::max(top_value, std::isfinite(b.value) ? b.value : 0.0);
  if (top_value <= 0.0) top_value = 1.0;
  std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(width) + "\" height=\"" +
                    std::to_string(top + height + 60) + "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  svg += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  svg += "<text x=\"" + std::to_string(left) + "\" y=\"24\" font-size=\"15\">" + escaped(title) + " (" +
         escaped(unit) + ")</text>\n";
  svg += "<line x1=\"" + std::to_string(left) + "\" y1=\"" + std::to_string(top + height) + "\" x2=\"" +
         std::to_string(width - gap / 2) + "\" y2=\"" + std::to_string(top + height) + "\" stroke=\"black\"/>\n";
  int x = left + gap;
  for (const Bar& b : bars) {
    const double value = std::isfinite(b.value) ? b.value : 0.0;
    const int h = static_cast<int>(std::lround(height * value / top_value));
    svg += "<rect x=\"" + std::to_string(x) + "\" y=\"" + std::to_string(top + height - h) + "\" width=\"" +
           std::to_string(bar_width) + "\" height=\"" + std::to_string(h) + "\" fill=\"#4a7ab5\"/>\n";
    svg += "<text x=\"" + std::to_string(x + bar_width / 2) + "\" y=\"" + std::to_string(top + height - h - 5) +
           "\" text-anchor=\"middle\">" + (std::isfinite(b.value) ? number(b.value) : "n/a") + "</text>\n";
    svg += "<text x=\"" + std::to_string(x + bar_width / 2) + "\" y=\"" + std::to_string(top + height + 18) +
           "\" text-anchor=\"middle\">" + escaped(b.label) + "</text>\n";
    x += bar_width + gap;
  }
  return svg + "</svg>\n";
}

}  // namespace alplan::bench
