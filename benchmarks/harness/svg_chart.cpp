#include "benchmarks/harness/svg_chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

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

std::string step_chart_svg(const std::string& title, const std::string& x_unit, const std::string& y_unit,
                           const std::vector<Series>& series) {
  const int left = 60, plot_w = 480, top = 45, plot_h = 260, legend_row = 16;
  static const char* const kColours[] = {"#4a7ab5", "#c0392b", "#27ae60", "#8e44ad", "#d35400", "#7f8c8d"};
  double x_lo = std::numeric_limits<double>::infinity(), x_hi = 0.0, y_hi = 0.0;
  for (const Series& s : series) {
    for (const auto& [x, y] : s.points) {
      if (x > 0.0) x_lo = std::min(x_lo, x), x_hi = std::max(x_hi, x);
      y_hi = std::max(y_hi, y);
    }
  }
  if (!std::isfinite(x_lo)) x_lo = 0.1, x_hi = 1.0;
  if (x_hi <= x_lo) x_hi = x_lo * 10.0;
  if (y_hi <= 0.0) y_hi = 1.0;
  auto x_of = [&](double x) {
    const double t = (std::log10(std::max(x, x_lo)) - std::log10(x_lo)) / (std::log10(x_hi) - std::log10(x_lo));
    return left + static_cast<int>(std::lround(plot_w * t));
  };
  auto y_of = [&](double y) { return top + plot_h - static_cast<int>(std::lround(plot_h * y / (y_hi * 1.05))); };
  const int height = top + plot_h + 45 + legend_row * static_cast<int>(series.size());
  std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(left + plot_w + 30) +
                    "\" height=\"" + std::to_string(height) + "\" font-family=\"sans-serif\" font-size=\"11\">\n";
  svg += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  svg += "<text x=\"10\" y=\"22\" font-size=\"14\">" + escaped(title) + "</text>\n";
  const int bottom = top + plot_h;
  svg += "<line x1=\"" + std::to_string(left) + "\" y1=\"" + std::to_string(bottom) + "\" x2=\"" +
         std::to_string(left + plot_w) + "\" y2=\"" + std::to_string(bottom) + "\" stroke=\"black\"/>\n";
  svg += "<line x1=\"" + std::to_string(left) + "\" y1=\"" + std::to_string(top) + "\" x2=\"" + std::to_string(left) +
         "\" y2=\"" + std::to_string(bottom) + "\" stroke=\"black\"/>\n";
  for (double tick = std::pow(10.0, std::floor(std::log10(x_lo))); tick <= x_hi * 1.0001; tick *= 10.0) {
    if (tick < x_lo * 0.9999) continue;
    svg += "<text x=\"" + std::to_string(x_of(tick)) + "\" y=\"" + std::to_string(bottom + 15) +
           "\" text-anchor=\"middle\">" + number(tick) + "</text>\n";
  }
  svg += "<text x=\"" + std::to_string(left + plot_w / 2) + "\" y=\"" + std::to_string(bottom + 30) +
         "\" text-anchor=\"middle\">" + escaped(x_unit) + " (log scale)</text>\n";
  for (int k = 0; k <= 4; ++k) {
    const double y = y_hi * k / 4.0;
    svg += "<text x=\"" + std::to_string(left - 5) + "\" y=\"" + std::to_string(y_of(y) + 4) +
           "\" text-anchor=\"end\">" + number(y) + "</text>\n";
  }
  svg += "<text x=\"12\" y=\"" + std::to_string(top - 8) + "\">" + escaped(y_unit) + "</text>\n";
  for (std::size_t i = 0; i < series.size(); ++i) {
    const Series& s = series[i];
    const std::string colour = kColours[i % (sizeof kColours / sizeof *kColours)];
    std::string path;
    for (std::size_t p = 0; p < s.points.size(); ++p) {
      const int x = x_of(s.points[p].first), y = y_of(s.points[p].second);
      if (p > 0) path += " " + std::to_string(x) + "," + std::to_string(y_of(s.points[p - 1].second));
      path += (path.empty() ? "" : " ") + std::to_string(x) + "," + std::to_string(y);
    }
    svg += "<polyline fill=\"none\" stroke=\"" + colour + "\" stroke-width=\"2\"" +
           (s.dashed ? " stroke-dasharray=\"6 4\"" : "") + " points=\"" + path + "\"/>\n";
    const int ly = bottom + 45 + legend_row * static_cast<int>(i);
    svg += "<line x1=\"" + std::to_string(left) + "\" y1=\"" + std::to_string(ly - 4) + "\" x2=\"" +
           std::to_string(left + 24) + "\" y2=\"" + std::to_string(ly - 4) + "\" stroke=\"" + colour +
           "\" stroke-width=\"2\"" + (s.dashed ? " stroke-dasharray=\"6 4\"" : "") + "/>\n";
    svg += "<text x=\"" + std::to_string(left + 30) + "\" y=\"" + std::to_string(ly) + "\">" + escaped(s.label) +
           "</text>\n";
  }
  return svg + "</svg>\n";
}

}  // namespace alplan::bench
