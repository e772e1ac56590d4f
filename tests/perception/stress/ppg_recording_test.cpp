#include <catch2/catch.hpp>

#include <filesystem>
#include <sstream>
#include <string>

#include "perception/stress/ppg_recording.h"
#include "perception/stress/ppg_simulator.h"

using namespace alplan::perception;

namespace {

PpgRecording read(const std::string& text) {
  std::istringstream in(text);
  return read_ppg_csv(in, "rec.csv");
}

std::string error_of(const std::string& text) {
  try {
    read(text);
  } catch (const PpgCsvError& error) {
    return error.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("a CSV recording is read with or without labels") {
  const PpgRecording plain = read("time,ppg\n0,1.5\n0.01,-2e-3\r\n\n0.02 , 3\n");
  REQUIRE(plain.size() == 3);
  CHECK_FALSE(plain.has_labels());
  CHECK(plain.time_s[1] == 0.01);
  CHECK(plain.ppg[1] == -2e-3);
  CHECK(plain.ppg[2] == 3.0);
  CHECK(plain.sample_rate_hz() == Approx(100.0));

  const PpgRecording labelled = read("time,ppg,label\n0,1,0\n0.5,2,1\n");
  REQUIRE(labelled.has_labels());
  CHECK(labelled.label == std::vector<int>{0, 1});
}

TEST_CASE("a simulated recording survives a CSV round trip exactly") {
  PpgSimulator simulator(3);
  RecordingConditions conditions;
  conditions.duration_s = 5.0;
  conditions.sample_rate_hz = 64.0;
  PpgRecording original = simulator.simulate({}, conditions).recording;
  original.label.assign(original.size(), 1);

  const auto path = std::filesystem::temp_directory_path() / "alplan_ppg_round_trip.csv";
  write_ppg_csv_file(path, original);
  const PpgRecording copy = read_ppg_csv_file(path);
  std::filesystem::remove(path);
  CHECK(copy.time_s == original.time_s);
  CHECK(copy.ppg == original.ppg);
  CHECK(copy.label == original.label);
}

TEST_CASE("bad CSV input is reported with its line and column") {
  CHECK(error_of("") == "rec.csv:1:1: error: empty input: expected the header 'time,ppg' or 'time,ppg,label'");
  CHECK(error_of("t,ppg\n0,1\n") ==
        "rec.csv:1:1: error: expected the header 'time,ppg' or 'time,ppg,label', found 't,ppg'");
  CHECK(error_of("time,ppg\n0,1\n0.01,abc\n") ==
        "rec.csv:3:6: error: column 2 (ppg): 'abc' is not a finite number");
  CHECK(error_of("time,ppg\n0,1\n0.01,\n") == "rec.csv:3:6: error: column 2 (ppg): '' is not a finite number");
  CHECK(error_of("time,ppg\nnan,1\n") == "rec.csv:2:1: error: column 1 (time): 'nan' is not a finite number");
  CHECK(error_of("time,ppg\n0,1\n0.01,2,3\n") ==
        "rec.csv:3:8: error: expected 2 columns (time,ppg), found 3");
  CHECK(error_of("time,ppg,label\n0,1\n") ==
        "rec.csv:2:4: error: expected 3 columns (time,ppg,label), found 2");
  CHECK(error_of("time,ppg,label\n0,1,stressed\n") ==
        "rec.csv:2:5: error: column 3 (label): 'stressed' is not an integer");
  CHECK(error_of("time,ppg\n0,1\n0.02,1\n0.01,1\n") ==
        "rec.csv:4:1: error: column 1 (time): 0.01 is not after the previous sample's time");
  CHECK(error_of("time,ppg\n0,1\n0,1\n") ==
        "rec.csv:3:1: error: column 1 (time): 0 is not after the previous sample's time");
}

TEST_CASE("the error carries the line and column for tools") {
  std::istringstream in("time,ppg\n0,1\n1, x\n");
  try {
    read_ppg_csv(in);
    FAIL("no error");
  } catch (const PpgCsvError& error) {
    CHECK(error.line() == 3);
    CHECK(error.column() == 4);
    CHECK(std::string(error.what()).rfind("<input>:3:4:", 0) == 0);
  }
}

TEST_CASE("writing columns of different lengths is refused") {
  PpgRecording recording;
  recording.time_s = {0.0, 0.1};
  recording.ppg = {1.0};
  std::ostringstream out;
  CHECK_THROWS_AS(write_ppg_csv(out, recording), std::invalid_argument);
  CHECK_THROWS_AS(read_ppg_csv_file("/nonexistent/alplan.csv"), std::runtime_error);
}
