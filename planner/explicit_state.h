// A state as plain vectors: one flag per fact and one value per numeric
// variable (NaN when undefined). Grows when the validator interns new facts.
#pragma once

#include <cmath>
#include <vector>

#include "planner/ids.h"

namespace alplan {

class ExplicitState {
 public:
  ExplicitState() = default;
  // The facts listed true, the rest false; the values as given.
  static ExplicitState of(const std::vector<FactId>& facts, const std::vector<double>& values) {
    ExplicitState state;
    for (FactId f : facts) state.set_fact(f, true);
    for (NumericVarId v = 0; v < values.size(); ++v) state.set_value(v, values[v]);
    return state;
  }
  bool fact(FactId f) const { return f < facts_.size() && facts_[f] != 0; }
  double value(NumericVarId v) const { return v < values_.size() ? values_[v] : std::nan(""); }
  void set_fact(FactId f, bool on) {
    if (f >= facts_.size()) facts_.resize(f + 1, 0);
    facts_[f] = on ? 1 : 0;
  }
  void set_value(NumericVarId v, double x) {
    if (v >= values_.size()) values_.resize(v + 1, std::nan(""));
    values_[v] = x;
  }
  const std::vector<char>& facts() const { return facts_; }
  const std::vector<double>& values() const { return values_; }
  bool operator==(const ExplicitState&) const = default;

 private:
  std::vector<char> facts_;
  std::vector<double> values_;
};

}  // namespace alplan
