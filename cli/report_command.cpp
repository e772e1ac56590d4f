// alplan report LOG --out DIR [--vega-dir DIR]
// Writes DIR/index.html, one self-contained page about a run of `alplan
// home`. Exit 0 written, 2 input error (no log, no usable event, no charting
// libraries, an output folder that cannot be written).
#include <CLI/CLI.hpp>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "report/event_log.h"
#include "report/html_page.h"
#include "report/vega_libraries.h"

namespace alplan::cli {
namespace {

struct ReportOptions {
  std::string log;
  std::string out;
  std::string vega_dir = ALPLAN_VEGA_DIR;
};

int run(const ReportOptions& options) {
  const report::ReadResult read = report::read_event_log_file(options.log, std::cerr);
  if (!read.log) {
    std::cerr << read.error << "\n";
    return kExitInputError;
  }
  const report::VegaLibrariesResult libraries = report::load_vega_libraries(options.vega_dir);
  if (!libraries.libraries) {
    std::cerr << libraries.error << "\n";
    return kExitInputError;
  }
  std::error_code ec;
  std::filesystem::create_directories(options.out, ec);
  const std::string page = options.out + "/index.html";
  std::ofstream out(page, std::ios::binary);
  if (ec || !out) {
    std::cerr << page << ": error: cannot write the report"
              << (ec ? " (" + ec.message() + ")" : std::string()) << "\n";
    return kExitInputError;
  }
  out << report::render_report_page(*read.log, std::filesystem::path(options.log).filename().string(),
                                    *libraries.libraries);
  out.close();
  if (!out) {
    std::cerr << page << ": error: writing the report failed\n";
    return kExitInputError;
  }
  std::cout << "report: " << page << "\n";
  return kExitOk;
}

}  // namespace

void add_report_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<ReportOptions>();
  CLI::App* cmd = app.add_subcommand(
      "report", "Write DIR/index.html, a self-contained page of charts about a run from its `alplan home` event log");
  cmd->add_option("LOG", options->log, "The event log (JSON Lines)")->required();
  cmd->add_option("--out", options->out, "Folder for index.html (made if missing)")->required();
  cmd->add_option("--vega-dir", options->vega_dir,
                  "Folder with vega.min.js, vega-lite.min.js and vega-embed.min.js (scripts/fetch_vega)")
      ->capture_default_str();
  cmd->callback([options, &exit_code] { exit_code = run(*options); });
}

}  // namespace alplan::cli
