#include "planner/continuous_schedule.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace alplan {
namespace {

bool reads_any(const std::vector<LinearCondition>& conditions, const std::vector<NumericVarId>& written) {
  for (const LinearCondition& c : conditions) {
    for (const auto& [v, coefficient] : c.form.terms) {
      if (std::find(written.begin(), written.end(), v) != written.end()) return true;
    }
  }
  return false;
}

}  // namespace

void ContinuousSchedule::Affine::add(std::uint32_t node, double coefficient) {
  for (auto& [n, c] : terms) {
    if (n == node) {
      c += coefficient;
      return;
    }
  }
  terms.emplace_back(node, coefficient);
}

void ContinuousSchedule::Affine::add(const Affine& other, double k) {
  constant += k * other.constant;
  for (const auto& [n, c] : other.terms) add(n, k * c);
}

ContinuousSchedule::ContinuousSchedule(std::shared_ptr<const ContinuousModel> model,
                                       const std::vector<double>& initial_values)
    : model_(std::move(model)), values_(initial_values.size()), last_change_(initial_values.size(), 0), times_(1, 0.0) {
  for (std::size_t v = 0; v < initial_values.size(); ++v) {
    // Increasing an undefined value starts it from 0, as VAL does.
    values_[v].base.constant = std::isnan(initial_values[v]) ? 0.0 : initial_values[v];
  }
}

ContinuousSchedule::Affine ContinuousSchedule::at(NumericVarId v, std::uint32_t node) const {
  Affine a = values_[v].base;
  if (values_[v].gradient != 0.0) a.add(node, values_[v].gradient);
  return a;
}

ContinuousSchedule::Affine ContinuousSchedule::evaluate(const LinearForm& form, std::uint32_t node,
                                                        const SnapNodes& at) const {
  Affine a;
  a.constant = form.constant;
  for (const auto& [v, coefficient] : form.terms) a.add(this->at(v, node), coefficient);
  if (form.duration != 0.0) {
    a.add(at.end_node, form.duration);
    a.add(at.start_node, -form.duration);
  }
  return a;
}

void ContinuousSchedule::require(const LinearCondition& c, std::uint32_t node, const SnapNodes& at) {
  rows_.push_back(row_for(c, node, at));
}

LinearRow ContinuousSchedule::row_for(const LinearCondition& c, std::uint32_t node, const SnapNodes& at) const {
  const Affine a = evaluate(c.form, node, at);
  LinearRow row;
  row.coefficients = a.terms;
  switch (c.comparison) {
    case pddl::Comparison::Less:
    case pddl::Comparison::LessEqual: row.upper = -a.constant; break;
    case pddl::Comparison::Greater:
    case pddl::Comparison::GreaterEqual: row.lower = -a.constant; break;
    case pddl::Comparison::Equal: row.lower = row.upper = -a.constant; break;
  }
  return row;
}

namespace {

std::vector<NumericVarId> written_by(const ContinuousStep& step, const SnapNodes& at,
                                     const std::vector<std::pair<NumericVarId, double>>* ending_rates) {
  std::vector<NumericVarId> written;
  for (const LinearAssignment& e : step.effects) written.push_back(e.variable);
  for (const auto& [v, rate] : step.rates) written.push_back(v);
  if (at.kind == SnapKind::End && ending_rates) {
    for (const auto& [v, rate] : *ending_rates) written.push_back(v);
  }
  std::sort(written.begin(), written.end());
  written.erase(std::unique(written.begin(), written.end()), written.end());
  return written;
}

}  // namespace

