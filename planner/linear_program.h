// A linear program solved with CoinOR CLP (the LP solver COLIN and OPTIC
// use): minimise c.x subject to lo <= A.x <= hi row by row and column
// bounds. Small and rebuilt per question; nothing of CLP leaks out.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

namespace alplan {

struct LinearRow {
  std::vector<std::pair<std::uint32_t, double>> coefficients;  // column, coefficient
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
};

struct LinearProgram {
  std::vector<double> objective;  // one per column
  std::vector<double> column_lower, column_upper;
  std::vector<LinearRow> rows;

  std::uint32_t add_column(double cost, double lower, double upper) {
    objective.push_back(cost);
    column_lower.push_back(lower);
    column_upper.push_back(upper);
    return static_cast<std::uint32_t>(objective.size() - 1);
  }
};

struct LinearSolution {
  enum class Status { Optimal, Infeasible, Unbounded };
  Status status = Status::Infeasible;  // a solver that gives up counts as infeasible
  std::vector<double> values;           // Optimal: one per column
  double objective = 0.0;
};

LinearSolution solve_program(const LinearProgram& program);

// The optimal values of the columns, or nullopt when there are none.
std::optional<std::vector<double>> solve(const LinearProgram& program);

}  // namespace alplan
