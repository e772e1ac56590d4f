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

std::string forest_plot_svg(const std::string& title, const std::string& unit, const std::vector<IntervalRow>& rows) {
  const int left = 230, plot = 420, top = 50, row_height = 18;
  const int height = top + static_cast<int>(rows.size()) * row_height + 50;
  double lo = 0.0, hi = 0.0;
  for (const IntervalRow& r : rows) {
    if (std::isfinite(r.low)) lo = std::min(lo, r.low);
    if (std::isfinite(r.high)) hi = std::max(hi, r.high);
  }
  if (hi - lo <= 0.0) hi = lo + 1.0;
  const double margin = 0.05 * (hi - lo);
  lo -= margin;
  hi += margin;
  auto x_of = [&](double v) { return left + static_cast<int>(std::lround(plot * (v - lo) / (hi - lo))); };
  std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(left + plot + 40) +
                    "\" height=\"" + std::to_string(height) + "\" font-family=\"sans-serif\" font-size=\"11\">\n";
  svg += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  svg += "<text x=\"10\" y=\"22\" font-size=\"14\">" + escaped(title) + " (" + escaped(unit) + ")</text>\n";
  const int zero = x_of(0.0), bottom = top + static_cast<int>(rows.size()) * row_height;
  svg += "<line x1=\"" + std::to_string(zero) + "\" y1=\"" + std::to_string(top - 8) + "\" x2=\"" + std::to_string(zero) +
         "\" y2=\"" + std::to_string(bottom) + "\" stroke=\"#888\" stroke-dasharray=\"4 3\"/>\n";
  int y = top;
  for (const IntervalRow& r : rows) {
    const std::string colour = r.highlighted ? "#c0392b" : "#4a7ab5";
    svg += "<text x=\"" + std::to_string(left - 8) + "\" y=\"" + std::to_string(y + 4) + "\" text-anchor=\"end\">" +
           escaped(r.label) + "</text>\n";
    if (std::isfinite(r.estimate)) {
      svg += "<line x1=\"" + std::to_string(x_of(r.low)) + "\" y1=\"" + std::to_string(y) + "\" x2=\"" +
             std::to_string(x_of(r.high)) + "\" y2=\"" + std::to_string(y) + "\" stroke=\"" + colour + "\" stroke-width=\"2\"/>\n";
      svg += "<circle cx=\"" + std::to_string(x_of(r.estimate)) + "\" cy=\"" + std::to_string(y) + "\" r=\"4\" fill=\"" +
             colour + "\"/>\n";
    }
    y += row_height;
  }
  svg += "<text x=\"" + std::to_string(left) + "\" y=\"" + std::to_string(bottom + 20) + "\">" + number(lo) + "</text>\n";
  svg += "<text x=\"" + std::to_string(left + plot) + "\" y=\"" + std::to_string(bottom + 20) +
         "\" text-anchor=\"end\">" + number(hi) + "</text>\n";
  svg += "<text x=\"" + std::to_string(zero) + "\" y=\"" + std::to_string(bottom + 20) + "\" text-anchor=\"middle\">0</text>\n";
  return svg + "</svg>\n";
}

}  // namespace alplan::bench
