#include "planner/plan.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace alplan {
namespace {

// A cursor over one line of a plan file.
class LineCursor {
 public:
  LineCursor(std::string_view line, std::uint32_t number) : line_(line), number_(number) {}

  void skip_space() {
    while (at_ < line_.size() && std::isspace(static_cast<unsigned char>(line_[at_]))) ++at_;
  }
  bool done() {
    skip_space();
    return at_ >= line_.size() || line_[at_] == ';';
  }
  bool accept(char c) {
    skip_space();
    if (at_ < line_.size() && line_[at_] == c) {
      ++at_;
      return true;
    }
    return false;
  }
  std::optional<double> number() {
    skip_space();
    double value = 0;
    auto [ptr, ec] = std::from_chars(line_.data() + at_, line_.data() + line_.size(), value);
    if (ec != std::errc() || ptr == line_.data() + at_) return std::nullopt;
    at_ = static_cast<std::size_t>(ptr - line_.data());
    return value;
  }
  std::string word() {
    skip_space();
    std::string w;
    while (at_ < line_.size()) {
      const char c = line_[at_];
      if (std::isspace(static_cast<unsigned char>(c)) || c == '(' || c == ')' || c == '[' || c == ';') break;
      w += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      ++at_;
    }
    return w;
  }
  std::uint32_t column() const { return static_cast<std::uint32_t>(at_ + 1); }
  std::uint32_t number_of_line() const { return number_; }

 private:
  std::string_view line_;
  std::uint32_t number_;
  std::size_t at_ = 0;
};

bool read_step(LineCursor& cursor, PlanStep& step, std::string& error) {
  if (!cursor.accept('(')) {
    step.time = cursor.number();
    if (!step.time) {
      error = "expected a time or '(' at the start of a plan step";
      return false;
    }
    if (*step.time < 0) {
      error = "a plan step cannot start at a negative time";
      return false;
    }
    if (!cursor.accept(':')) {
      error = "expected ':' after the time of a plan step";
      return false;
    }
    if (!cursor.accept('(')) {
      error = "expected '(' to open the action of a plan step";
      return false;
    }
  }
  step.action = cursor.word();
  if (step.action.empty()) {
    error = "expected an action name after '('";
    return false;
  }
  while (!cursor.accept(')')) {
    std::string arg = cursor.word();
    if (arg.empty()) {
      error = "expected an object name or ')' in the action of a plan step";
      return false;
    }
    step.args.push_back(std::move(arg));
  }
  if (cursor.accept('[')) {
    step.duration = cursor.number();
    if (!step.duration || !cursor.accept(']')) {
      error = "expected a duration as [number]";
      return false;
    }
    if (*step.duration < 0) {
      error = "a duration cannot be negative";
      return false;
    }
  }
  if (!cursor.done()) {
    error = "unexpected text after the plan step";
    return false;
  }
  return true;
}

}  // namespace

PlanReadResult read_plan(std::string_view text, const std::string& file_name) {
  PlanReadResult result;
  std::uint32_t number = 0;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    ++number;
    LineCursor cursor(text.substr(start, end - start), number);
    start = end + 1;
    if (cursor.done()) continue;
    PlanStep step;
    step.line = number;
    std::string error;
    if (read_step(cursor, step, error)) {
      result.plan.steps.push_back(std::move(step));
    } else {
      result.diagnostics.push_back({pddl::Severity::Error, file_name, number, cursor.column(), error});
    }
    if (end == text.size()) break;
  }
  return result;
}

namespace {

bool on_grid(double x, double grid) { return std::fabs(grid - x) < 1e-7; }

}  // namespace

std::string format_value(double x) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.10g", x);
  return buffer;
}

std::string format_seconds(double seconds) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.3f", seconds);
  return buffer;
}

std::string format_plan_time(double x) {
  char buffer[64];
  const double grid = std::round(x * 1000.0) / 1000.0;
  if (on_grid(x, grid)) {
    std::snprintf(buffer, sizeof buffer, "%.3f", grid == 0.0 ? 0.0 : grid);
  } else {
    // Six decimals, or up to nine where six would move a time by more than
    // 1e-9 (a plan whose happenings are only just over 0.0001 apart).
    int decimals = 6;
    for (; decimals < 9; ++decimals) {
      const double scale = std::pow(10.0, decimals);
      if (std::fabs(std::round(x * scale) / scale - x) < 1e-10) break;
    }
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, x);
  }
  return buffer;
}

double rounded_plan_time(double x) {
  const double grid = std::round(x * 1000.0) / 1000.0;
  if (on_grid(x, grid)) return grid == 0.0 ? 0.0 : grid;
  return std::stod(format_plan_time(x));
}

std::string write_plan(const Plan& plan, int decimals) {
  std::string out;
  char buffer[64];
  for (const PlanStep& step : plan.steps) {
    if (step.time) {
      std::snprintf(buffer, sizeof buffer, "%.*f: ", decimals, *step.time);
      out += buffer;
    }
    out += "(" + step.action;
    for (const std::string& a : step.args) out += " " + a;
    out += ")";
    if (step.duration) {
      std::snprintf(buffer, sizeof buffer, "  [%.*f]", decimals, *step.duration);
      out += buffer;
    }
    out += "\n";
  }
  return out;
}

std::string plan_comment(std::string_view text) {
  std::string out;
  std::size_t begin = 0;
  while (true) {
    const std::size_t end = text.find('\n', begin);
    out += "; ";
    out += text.substr(begin, end == std::string_view::npos ? std::string_view::npos : end - begin);
    out += '\n';
    if (end == std::string_view::npos || end + 1 == text.size()) return out;
    begin = end + 1;
  }
}

}  // namespace alplan
