// A state of the world between happenings: which ground atoms hold, the
// value of each fluent (a fluent nothing assigned is undefined), and the
// derived atoms that follow from them (derived.h), kept apart because they
// are a consequence of the rest and never set by an effect.
#pragma once

#include <optional>
#include <vector>

namespace alplan::oracle {

class State {
 public:
  bool holds(int atom) const { return at(facts_, atom); }
  void set(int atom, bool value) { put(facts_, atom, value); }

  std::optional<double> value(int fluent) const {
    if (!at(defined_, fluent)) return std::nullopt;
    return values_[static_cast<std::size_t>(fluent)];
  }
  void assign(int fluent, double v) {
    put(defined_, fluent, true);
    if (values_.size() <= static_cast<std::size_t>(fluent)) values_.resize(static_cast<std::size_t>(fluent) + 1, 0.0);
    values_[static_cast<std::size_t>(fluent)] = v;
  }

  bool derived_holds(int atom) const { return at(derived_, atom); }
  void set_derived(int atom, bool value) { put(derived_, atom, value); }
  void clear_derived() { derived_.clear(); }

 private:
  static bool at(const std::vector<char>& v, int i) {
    return static_cast<std::size_t>(i) < v.size() && v[static_cast<std::size_t>(i)] != 0;
  }
  static void put(std::vector<char>& v, int i, bool value) {
    if (v.size() <= static_cast<std::size_t>(i)) {
      if (!value) return;
      v.resize(static_cast<std::size_t>(i) + 1, 0);
    }
    v[static_cast<std::size_t>(i)] = value ? 1 : 0;
  }

  std::vector<char> facts_;
  std::vector<double> values_;
  std::vector<char> defined_;
  std::vector<char> derived_;
};

}  // namespace alplan::oracle
