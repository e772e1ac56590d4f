#include "benchmarks/harness/table.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace alplan::bench {

std::string fixed(double value, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  return buffer;
}

void Table::print(std::ostream& out) const {
  std::vector<std::size_t> width(header_.size(), 0);
  for (std::size_t c = 0; c < header_.size(); ++c) width[c] = header_[c].size();
  for (const auto& row : rows_) {
    for (std::size_t c = 0; c < row.size() && c < width.size(); ++c) width[c] = std::max(width[c], row[c].size());
  }
  auto line = [&](const std::vector<std::string>& cells) {
    for (std::size_t c = 0; c < header_.size(); ++c) {
      const std::string cell = c < cells.size() ? cells[c] : "";
      out << cell << std::string(width[c] - cell.size() + (c + 1 < header_.size() ? 2 : 0), ' ');
    }
    out << '\n';
  };
  line(header_);
  for (const auto& row : rows_) line(row);
}

void Table::print_markdown(std::ostream& out) const {
  auto line = [&](const std::vector<std::string>& cells) {
    out << '|';
    for (std::size_t c = 0; c < header_.size(); ++c) out << ' ' << (c < cells.size() ? cells[c] : "") << " |";
    out << '\n';
  };
  line(header_);
  out << '|';
  for (std::size_t c = 0; c < header_.size(); ++c) out << "---|";
  out << '\n';
  for (const auto& row : rows_) line(row);
}

void Table::write_csv(std::ostream& out) const {
  auto line = [&](const std::vector<std::string>& cells) {
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const bool quote = cells[c].find_first_of(",\"\n") != std::string::npos;
      if (c) out << ',';
      if (!quote) {
        out << cells[c];
        continue;
      }
      out << '"';
      for (char ch : cells[c]) out << (ch == '"' ? "\"\"" : std::string(1, ch));
      out << '"';
    }
    out << '\n';
  };
  line(header_);
  for (const auto& row : rows_) line(row);
}

std::vector<std::string> csv_cells(const std::string& text) {
  // A file written on Windows (quality_ref.csv is) ends its lines "\r\n".
  const std::string line = !text.empty() && text.back() == '\r' ? text.substr(0, text.size() - 1) : text;
  std::vector<std::string> cells;
  std::stringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

std::optional<double> csv_number(const std::string& cell) {
  if (cell.empty()) return std::nullopt;
  try {
    std::size_t used = 0;
    const double v = std::stod(cell, &used);
    if (used != cell.size() || !std::isfinite(v)) return std::nullopt;
    return v;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

}  // namespace alplan::bench
