#include "perception/common/confusion_matrix.h"

#include <cstdio>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace alplan::perception {
namespace {

std::string one_decimal(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", value);
  return text;
}

}  // namespace

ConfusionMatrix::ConfusionMatrix(std::vector<std::string> classes)
    : classes_(std::move(classes)), cells_(classes_.size() * classes_.size(), 0) {
  if (classes_.empty()) throw std::invalid_argument("a confusion matrix needs at least one class");
}

void ConfusionMatrix::add(std::size_t real, std::size_t predicted, std::size_t count) {
  if (real >= classes_.size() || predicted >= classes_.size()) {
    throw std::out_of_range("confusion matrix: class index out of range");
  }
  cells_[real * classes_.size() + predicted] += count;
}

void ConfusionMatrix::add(const ConfusionMatrix& other) {
  if (other.classes_ != classes_) throw std::invalid_argument("confusion matrices over different classes");
  for (std::size_t i = 0; i < cells_.size(); ++i) cells_[i] += other.cells_[i];
}

std::size_t ConfusionMatrix::count(std::size_t real, std::size_t predicted) const {
  return cells_.at(real * classes_.size() + predicted);
}

std::size_t ConfusionMatrix::total() const { return std::accumulate(cells_.begin(), cells_.end(), std::size_t{0}); }

std::size_t ConfusionMatrix::row_total(std::size_t real) const {
  std::size_t sum = 0;
  for (std::size_t p = 0; p < classes_.size(); ++p) sum += count(real, p);
  return sum;
}

double ConfusionMatrix::row_percent(std::size_t real, std::size_t predicted) const {
  const std::size_t row = row_total(real);
  return row == 0 ? 0.0 : 100.0 * static_cast<double>(count(real, predicted)) / static_cast<double>(row);
}

double ConfusionMatrix::accuracy() const {
  std::size_t right = 0;
  for (std::size_t c = 0; c < classes_.size(); ++c) right += count(c, c);
  const std::size_t all = total();
  return all == 0 ? 0.0 : static_cast<double>(right) / static_cast<double>(all);
}

double ConfusionMatrix::precision(std::size_t c) const {
  std::size_t predicted = 0;
  for (std::size_t r = 0; r < classes_.size(); ++r) predicted += count(r, c);
  return predicted == 0 ? 0.0 : static_cast<double>(count(c, c)) / static_cast<double>(predicted);
}

double ConfusionMatrix::recall(std::size_t c) const {
  const std::size_t row = row_total(c);
  return row == 0 ? 0.0 : static_cast<double>(count(c, c)) / static_cast<double>(row);
}

double ConfusionMatrix::macro_precision() const {
  double sum = 0;
  for (std::size_t c = 0; c < classes_.size(); ++c) sum += precision(c);
  return sum / static_cast<double>(classes_.size());
}

double ConfusionMatrix::macro_recall() const {
  double sum = 0;
  for (std::size_t c = 0; c < classes_.size(); ++c) sum += recall(c);
  return sum / static_cast<double>(classes_.size());
}

std::string ConfusionMatrix::markdown() const {
  std::ostringstream out;
  out << "| | |";
  for (std::size_t p = 0; p < classes_.size(); ++p) out << (p == 0 ? " Predicted |" : " |");
  out << "\n|---|---|";
  for (std::size_t p = 0; p < classes_.size(); ++p) out << "---|";
  out << "\n| | |";
  for (const std::string& c : classes_) out << " " << c << " |";
  out << "\n";
  for (std::size_t r = 0; r < classes_.size(); ++r) {
    out << "| " << (r == 0 ? "Real" : "") << " | " << classes_[r] << " |";
    for (std::size_t p = 0; p < classes_.size(); ++p) {
      const std::string cell = one_decimal(row_percent(r, p));
      out << " " << (r == p ? "**" + cell + "**" : cell) << " |";
    }
    out << "\n";
  }
  return out.str();
}

nlohmann::json ConfusionMatrix::json() const {
  nlohmann::json rows = nlohmann::json::array();
  for (std::size_t r = 0; r < classes_.size(); ++r) {
    nlohmann::json row = nlohmann::json::array();
    for (std::size_t p = 0; p < classes_.size(); ++p) row.push_back(count(r, p));
    rows.push_back(row);
  }
  nlohmann::json per_class = nlohmann::json::object();
  for (std::size_t c = 0; c < classes_.size(); ++c) {
    per_class[classes_[c]] = {{"precision", precision(c)}, {"recall", recall(c)}, {"samples", row_total(c)}};
  }
  return {{"classes", classes_},        {"counts", rows},
          {"accuracy", accuracy()},     {"macro_precision", macro_precision()},
          {"macro_recall", macro_recall()}, {"per_class", per_class}};
}

}  // namespace alplan::perception
