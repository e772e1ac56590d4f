#include "planner/fact_windows.h"

#include <algorithm>
#include <limits>

#include "planner/successor_generator.h"

namespace alplan {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kTolerance = 1e-9;

}  // namespace

FactWindows::FactWindows(const GroundTask& task) : task_(task) {
  literals_of_.resize(task.facts.size());
  for (std::uint32_t t = 0; t < task.timed_literals.size(); ++t) literals_of_[task.timed_literals[t].fact].push_back(t);
  restricted_.assign(task.facts.size(), 0);
  windows_.resize(task.facts.size());
  find_windowed_facts();
}

void FactWindows::find_windowed_facts() {
  const std::size_t facts = task_.facts.size();
  windowed_.assign(facts, 0);
  spans_.resize(facts);
  provider_span_.assign(task_.actions.size(), 0.0);
  std::vector<char> given(facts, 0), ruled_out(facts, 0);
  auto contains = [](const std::vector<FactId>& v, FactId f) { return std::find(v.begin(), v.end(), f) != v.end(); };
  for (std::size_t a = 0; a < task_.actions.size(); ++a) {
    const GroundAction& action = task_.actions[a];
    for (const HappeningEffects* effects : {&action.start, &action.end}) {
      for (const ConditionalEffect& conditional : effects->conditional) {
        for (FactId f : conditional.add) ruled_out[f] = 1;
      }
    }
    for (FactId f : action.end.add) ruled_out[f] = 1;
    if (!action.durative) {
      for (FactId f : action.start.add) ruled_out[f] = 1;
      continue;
    }
    const std::optional<DurationWindow> window = constant_duration_window(action, Moment::Start);
    const bool bounded = window && window->valid && window->max < kInfiniteDuration;
    for (FactId f : action.start.add) {
      if (bounded && contains(action.end.del, f)) {
        given[f] = 1;
        provider_span_[a] = window->max;
      } else {
        ruled_out[f] = 1;
      }
    }
  }
  for (const GroundTimedLiteral& literal : task_.timed_literals) ruled_out[literal.fact] = 1;
  for (FactId f = 0; f < facts; ++f) {
    if (given[f] && !ruled_out[f]) {
      windowed_[f] = 1;
      windowed_facts_.push_back(f);
    }
  }
  // A provider's span counts only for the windowed facts it gives; one that
  // gives none keeps its span unused.
}

void FactWindows::reset(const SearchState& state, const PartialPlan& plan, bool running_ends, double gap) {
  for (FactId f : touched_) {
    restricted_[f] = 0;
    windows_[f].clear();
  }
  touched_.clear();
  // Deadlines from running actions whose end deletes a fact true now.
  std::vector<std::pair<FactId, double>> closing;
  static const std::vector<RunningAction> kNone;
  const std::vector<RunningAction>& running = running_ends ? state.running() : kNone;
  const std::vector<double> latest = running.empty() ? std::vector<double>{} : plan.latest_end_times(running);
  for (std::size_t i = 0; i < running.size(); ++i) {
    if (latest[i] == kInfinity) continue;
    const HappeningEffects& end = task_.actions[running[i].action].end;
    for (FactId f : end.del) {
      // An end that deletes and adds a fact leaves it true (adds win).
      if (state.fact(f) && std::find(end.add.begin(), end.add.end(), f) == end.add.end()) closing.emplace_back(f, latest[i]);
    }
  }
  std::vector<FactId> candidates;
  for (const auto& [f, at] : closing) candidates.push_back(f);
  for (std::uint32_t t = state.next_timed_literal(); t < task_.timed_literals.size(); ++t) {
    candidates.push_back(task_.timed_literals[t].fact);
  }
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  for (FactId f : candidates) {
    double open = state.fact(f) ? plan.available_from(f, gap) : kInfinity;
    double now_closes = kInfinity;
    for (const auto& [g, at] : closing) {
      if (g == f) now_closes = std::min(now_closes, at);
    }
    std::vector<Window> windows;
    bool first = open != kInfinity;
    for (std::uint32_t t : literals_of_[f]) {
      if (t < state.next_timed_literal()) continue;
      const GroundTimedLiteral& til = task_.timed_literals[t];
      if (til.positive && open == kInfinity) open = til.time + gap;
      if (!til.positive && open != kInfinity) {
        windows.emplace_back(open, first ? std::min(til.time, now_closes) : til.time);
        open = kInfinity;
        first = false;
      }
    }
    if (open != kInfinity) windows.emplace_back(open, first ? now_closes : kInfinity);
    if (windows.size() == 1 && windows.front().second == kInfinity) continue;  // never closes
    restricted_[f] = 1;
    windows_[f] = std::move(windows);
    touched_.push_back(f);
  }
  // Windowed facts are always restricted: what the state holds of them is
  // their window now (closing when a running provider ends), and achievers
  // in the relaxation give spans.
  for (FactId f : windowed_facts_) {
    spans_[f].clear();
    if (restricted_[f]) continue;
    restricted_[f] = 1;
    if (state.fact(f)) windows_[f].emplace_back(plan.available_from(f, gap), kInfinity);
    touched_.push_back(f);
  }
}

