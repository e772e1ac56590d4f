// A PPG recording as the stress detector and its tools read and write it:
// sample times, PPG values and, optionally, a per-sample integer label (the
// labelled database uses 0 = unstressed, 1 = stressed).
//
// CSV format: a header naming the columns, then one sample per line:
//
//   time,ppg[,label]
//   0,0.0123
//   0.01,0.0151
//
// time in seconds, strictly increasing; ppg any finite number; label an
// integer. Blank lines are skipped; spaces around fields are allowed; lines
// may end in "\r\n". Any other input is an error that names the source, the
// line and the column: "rec.csv:12:7: error: column 2 (ppg): 'abc' is not a
// number". The writer writes the shortest text that reads back to the same
// doubles, so a round trip is exact.
#pragma once

#include <cstddef>
#include <filesystem>
#include <iosfwd>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace alplan::perception {

struct PpgRecording {
  std::vector<double> time_s;
  std::vector<double> ppg;
  std::vector<int> label;  // empty, or one per sample

  std::size_t size() const { return time_s.size(); }
  bool has_labels() const { return !label.empty(); }
  // (n - 1) / (last time - first time); 0 with fewer than two samples.
  double sample_rate_hz() const;
};

class PpgCsvError : public std::runtime_error {
 public:
  PpgCsvError(const std::string& source, std::size_t line, std::size_t column, const std::string& what);
  std::size_t line() const { return line_; }
  std::size_t column() const { return column_; }  // 1-based character column

 private:
  std::size_t line_;
  std::size_t column_;
};

// `source` names the input in error messages.
PpgRecording read_ppg_csv(std::istream& in, std::string_view source = "<input>");
PpgRecording read_ppg_csv_file(const std::filesystem::path& path);

// Writes the label column when the recording has labels. Throws
// std::invalid_argument when the columns' lengths differ.
void write_ppg_csv(std::ostream& out, const PpgRecording& recording);
void write_ppg_csv_file(const std::filesystem::path& path, const PpgRecording& recording);

}  // namespace alplan::perception
