// A confusion matrix in the form of the paper's Tables 1-4: rows are the real
// classes, columns the predicted ones, cells the percentage of the row's
// samples; with accuracy and per-class precision and recall.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace alplan::perception {

class ConfusionMatrix {
 public:
  explicit ConfusionMatrix(std::vector<std::string> classes);

  void add(std::size_t real, std::size_t predicted, std::size_t count = 1);
  void add(const ConfusionMatrix& other);  // same classes

  const std::vector<std::string>& classes() const { return classes_; }
  std::size_t count(std::size_t real, std::size_t predicted) const;
  std::size_t total() const;
  std::size_t row_total(std::size_t real) const;
  // Percentage of the real class's samples predicted as `predicted` (a
  // cell of the paper's tables); 0 for an empty row.
  double row_percent(std::size_t real, std::size_t predicted) const;

  double accuracy() const;
  double precision(std::size_t c) const;  // 0 when nothing was predicted as c
  double recall(std::size_t c) const;     // 0 for an empty row
  double macro_precision() const;
  double macro_recall() const;

  // The table as Markdown, rows "Real", columns "Predicted", one decimal.
  std::string markdown() const;
  nlohmann::json json() const;

 private:
  std::vector<std::string> classes_;
  std::vector<std::size_t> cells_;  // row-major, real x predicted
};

}  // namespace alplan::perception
