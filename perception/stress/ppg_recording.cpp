#include "perception/stress/ppg_recording.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <istream>
#include <ostream>
#include <system_error>

namespace alplan::perception {

double PpgRecording::sample_rate_hz() const {
  if (time_s.size() < 2 || !(time_s.back() > time_s.front())) return 0.0;
  return static_cast<double>(time_s.size() - 1) / (time_s.back() - time_s.front());
}

PpgCsvError::PpgCsvError(const std::string& source, std::size_t line, std::size_t column, const std::string& what)
    : std::runtime_error(source + ":" + std::to_string(line) + ":" + std::to_string(column) + ": error: " + what),
      line_(line),
      column_(column) {}

namespace {

struct Field {
  std::string_view text;  // trimmed
  std::size_t column;     // 1-based, of the field's first character
};

std::vector<Field> split_fields(std::string_view line) {
  std::vector<Field> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    const std::size_t end = comma == std::string_view::npos ? line.size() : comma;
    std::size_t first = start;
    std::size_t last = end;
    while (first < last && (line[first] == ' ' || line[first] == '\t')) ++first;
    while (last > first && (line[last - 1] == ' ' || line[last - 1] == '\t')) --last;
    fields.push_back({line.substr(first, last - first), first + 1});
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

class CsvReader {
 public:
  explicit CsvReader(std::string_view source) : source_(source) {}

  [[noreturn]] void fail(std::size_t line, std::size_t column, const std::string& what) const {
    throw PpgCsvError(source_, line, column, what);
  }

  double number(const Field& field, std::size_t line, std::size_t index, std::string_view name) const {
    double value = 0.0;
    const char* begin = field.text.data();
    const char* end = begin + field.text.size();
    const auto [stop, error] = std::from_chars(begin, end, value);
    if (field.text.empty() || error != std::errc() || stop != end || !std::isfinite(value)) {
      fail(line, field.column,
           "column " + std::to_string(index + 1) + " (" + std::string(name) + "): '" + std::string(field.text) +
               "' is not a finite number");
    }
    return value;
  }

  int integer(const Field& field, std::size_t line, std::size_t index) const {
    int value = 0;
    const char* begin = field.text.data();
    const char* end = begin + field.text.size();
    const auto [stop, error] = std::from_chars(begin, end, value);
    if (field.text.empty() || error != std::errc() || stop != end) {
      fail(line, field.column,
           "column " + std::to_string(index + 1) + " (label): '" + std::string(field.text) + "' is not an integer");
    }
    return value;
  }

  bool header(std::string_view text, std::size_t line) const {
    const std::vector<Field> fields = split_fields(text);
    const bool time_ppg = fields.size() >= 2 && fields[0].text == "time" && fields[1].text == "ppg";
    if (time_ppg && fields.size() == 2) return false;
    if (time_ppg && fields.size() == 3 && fields[2].text == "label") return true;
    fail(line, 1, "expected the header 'time,ppg' or 'time,ppg,label', found '" + std::string(text) + "'");
  }

 private:
  std::string source_;
};

}  // namespace

PpgRecording read_ppg_csv(std::istream& in, std::string_view source) {
  const CsvReader reader(source);
  PpgRecording recording;
  std::string text;
  std::size_t line = 0;
  bool has_header = false;
  bool labelled = false;
  while (std::getline(in, text)) {
    ++line;
    if (!text.empty() && text.back() == '\r') text.pop_back();
    if (text.find_first_not_of(" \t") == std::string::npos) continue;
    if (!has_header) {
      labelled = reader.header(text, line);
      has_header = true;
      continue;
    }
    const std::vector<Field> fields = split_fields(text);
    const std::size_t expected = labelled ? 3 : 2;
    if (fields.size() != expected) {
      const std::size_t column = fields.size() > expected ? fields[expected].column : text.size() + 1;
      reader.fail(line, column,
                  "expected " + std::to_string(expected) + " columns (" + (labelled ? "time,ppg,label" : "time,ppg") +
                      "), found " + std::to_string(fields.size()));
    }
    const double time = reader.number(fields[0], line, 0, "time");
    if (!recording.time_s.empty() && !(time > recording.time_s.back())) {
      reader.fail(line, fields[0].column,
                  "column 1 (time): " + std::string(fields[0].text) + " is not after the previous sample's time");
    }
    recording.time_s.push_back(time);
    recording.ppg.push_back(reader.number(fields[1], line, 1, "ppg"));
    if (labelled) recording.label.push_back(reader.integer(fields[2], line, 2));
  }
  if (in.bad()) reader.fail(line + 1, 1, "read error");
  if (!has_header) reader.fail(1, 1, "empty input: expected the header 'time,ppg' or 'time,ppg,label'");
  return recording;
}

PpgRecording read_ppg_csv_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot open for reading");
  return read_ppg_csv(in, path.string());
}

namespace {

void write_number(std::ostream& out, double value) {
  char buffer[32];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
  if (error != std::errc()) throw std::invalid_argument("write_ppg_csv: cannot format a number");
  out.write(buffer, end - buffer);
}

}  // namespace

void write_ppg_csv(std::ostream& out, const PpgRecording& recording) {
  if (recording.ppg.size() != recording.time_s.size() ||
      (recording.has_labels() && recording.label.size() != recording.time_s.size())) {
    throw std::invalid_argument("write_ppg_csv: the time, ppg and label columns differ in length");
  }
  out << (recording.has_labels() ? "time,ppg,label\n" : "time,ppg\n");
  for (std::size_t i = 0; i < recording.size(); ++i) {
    write_number(out, recording.time_s[i]);
    out << ',';
    write_number(out, recording.ppg[i]);
    if (recording.has_labels()) out << ',' << recording.label[i];
    out << '\n';
  }
}

void write_ppg_csv_file(const std::filesystem::path& path, const PpgRecording& recording) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error(path.string() + ": cannot open for writing");
  write_ppg_csv(out, recording);
  if (!out.flush()) throw std::runtime_error(path.string() + ": write failed");
}

}  // namespace alplan::perception