bool FactWindows::open_span(FactId f, double time, double length, ActionId provider) {
  std::vector<Span>& spans = spans_[f];
  for (const Span& s : spans) {
    if (s.from <= time + kTolerance && s.length >= length - kTolerance) return false;
  }
  spans.push_back({time, length, provider});
  return true;
}

ActionId FactWindows::span_provider(FactId f, double length) const {
  const Span* best = nullptr;
  for (const Span& s : spans_[f]) {
    if (s.length >= length - kTolerance && (!best || s.from < best->from)) best = &s;
  }
  return best ? best->provider : kNoId;
}

double FactWindows::span_delay(FactId f, double from, double length) const {
  double delay = kInfinity;
  for (const Span& s : spans_[f]) {
    if (s.length >= length - kTolerance) delay = std::min(delay, std::max(0.0, s.from - from));
  }
  return delay;
}

bool FactWindows::open_from(FactId f, double time) {
  if (!restricted_[f]) return false;
  std::vector<Window>& w = windows_[f];
  if (!w.empty() && w.back().second == kInfinity && w.back().first <= time) return false;
  // Usable for good from `time`: drop what that window swallows.
  while (!w.empty() && w.back().first >= time) w.pop_back();
  if (!w.empty() && w.back().second >= time) {
    w.back().second = kInfinity;
  } else {
    w.emplace_back(time, kInfinity);
  }
  return true;
}

// Whether one window holds [from, to]; otherwise `moved` is how far to the
// first window that can, or infinity when none can.
bool FactWindows::covers(FactId f, double from, double to, double& moved) const {
  for (const Window& w : windows_[f]) {
    // Closes too soon. A window closing exactly at the end still covers an
    // over-all condition (VAL checks it on the open interval); at a point
    // it may be a mutex, which the relaxation need not see.
    if (w.second < to - kTolerance) continue;
    if (w.first <= from + kTolerance) return true;
    moved = w.first - from;
    return false;
  }
  moved = kInfinity;
  return false;
}

FactWindows::Fit FactWindows::fit(double start, double duration, const std::vector<FactId>& at_start,
                                  const std::vector<FactId>& over_all, const std::vector<FactId>& at_end) const {
  Fit result;
  result.start = start;
  // Most states restrict no fact (no deadline, no running end deleting what
  // holds): every window is open for good.
  if (touched_.empty()) return result;
  for (int round = 0; round < 16; ++round) {
    bool moved_any = false;
    auto check = [&](const std::vector<FactId>& facts, double from, double to) {
      for (FactId f : facts) {
        if (!restricted_[f]) continue;
        double moved = 0.0;
        if (covers(f, result.start + from, result.start + to, moved)) continue;
        if (windowed_[f]) {
          const double delay = span_delay(f, result.start + from, to - from);
          if (delay <= kTolerance) continue;
          moved = std::min(moved, delay);
        }
        if (moved == kInfinity) {
          result.ok = false;
          result.blocking = f;
          return false;
        }
        result.start += moved;
        moved_any = true;
      }
      return true;
    };
    if (!check(at_start, 0.0, 0.0) || !check(over_all, 0.0, duration) || !check(at_end, duration, duration)) {
      return result;
    }
    if (!moved_any) return result;
  }
  return result;
}

}  // namespace alplan
