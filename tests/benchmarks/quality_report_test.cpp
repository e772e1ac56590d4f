// The quality report (benchmarks/harness/quality_report.h): scores of first
// and best plans against the best known value, reference files read by
// their columns, the summed score over time.
#include "benchmarks/harness/quality_report.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace alplan::bench;

namespace {

std::string temp_folder(const std::string& name) {
  const std::string dir = (std::filesystem::temp_directory_path() / ("alplan-quality-" + name)).string();
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

std::string read(const std::string& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

const char* const kKey1 = "ipc/ipc-2011/d/instances/instance-1.pddl";
const char* const kKey2 = "ipc/ipc-2011/d/instances/instance-2.pddl";

}  // namespace

TEST_CASE("a reference file gives its value columns, not its times, its problem or its best") {
  const std::string dir = temp_folder("refs");
  // Lines end "\r\n", as quality_ref.csv's do.
  std::ofstream(dir + "/ref.csv") << "domain_file,problem_file,optic_first,optic_first_s,best\r\n"
                                  << "x,../shared/benchmarks/" << kKey1 << ",150,0.4,120\r\n"
                                  << "x," << kKey2 << ",,0.5,\r\n";
  ReferenceValues refs;
  add_reference_file(refs, dir + "/ref.csv");
  CHECK(refs.names == std::vector<std::string>{"optic_first"});
  CHECK(refs.values.at(kKey1).at("optic_first") == 150.0);
  CHECK(refs.best.at(kKey1) == 120.0);
  CHECK(refs.values.count(kKey2) == 0);
  // The same column again, from another file, is named by its file.
  std::ofstream(dir + "/other.csv") << "problem_file,optic_first\n" << kKey2 << ",90\n";
  add_reference_file(refs, dir + "/other.csv");
  CHECK(refs.names == std::vector<std::string>{"optic_first", "other/optic_first"});
  CHECK_THROWS(add_reference_file(refs, dir + "/missing.csv"));
  std::ofstream(dir + "/bad.csv") << "domain,value\n";
  CHECK_THROWS_WITH(add_reference_file(refs, dir + "/bad.csv"), Catch::Contains("no problem_file column"));
}

TEST_CASE("first and best plans are scored against the best known value, over time too") {
  const std::string dir = temp_folder("report");
  ReferenceValues refs;
  refs.names = {"optic"};
  refs.values[kKey1]["optic"] = 100.0;  // the best known on problem 1
  refs.values[kKey2]["optic"] = 80.0;   // worse than our best on problem 2
  const std::vector<QualityRun> runs{
      {"d", kKey1, {{0.05, 200.0}, {3.0, 125.0}}},  // first 0.5, best 0.8
      {"d", kKey2, {{0.5, 64.0}}},                  // best known itself
      {"d", "ipc/ipc-2011/d/instances/instance-3.pddl", {}}};
  QualityReportOptions options;
  options.time_limit = 10.0;
  options.out_dir = dir;
  std::ostringstream out;
  write_quality_report(runs, refs, options, out);
  const std::string md = read(dir + "/quality.md");
  // problems, best known, ours first (0.5 + 1), ours best (0.8 + 1), optic (1 + 0.8)
  CHECK(md.find("| d | 3 | 2 | 1.50 | 1.80 | 1.80 |") != std::string::npos);
  const std::string csv = read(dir + "/quality.csv");
  CHECK(csv.find("instance-1.pddl,200.000,0.05,125.000,3.00,2,100.000,0.500,0.800,100.000,1.000") != std::string::npos);
  CHECK(csv.find("instance-3.pddl,,,,,0,,0.000,0.000,,") != std::string::npos);
  // Over time: nothing before 0.05 s; problem 1's first plan from 0.05 s,
  // problem 2's from 0.5 s, problem 1's better plan from 3 s (read at 5 s).
  const std::string over_time = read(dir + "/quality_over_time.csv");
  CHECK(over_time.find("0.02,0.000,1.800") != std::string::npos);
  CHECK(over_time.find("0.05,0.500,1.800") != std::string::npos);
  CHECK(over_time.find("0.5,1.500,1.800") != std::string::npos);
  CHECK(over_time.find("5,1.800,1.800") != std::string::npos);
  CHECK(over_time.find("10,1.800,1.800") != std::string::npos);
  CHECK(read(dir + "/quality_over_time.svg").find("<polyline") != std::string::npos);
}

TEST_CASE("a maximised metric is scored ours / best") {
  ReferenceValues refs;
  refs.names = {"r"};
  refs.values[kKey1]["r"] = 50.0;
  QualityReportOptions options;
  options.maximized = [](const std::string&) { return true; };
  std::ostringstream out;
  write_quality_report({{"d", kKey1, {{1.0, 40.0}}}}, refs, options, out);
  // best known 50 (the reference): ours 40 / 50.
  CHECK(out.str().find("0.80") != std::string::npos);
}

TEST_CASE("the time grid runs 1-2-5 up to the limit") {
  const std::vector<double> grid = quality_time_grid(1.0);
  const std::vector<double> expected{0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1.0};
  REQUIRE(grid.size() == expected.size());
  for (std::size_t i = 0; i < grid.size(); ++i) CHECK(grid[i] == Approx(expected[i]));
  CHECK(quality_time_grid(60.0).back() == 60.0);
}
