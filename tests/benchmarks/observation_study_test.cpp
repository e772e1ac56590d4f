#include "benchmarks/harness/observation_study.h"

#include <catch2/catch.hpp>

#include <string>

using namespace alplan::bench;
using alplan::stats::BootstrapOptions;

namespace {

// One run of `home`: comforted after `delay`, or not.
StudyRun run(const std::string& home, int n, const std::string& strategy, const std::string& kind,
             std::optional<double> delay) {
  StudyRun r;
  r.home = home;
  r.run = n;
  r.strategy = strategy;
  r.kind = kind;
  r.comforted = delay.has_value();
  r.delay = delay;
  if (delay) r.cost = 100.0;
  return r;
}

// The table rows under `heading`, up to the next blank line after them.
std::string section(const std::string& markdown, const std::string& heading) {
  const std::size_t at = markdown.find(heading);
  if (at == std::string::npos) return "";
  const std::size_t table = markdown.find("| strategy", at);
  const std::size_t end = markdown.find("\n\n", table);
  return markdown.substr(table, end == std::string::npos ? std::string::npos : end - table);
}

}  // namespace

TEST_CASE("the observation tables pair the same runs across models: full minus iot, iot minus camera") {
  // Six homes, two runs each, one iot failure per run. With the tags the
  // robot is 20 sooner than with the camera alone; seeing everything saves
  // 10 more. The camera alone loses one run of home h0.
  std::map<std::string, std::vector<StudyRun>> by_model;
  for (int h = 0; h < 6; ++h) {
    for (int n = 0; n < 2; ++n) {
      const std::string home = "h" + std::to_string(h);
      const double base = 30.0 + 5.0 * h + n;
      by_model["full"].push_back(run(home, n, "replan", "iot", base));
      by_model["iot"].push_back(run(home, n, "replan", "iot", base + 10.0));
      by_model["camera"].push_back(
          run(home, n, "replan", "iot", h == 0 && n == 0 ? std::nullopt : std::optional<double>(base + 30.0)));
    }
  }
  BootstrapOptions bootstrap;
  bootstrap.resamples = 500;
  const std::string md = observation_tables(by_model, {"replan"}, bootstrap);
  INFO(md);
  CHECK(md.find("## iot (seen: a tagged object") != std::string::npos);
  CHECK(md.find("| replan | 12/12 |") != std::string::npos);
  CHECK(md.find("11/12") != std::string::npos);
  CHECK(md.find("| 0/") == std::string::npos);

  const std::string full_iot = section(md, "full minus iot:\n");
  CHECK(full_iot.find("| replan | comforted | 12 in 6 homes | 0.000 |") != std::string::npos);
  // Every pair differs by exactly -10: the interval cannot leave it.
  CHECK(full_iot.find("| replan | delay | 12 in 6 homes | -10.000 | [-10.000, -10.000] |") != std::string::npos);

  const std::string iot_camera = section(md, "iot minus camera (what the tags are worth):\n");
  // One run more comforted in 12: +1/12; the delay over the 11 runs both comforted.
  CHECK(iot_camera.find("| replan | comforted | 12 in 6 homes | 0.083 |") != std::string::npos);
  CHECK(iot_camera.find("| replan | delay | 11 in 6 homes | -20.000 | [-20.000, -20.000] |") != std::string::npos);
  // Six homes all 20 sooner: the exact Wilcoxon p of six like signs, 2/64.
  // The page's family is four tests (two measures, two model pairs), p
  // 2/64, 2/64, 1, 1: Holm gives 4 x 2/64 = 0.125 to both delays.
  CHECK(iot_camera.find("| 0.0312 | 0.1250 |") != std::string::npos);
  CHECK(full_iot.find("| 0.0312 | 0.1250 |") != std::string::npos);
  CHECK(md.find("Holm-adjusted over every test of this page") != std::string::npos);
}

TEST_CASE("without camera runs there is no tag table, and kinds without runs are left out") {
  std::map<std::string, std::vector<StudyRun>> by_model;
  by_model["full"].push_back(run("h0", 0, "replan", "moves", 10.0));
  by_model["iot"].push_back(run("h0", 0, "replan", "moves", 12.0));
  const std::string md = observation_tables(by_model, {"replan"}, BootstrapOptions{});
  CHECK(md.find("## moves") != std::string::npos);
  CHECK(md.find("## iot (") == std::string::npos);
  CHECK(md.find("full minus iot:\n") != std::string::npos);
  CHECK(md.find("iot minus camera (what") == std::string::npos);
}

TEST_CASE("a model under which no run was comforted shows no mean delay or cost, not zeros") {
  std::map<std::string, std::vector<StudyRun>> by_model;
  by_model["iot"].push_back(run("h0", 0, "replan", "moves", 12.0));
  by_model["camera"].push_back(run("h0", 0, "replan", "moves", std::nullopt));
  const std::string md = observation_tables(by_model, {"replan"}, BootstrapOptions{});
  INFO(md);
  CHECK(md.find("| replan | 1/1 | 12.0 | 100.0 | 0/1 | - | - |") != std::string::npos);
}
