#include "planner/numeric_intervals.h"

#include <algorithm>
#include <cmath>

namespace alplan {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

Interval operator+(Interval a, Interval b) { return {a.lo + b.lo, a.hi + b.hi}; }
Interval operator-(Interval a, Interval b) { return {a.lo - b.hi, a.hi - b.lo}; }
Interval operator*(Interval a, Interval b) {
  const double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
  Interval r{kInfinity, -kInfinity};
  for (double x : p) {
    if (std::isnan(x)) return {};  // 0 * inf: anything
    r.lo = std::min(r.lo, x);
    r.hi = std::max(r.hi, x);
  }
  return r;
}
Interval operator/(Interval a, Interval b) {
  if (b.lo <= 0.0 && b.hi >= 0.0) return {};
  return a * Interval{1.0 / b.hi, 1.0 / b.lo};
}

}  // namespace

NumericIntervals::NumericIntervals(std::size_t variables)
    : bounds_(variables),
      greatest_now_(variables),
      up_(variables, kNoId),
      down_(variables, kNoId),
      first_(variables, kNoId),
      changes_(variables, 0) {}

void NumericIntervals::reset(const SearchState& state, const PartialPlan& plan, const ContinuousModel* continuous) {
  for (NumericVarId v = 0; v < bounds_.size(); ++v) {
    const double x = state.value(v);
    bounds_[v] = std::isnan(x) ? Interval{kInfinity, -kInfinity} : Interval{x, x};
    greatest_now_[v] = std::nan("");
    if (continuous && continuous->changing(v) && !std::isnan(x)) {
      const ContinuousModel::NeededBounds needed = continuous->needed_bounds(v, state);
      if (needed.least || needed.greatest) {
        const auto [lo, hi] = plan.changing_bounds(v, x, needed.least, needed.greatest);
        if (lo <= hi) bounds_[v] = Interval{lo, hi};
        if (lo <= hi && needed.greatest) greatest_now_[v] = hi;
      }
    }
    up_[v] = down_[v] = first_[v] = kNoId;
    changes_[v] = 0;
  }
}

Interval NumericIntervals::interval(const GroundExpression& e) const {
  using K = GroundExpression::Kind;
  switch (e.kind) {
    case K::Constant: return {e.value, e.value};
    case K::Variable: return bounds_[e.variable];
    case K::Add: {
      Interval r = interval(e.operands[0]);
      for (std::size_t i = 1; i < e.operands.size(); ++i) r = r + interval(e.operands[i]);
      return r;
    }
    case K::Multiply: {
      Interval r = interval(e.operands[0]);
      for (std::size_t i = 1; i < e.operands.size(); ++i) r = r * interval(e.operands[i]);
      return r;
    }
    case K::Subtract: return interval(e.operands[0]) - interval(e.operands[1]);
    case K::Divide: return interval(e.operands[0]) / interval(e.operands[1]);
    case K::Negate: {
      const Interval i = interval(e.operands[0]);
      return {-i.hi, -i.lo};
    }
    case K::Duration: return {0.0, kInfinity};
    default: return {};
  }
}

bool NumericIntervals::satisfiable(const GroundComparison& cmp) const {
  const Interval left = interval(cmp.left), right = interval(cmp.right);
  if (left.undefined() || right.undefined()) return false;  // an undefined variable
  const Interval d = left - right;
  switch (cmp.comparison) {
    case pddl::Comparison::Less: return d.lo < 0.0;
    case pddl::Comparison::LessEqual: return d.lo <= 0.0;
    case pddl::Comparison::Equal: return d.lo <= 0.0 && d.hi >= 0.0;
    case pddl::Comparison::GreaterEqual: return d.hi >= 0.0;
    case pddl::Comparison::Greater: return d.hi > 0.0;
  }
  return true;
}

bool NumericIntervals::apply(const NumericAssignment& a, ActionId source) {
  Interval& b = bounds_[a.variable];
  const Interval before = b;
  const Interval v = interval(a.value);
  if (v.undefined()) return false;  // reads an undefined variable
  switch (a.assign) {
    case pddl::AssignOperator::Assign:
      b = b.undefined() ? v : Interval{std::min(b.lo, v.lo), std::max(b.hi, v.hi)};
      break;
    case pddl::AssignOperator::Increase:
    case pddl::AssignOperator::Decrease: {
      if (b.undefined()) b = {0.0, 0.0};  // VAL starts an undefined value at 0
      const bool up = a.assign == pddl::AssignOperator::Increase;
      if ((up ? v.hi : -v.lo) > 0) b.hi = kInfinity;
      if ((up ? v.lo : -v.hi) < 0) b.lo = -kInfinity;
      break;
    }
    default: b = {}; break;
  }
  if (b.lo == before.lo && b.hi == before.hi) return false;
  if (++changes_[a.variable] > kWidenAfter) b = {};
  if (first_[a.variable] == kNoId) first_[a.variable] = source;
  const bool undefined_before = before.undefined();
  if (up_[a.variable] == kNoId && (undefined_before || b.hi > before.hi)) up_[a.variable] = source;
  if (down_[a.variable] == kNoId && (undefined_before || b.lo < before.lo)) down_[a.variable] = source;
  return true;
}

}  // namespace alplan
