#include "planner/progress_meter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace alplan {
namespace {

std::string clock_text(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "?";
  const long s = std::lround(seconds);
  char text[32];
  if (s >= 3600) std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
  else std::snprintf(text, sizeof text, "%ld:%02ld", s / 60, s % 60);
  return text;
}

std::string amount(double x) {
  char text[32];
  std::snprintf(text, sizeof text, std::fabs(x - std::round(x)) < 0.05 ? "%.0f" : "%.1f", x);
  return text;
}

}  // namespace

ProgressMeter::ProgressMeter(std::ostream& out, double total, std::string unit, bool terminal)
    : out_(out), total_(std::max(total, 0.0)), unit_(std::move(unit)), terminal_(terminal) {}

ProgressMeter::~ProgressMeter() { finish(); }

std::string ProgressMeter::bar(double done, double total, const std::string& unit, double elapsed_s, int width) {
  const double share = total > 0 ? std::clamp(done / total, 0.0, 1.0) : 1.0;
  const int filled = static_cast<int>(share * width);
  std::string text = "[";
  for (int i = 0; i < width; ++i) text += i < filled ? '=' : (i == filled ? '>' : ' ');
  text += "] " + amount(done) + "/" + amount(total) + " " + unit;
  const double rate = elapsed_s > 0 ? done / elapsed_s : 0.0;
  char tail[96];
  std::snprintf(tail, sizeof tail, rate >= 100 ? "  %.0f/s  ETA %s" : "  %.3g/s  ETA %s", rate,
                rate > 0 ? clock_text((total - done) / rate).c_str() : "?");
  return text + tail;
}

void ProgressMeter::update(double done, const std::string& line) {
  done_ = std::min(done, total_);
  if (!terminal_) {
    if (!line.empty()) out_ << line << "\n" << std::flush;
    return;
  }
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - began_).count();
  out_ << "\r\033[K";
  if (!line.empty()) out_ << line << "\n";
  out_ << bar(done_, total_, unit_, elapsed) << std::flush;
  drawn_ = true;
}

void ProgressMeter::finish() {
  if (terminal_ && drawn_) out_ << "\n" << std::flush;
  drawn_ = false;
}

std::function<void(double)> simulated_time_meter(ProgressMeter& meter) {
  double next_line = 3600.0, next_draw = 0.0;
  return [&meter, next_line, next_draw](double t) mutable {
    if (t >= next_line) {
      meter.update(t, "simulated " + std::to_string(static_cast<long>(t / 3600)) + " h");
      next_line += 3600.0;
    } else if (t >= next_draw) {
      meter.update(t);
      next_draw = t + 60.0;
    }
  };
}

}  // namespace alplan
