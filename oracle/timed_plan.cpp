#include "oracle/timed_plan.h"

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace alplan::oracle {
namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

bool read_number(const std::string& text, double& out) {
  if (text.empty()) return false;
  char* end = nullptr;
  out = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size();
}

std::string trim(const std::string& s) {
  std::size_t b = 0, e = s.size();
  while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
  while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
  return s.substr(b, e - b);
}

// One line without its comment; false with `error` set when it is no step.
bool read_line(const std::string& raw, int number, TimedStep& step, bool& has_time, std::string& error) {
  const std::string line = trim(raw);
  const std::size_t open = line.find('(');
  const std::size_t close = line.find(')', open == std::string::npos ? 0 : open);
  if (open == std::string::npos || close == std::string::npos) {
    error = "line " + std::to_string(number) + ": expected (action args)";
    return false;
  }
  std::string head = trim(line.substr(0, open));
  has_time = !head.empty();
  if (has_time) {
    if (head.back() != ':') {
      error = "line " + std::to_string(number) + ": expected 'time:' before the action";
      return false;
    }
    head = trim(head.substr(0, head.size() - 1));
    if (!read_number(head, step.time)) {
      error = "line " + std::to_string(number) + ": '" + head + "' is not a time";
      return false;
    }
  }
  std::istringstream words(line.substr(open + 1, close - open - 1));
  std::string word;
  if (!(words >> word)) {
    error = "line " + std::to_string(number) + ": an action name is missing";
    return false;
  }
  step.action = lower(word);
  while (words >> word) step.args.push_back(lower(word));
  const std::string tail = trim(line.substr(close + 1));
  if (!tail.empty()) {
    if (tail.front() != '[' || tail.back() != ']') {
      error = "line " + std::to_string(number) + ": expected [duration] after the action";
      return false;
    }
    double d = 0.0;
    const std::string inner = trim(tail.substr(1, tail.size() - 2));
    if (!read_number(inner, d)) {
      error = "line " + std::to_string(number) + ": '" + inner + "' is not a duration";
      return false;
    }
    step.duration = d;
  }
  step.line = number;
  return true;
}

}  // namespace

TimedPlanRead read_timed_plan(std::string_view text) {
  TimedPlanRead read;
  std::istringstream in{std::string(text)};
  std::string raw;
  int number = 0, timed = 0, untimed = 0;
  while (std::getline(in, raw)) {
    ++number;
    if (const std::size_t semicolon = raw.find(';'); semicolon != std::string::npos) raw.resize(semicolon);
    if (trim(raw).empty()) continue;
    TimedStep step;
    bool has_time = false;
    if (!read_line(raw, number, step, has_time, read.error)) return read;
    (has_time ? timed : untimed) += 1;
    read.plan.steps.push_back(std::move(step));
  }
  if (timed > 0 && untimed > 0) {
    read.error = "some steps have times and some do not";
    return read;
  }
  read.plan.sequential = untimed > 0;
  if (read.plan.sequential) {
    for (std::size_t k = 0; k < read.plan.steps.size(); ++k) read.plan.steps[k].time = static_cast<double>(k + 1);
  }
  return read;
}

std::string write_timed_plan(const TimedPlan& plan, int decimals) {
  std::string out;
  char buffer[64];
  for (const TimedStep& step : plan.steps) {
    std::snprintf(buffer, sizeof buffer, "%.*f: (", decimals, step.time);
    out += buffer;
    out += step.action;
    for (const std::string& a : step.args) out += " " + a;
    out += ")";
    if (step.duration) {
      std::snprintf(buffer, sizeof buffer, " [%.*f]", decimals, *step.duration);
      out += buffer;
    }
    out += "\n";
  }
  return out;
}

}  // namespace alplan::oracle
