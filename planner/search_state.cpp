#include "planner/search_state.h"

#include <algorithm>
#include <bit>
#include <cstring>

namespace alplan {

void SearchState::start(const RunningAction& action) {
  auto at = std::upper_bound(running_.begin(), running_.end(), action,
                             [](const RunningAction& a, const RunningAction& b) { return a.action < b.action; });
  running_.insert(at, action);
}

void SearchState::set_start_step(ActionId action, std::uint32_t step) {
  for (RunningAction& r : running_) {
    if (r.action == action && r.start_step == kStepNotYetKnown) r.start_step = step;
  }
}

bool SearchState::is_running(ActionId action) const {
  return std::any_of(running_.begin(), running_.end(), [&](const RunningAction& r) { return r.action == action; });
}

std::size_t SearchState::hash() const {
  std::uint64_t h = 0x9E3779B97F4A7C15ull ^ next_til_ ^ (std::uint64_t{open_from_ != kNoId} << 32) ^
                    (std::uint64_t{ends_open_} << 33);
  auto mix = [&](std::uint64_t x) {
    h ^= x + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
  };
  for (std::uint64_t word : bits_) mix(word);
  for (double v : values_) mix(std::bit_cast<std::uint64_t>(v));
  for (const RunningAction& r : running_) {
    mix(r.action);
    mix(std::bit_cast<std::uint64_t>(r.min_duration));
  }
  return static_cast<std::size_t>(h);
}

bool SearchState::same_as(const SearchState& other) const {
  if (next_til_ != other.next_til_ || (open_from_ == kNoId) != (other.open_from_ == kNoId) ||
      ends_open_ != other.ends_open_ || bits_ != other.bits_ ||
      running_.size() != other.running_.size()) {
    return false;
  }
  for (std::size_t i = 0; i < running_.size(); ++i) {
    const RunningAction& a = running_[i];
    const RunningAction& b = other.running_[i];
    if (a.action != b.action || a.min_duration != b.min_duration || a.max_duration != b.max_duration) return false;
    if (joined_open_happening(a) != other.joined_open_happening(b)) return false;
  }
  // NaN (undefined) equals NaN here: compare bit patterns.
  // memcmp may not be given the null data() of an empty vector, even for 0 bytes.
  return values_.size() == other.values_.size() &&
         (values_.empty() || std::memcmp(values_.data(), other.values_.data(), values_.size() * sizeof(double)) == 0);
}

}  // namespace alplan
