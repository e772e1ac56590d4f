#include "benchmarks/harness/repair_study_folder.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "benchmarks/harness/repair_bench.h"
#include "benchmarks/harness/repair_study.h"

namespace alplan::bench {
namespace fs = std::filesystem;

namespace {

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

}  // namespace

void summarise_study_folder(const std::string& model_dir, const stats::BootstrapOptions& bootstrap) {
  const fs::path dir(model_dir);
  const std::vector<StudyRun> runs = load_study_runs((dir / "runs.json").string());
  std::vector<std::string> order;
  for (const StudyRun& r : runs) {
    if (std::find(order.begin(), order.end(), r.strategy) == order.end()) order.push_back(r.strategy);
  }
  if (order.empty()) throw std::runtime_error((dir / "runs.json").string() + ": no runs");
  // As bench repair chose it (repair_bench.cpp, write_outputs).
  const std::string reference = std::find(order.begin(), order.end(), "replan") != order.end() ? "replan" : order.front();
  const StudyAnalysis study = analyse_repair_study(runs, order, reference, bootstrap);

  nlohmann::json summary;
  try {
    summary = nlohmann::json::parse(read_text(dir / "summary.json"));
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error((dir / "summary.json").string() + ": " + e.what());
  }
  for (const char* derived : {"kinds", "wins", "fox2006"}) summary.erase(derived);
  summary.update(study.json);
  write_text(dir / "summary.json", summary.dump(2) + "\n");

  const std::string md = read_text(dir / "summary.md");
  const std::size_t tables = md.find("## Per failure kind and strategy");
  if (tables == std::string::npos) throw std::runtime_error((dir / "summary.md").string() + ": no tables to replace");
  write_text(dir / "summary.md", md.substr(0, tables) + study.markdown);
  fs::create_directories(dir / "plots");
  for (const auto& [file, svg] : study.plots) write_text(dir / "plots" / file, svg);
}

}  // namespace alplan::bench