std::vector<NumericVarId> ContinuousSchedule::invariant_reads(const ContinuousStep& step, const SnapNodes& at) const {
  const std::vector<std::pair<NumericVarId, double>>* ending = nullptr;
  for (const Running& r : running_) {
    if (at.kind == SnapKind::End && r.action == at.action) ending = &r.rates;
  }
  const std::vector<NumericVarId> written = written_by(step, at, ending);
  std::vector<NumericVarId> reads;
  for (const Running& r : running_) {
    if (!reads_any(r.invariants, written)) continue;
    for (const LinearCondition& c : r.invariants) {
      for (const auto& [v, coefficient] : c.form.terms) reads.push_back(v);
    }
  }
  std::sort(reads.begin(), reads.end());
  reads.erase(std::unique(reads.begin(), reads.end()), reads.end());
  return reads;
}

void ContinuousSchedule::check_invariants(const std::vector<NumericVarId>& written, const SnapNodes& at,
                                          ActionId always) {
  for (const Running& r : running_) {
    if (r.action != always && !reads_any(r.invariants, written)) continue;
    // ?duration in an invariant is the running action's own.
    const SnapNodes own{SnapKind::Start, r.action, at.node, r.start_node, r.end_node};
    for (const LinearCondition& c : r.invariants) require(c, at.node, own);
  }
}

bool ContinuousSchedule::apply_effects(const std::vector<LinearAssignment>& effects, const SnapNodes& at) {
  // Every right-hand side reads the values before the snap, as VAL does.
  std::vector<Affine> values;
  for (const LinearAssignment& e : effects) values.push_back(evaluate(e.value, at.node, at));
  for (std::size_t i = 0; i < effects.size(); ++i) {
    Trajectory& t = values_[effects[i].variable];
    const Affine& value = values[i];
    switch (effects[i].assign) {
      case pddl::AssignOperator::Increase: t.base.add(value, 1.0); break;
      case pddl::AssignOperator::Decrease: t.base.add(value, -1.0); break;
      case pddl::AssignOperator::Assign:
        t.base = value;
        if (t.gradient != 0.0) t.base.add(at.node, -t.gradient);
        break;
      case pddl::AssignOperator::ScaleUp:
      case pddl::AssignOperator::ScaleDown: {
        if (!value.terms.empty()) return false;  // a product of two times: not linear
        if (effects[i].assign == pddl::AssignOperator::ScaleDown && value.constant == 0.0) return false;
        const double k = effects[i].assign == pddl::AssignOperator::ScaleUp ? value.constant : 1.0 / value.constant;
        Affine scaled;
        scaled.add(t.base, k);
        if (t.gradient != 0.0) scaled.add(at.node, (k - 1.0) * t.gradient);
        t.base = std::move(scaled);
        break;
      }
    }
  }
  return true;
}

bool ContinuousSchedule::add(const ContinuousStep& step, const SnapNodes& at, const SimpleTemporalNetwork& network,
                             bool solve) {
  ContinuousSchedule next = *this;
  auto ending = std::find_if(next.running_.begin(), next.running_.end(),
                             [&](const Running& r) { return at.kind == SnapKind::End && r.action == at.action; });
  const std::vector<NumericVarId> written =
      written_by(step, at, ending == next.running_.end() ? nullptr : &ending->rates);
  for (const LinearCondition& c : step.conditions) next.require(c, at.node, at);
  next.check_invariants(written, at, at.kind == SnapKind::End ? at.action : kNoId);
  if (!next.apply_effects(step.effects, at)) return false;
  if (at.kind == SnapKind::End && ending != next.running_.end()) {
    for (const auto& [v, rate] : ending->rates) {
      next.values_[v].base.add(at.node, rate);
      next.values_[v].gradient -= rate;
    }
    next.running_.erase(ending);
  }
  if (at.kind == SnapKind::Start) {
    for (const auto& [v, rate] : step.rates) {
      next.values_[v].base.add(at.node, -rate);
      next.values_[v].gradient += rate;
    }
    if (!step.invariants.empty() || !step.rates.empty()) {
      next.running_.push_back({at.action, step.invariants, step.rates, at.start_node, at.end_node});
    }
  }
  next.check_invariants(written, at, at.kind == SnapKind::Start ? at.action : kNoId);
  for (NumericVarId v : written) next.last_change_[v] = at.node;
  if (solve && !next.solve(network)) return false;
  *this = std::move(next);
  return true;
}

