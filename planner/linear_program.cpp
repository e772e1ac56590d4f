#include "planner/linear_program.h"

#include <ClpSimplex.hpp>
#include <CoinPackedMatrix.hpp>

#include <cmath>
#include <utility>

namespace alplan {
namespace {

double finite(double x) {
  if (x == std::numeric_limits<double>::infinity()) return COIN_DBL_MAX;
  if (x == -std::numeric_limits<double>::infinity()) return -COIN_DBL_MAX;
  return x;
}

}  // namespace

std::optional<std::vector<double>> solve(const LinearProgram& program) {
  LinearSolution s = solve_program(program);
  if (s.status != LinearSolution::Status::Optimal) return std::nullopt;
  return std::move(s.values);
}

LinearSolution solve_program(const LinearProgram& program) {
  const auto columns = static_cast<int>(program.objective.size());
  std::vector<int> row_index, column_index;
  std::vector<double> elements;
  std::vector<double> row_lower, row_upper;
  for (std::size_t r = 0; r < program.rows.size(); ++r) {
    for (const auto& [column, value] : program.rows[r].coefficients) {
      if (value == 0.0) continue;
      row_index.push_back(static_cast<int>(r));
      column_index.push_back(static_cast<int>(column));
      elements.push_back(value);
    }
    row_lower.push_back(finite(program.rows[r].lower));
    row_upper.push_back(finite(program.rows[r].upper));
  }
  std::vector<double> column_lower, column_upper;
  for (int c = 0; c < columns; ++c) {
    column_lower.push_back(finite(program.column_lower[c]));
    column_upper.push_back(finite(program.column_upper[c]));
  }
  CoinPackedMatrix matrix(true, row_index.data(), column_index.data(), elements.data(),
                          static_cast<CoinBigIndex>(elements.size()));
  // The matrix is sized by its largest indices; empty trailing rows or
  // columns must still exist.
  matrix.setDimensions(static_cast<int>(program.rows.size()), columns);
  ClpSimplex model;
  model.setLogLevel(0);
  model.loadProblem(matrix, column_lower.data(), column_upper.data(), program.objective.data(), row_lower.data(),
                    row_upper.data());
  model.dual();
  LinearSolution solution;
  if (model.isProvenOptimal()) {
    const double* x = model.primalColumnSolution();
    solution.status = LinearSolution::Status::Optimal;
    solution.values.assign(x, x + columns);
    solution.objective = model.objectiveValue();
  } else if (model.isProvenDualInfeasible()) {
    solution.status = LinearSolution::Status::Unbounded;
  }
  return solution;
}

}  // namespace alplan
