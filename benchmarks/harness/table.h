// A text table with aligned columns, and the same rows as CSV, for harness
// reports that people read and scripts parse.
#pragma once

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace alplan::bench {

class Table {
 public:
  explicit Table(std::vector<std::string> header) : header_(std::move(header)) {}
  void add(std::vector<std::string> row) { rows_.push_back(std::move(row)); }
  void print(std::ostream& out) const;       // aligned, for the terminal
  void print_markdown(std::ostream& out) const;
  void write_csv(std::ostream& out) const;
  std::size_t size() const { return rows_.size(); }

 private:
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
};

// The cells of one CSV line (no quoting: the harness's files have none); a
// trailing comma is an empty last cell, a trailing carriage return is no part of it.
std::vector<std::string> csv_cells(const std::string& line);

// A CSV cell as a finite number; nullopt for an empty cell or anything else.
std::optional<double> csv_number(const std::string& cell);

// Fixed-point text with `decimals` digits.
std::string fixed(double value, int decimals);

}  // namespace alplan::bench