bool ContinuousSchedule::require_final(const std::vector<LinearCondition>& conditions,
                                       const SimpleTemporalNetwork& network) {
  if (conditions.empty()) return solve(network, true);
  ContinuousSchedule next = *this;
  const SnapNodes nowhere;
  for (const LinearCondition& c : conditions) next.require(c, 0, nowhere);
  if (!next.solve(network, true)) return false;
  *this = std::move(next);
  return true;
}

bool ContinuousSchedule::resolve(const SimpleTemporalNetwork& network) { return solve(network); }

bool ContinuousSchedule::solve(const SimpleTemporalNetwork& network, bool least) {
  // The network's earliest times are the least schedule there is: when they
  // meet every linear constraint they are the program's optimum, unsolved.
  if (satisfied_by(network.earliest_times())) {
    times_ = network.earliest_times();
    return true;
  }
  // Most steps fit after the schedule found before them: that schedule,
  // pushed along the new constraints, is feasible if it meets them all, if
  // not always the least.
  if (!least) {
    if (std::optional<std::vector<double>> pushed = pushed_schedule(network); pushed && satisfied_by(*pushed)) {
      times_ = std::move(*pushed);
      return true;
    }
  }
  std::optional<std::vector<double>> x = alplan::solve(program(network));
  if (!x) return false;
  times_ = std::move(*x);
  return true;
}

std::pair<double, double> ContinuousSchedule::bounds(NumericVarId v, std::uint32_t node,
                                                     const SimpleTemporalNetwork& network, bool least,
                                                     bool greatest) const {
  const Affine a = at(v, node);
  if (a.terms.empty()) return {a.constant, a.constant};
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  LinearProgram lp = program(network);
  const double value = value_at(v, node);
  std::pair<double, double> range{least ? -kInfinity : value, greatest ? kInfinity : value};
  for (double sign : {1.0, -1.0}) {
    if ((sign > 0 && !least) || (sign < 0 && !greatest)) continue;
    std::fill(lp.objective.begin(), lp.objective.end(), 0.0);
    for (const auto& [n, c] : a.terms) lp.objective[n] += sign * c;
    const LinearSolution s = solve_program(lp);
    if (s.status == LinearSolution::Status::Infeasible) return {kInfinity, -kInfinity};
    if (s.status == LinearSolution::Status::Optimal) {
      (sign > 0 ? range.first : range.second) = a.constant + sign * s.objective;
    }
  }
  return range;
}

LinearProgram ContinuousSchedule::program(const SimpleTemporalNetwork& network) const {
  LinearProgram program;
  const std::uint32_t nodes = network.size();
  program.add_column(0.0, 0.0, 0.0);  // the origin
  for (std::uint32_t n = 1; n < nodes; ++n) program.add_column(1.0, 0.0, std::numeric_limits<double>::infinity());
  // The network repeats a pair of nodes once per fact or variable that
  // orders them: one row per pair, the strongest bound, and none for a
  // lower bound of 0 or less from the origin (the columns have it). A time's
  // lower bound from the origin goes on its column.
  std::vector<TemporalEdge> edges = network.edges();
  std::sort(edges.begin(), edges.end(), [](const TemporalEdge& a, const TemporalEdge& b) {
    return a.from != b.from ? a.from < b.from : a.to != b.to ? a.to < b.to : a.weight > b.weight;
  });
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const TemporalEdge& e = edges[i];
    if (i > 0 && edges[i - 1].from == e.from && edges[i - 1].to == e.to) continue;
    if (e.from == 0) {
      program.column_lower[e.to] = std::max(program.column_lower[e.to], e.weight);
      continue;
    }
    program.rows.push_back({{{e.to, 1.0}, {e.from, -1.0}}, e.weight, std::numeric_limits<double>::infinity()});
  }
  program.rows.insert(program.rows.end(), rows_.begin(), rows_.end());
  return program;
}

std::optional<std::vector<double>> ContinuousSchedule::pushed_schedule(const SimpleTemporalNetwork& network) const {
  constexpr double kTolerance = 1e-9;
  std::vector<double> times = times_;
  times.resize(network.size(), 0.0);
  for (std::uint32_t n = 0; n < network.size(); ++n) times[n] = std::max(times[n], network.earliest(n));
  for (std::uint32_t pass = 0; pass <= network.size(); ++pass) {
    bool changed = false;
    for (const TemporalEdge& e : network.edges()) {
      if (times[e.to] < times[e.from] + e.weight - kTolerance) {
        times[e.to] = times[e.from] + e.weight;
        changed = true;
      }
    }
    if (!changed) return times[0] == 0.0 ? std::optional<std::vector<double>>(std::move(times)) : std::nullopt;
  }
  return std::nullopt;
}

std::vector<std::pair<ActionId, std::vector<NumericVarId>>> ContinuousSchedule::failing_at_end(
    const SimpleTemporalNetwork& network) const {
  std::vector<std::pair<ActionId, std::vector<NumericVarId>>> failing;
  auto end_rows = [&](const Running& r) {
    std::vector<LinearRow> rows;
    const SnapNodes own{SnapKind::End, r.action, r.end_node, r.start_node, r.end_node};
    for (const LinearCondition& c : r.invariants) rows.push_back(row_for(c, r.end_node, own));
    return rows;
  };
  // Every end at once first: feasible together, each is feasible alone, and
  // that is the common case (one program instead of one per action).
  std::vector<LinearRow> all;
  for (const Running& r : running_) {
    const std::vector<LinearRow> rows = end_rows(r);
    all.insert(all.end(), rows.begin(), rows.end());
  }
  if (all.empty() || feasible_with(all, network)) return failing;
  for (const Running& r : running_) {
    if (r.invariants.empty() || feasible_with(end_rows(r), network)) continue;
    std::vector<NumericVarId> read;
    for (const LinearCondition& c : r.invariants) {
      for (const auto& [v, coefficient] : c.form.terms) read.push_back(v);
    }
    std::sort(read.begin(), read.end());
    read.erase(std::unique(read.begin(), read.end()), read.end());
    failing.emplace_back(r.action, std::move(read));
  }
  return failing;
}

bool ContinuousSchedule::feasible_with(const std::vector<LinearRow>& extra, const SimpleTemporalNetwork& network) const {
  // The current schedule meets every row so far; if it meets the extra ones
  // too, no program is needed.
  if (times_.size() == network.size() && rows_satisfied(extra, times_)) return true;
  LinearProgram lp = program(network);
  lp.rows.insert(lp.rows.end(), extra.begin(), extra.end());
  std::fill(lp.objective.begin(), lp.objective.end(), 0.0);  // feasibility only
  return solve_program(lp).status == LinearSolution::Status::Optimal;
}

bool ContinuousSchedule::rows_satisfied(const std::vector<LinearRow>& rows, const std::vector<double>& times) {
  constexpr double kTolerance = 1e-9;
  for (const LinearRow& row : rows) {
    double x = 0.0;
    for (const auto& [n, c] : row.coefficients) x += c * times[n];
    if (x < row.lower - kTolerance || x > row.upper + kTolerance) return false;
  }
  return true;
}

bool ContinuousSchedule::satisfied_by(const std::vector<double>& times) const { return rows_satisfied(rows_, times); }

double ContinuousSchedule::value_at(NumericVarId v, std::uint32_t node) const {
  const Affine a = at(v, node);
  double x = a.constant;
  for (const auto& [n, c] : a.terms) x += c * times_[n];
  return x;
}

}  // namespace alplan
