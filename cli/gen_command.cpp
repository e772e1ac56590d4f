// alplan gen home --rooms R --seniors S --robots K --objects O --seed N
//                 [--stressed M] [--battery] [--out FILE]
// Writes a generated home as a PDDL problem for the assisted-living domain
// (domains/assisted_living/domain.pddl; with --battery, for its battery
// variant, with a dock and the default batteries as `alplan home --battery`
// gives them). Exit 2 on impossible options.
#include <CLI/CLI.hpp>

#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "domains/battery_home.h"
#include "domains/home_generator.h"
#include "domains/pddl_files.h"
#include "pddl_parser/parser.h"
#include "pddl_parser/writer.h"

namespace alplan::cli {
namespace {

struct GenOptions {
  domains::HomeOptions home;
  bool battery = false;
  std::string out;
};

// The generated problem with what the battery domain needs, through the
// same code `alplan home --battery` uses (domains/battery_home.h); its first
// line, the command that made it, is kept.
std::string with_batteries(const std::string& problem_text) {
  const std::string domain_file = std::string(ALPLAN_ASSISTED_LIVING_DIR) + "/battery/domain.pddl";
  std::string domain_text;
  std::vector<pddl::Diagnostic> io;
  if (!pddl::read_file(domain_file, domain_text, io)) {
    throw std::invalid_argument(domain_file + ": cannot read the battery domain");
  }
  const domains::LoadedFiles files =
      domains::load_pddl_text(domain_text, domain_file, problem_text, "generated-home.pddl");
  pddl::Problem problem = *files.problem;
  domains::add_batteries(problem, {});
  return problem_text.substr(0, problem_text.find('\n') + 1) +
         "; with batteries, for domains/assisted_living/battery/domain.pddl\n" + pddl::write_problem(problem);
}

int run(const GenOptions& o) {
  domains::GeneratedHome home;
  try {
    home = domains::generate_home(o.home);
    if (o.battery) home.problem = with_batteries(home.problem);
  } catch (const std::invalid_argument& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kExitInputError;
  } catch (const domains::InputError& e) {  // the battery domain file
    std::cerr << "error: " << e.what() << "\n";
    return kExitInputError;
  }
  if (o.out.empty()) {
    std::cout << home.problem;
    return kExitOk;
  }
  std::ofstream file(o.out, std::ios::binary);
  if (!(file << home.problem)) {
    std::cerr << "error: cannot write " << o.out << "\n";
    return kExitInputError;
  }
  std::cerr << "wrote " << o.out << ": " << home.rooms.size() << " rooms, " << home.objects.size() << " objects, goal";
  for (const domains::StressedSenior& s : home.stressed) std::cerr << " " << s.goal << " (" << s.emotion << ")";
  std::cerr << "\n";
  return kExitOk;
}

}  // namespace

void add_gen_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<GenOptions>();
  CLI::App* gen = app.add_subcommand("gen", "Generate problems");
  gen->require_subcommand(1);
  CLI::App* home = gen->add_subcommand("home", "An assisted-living home, as a PDDL problem");
  home->add_option("--rooms", options->home.rooms, "Rooms besides corridors (at least 4)");
  home->add_option("--seniors", options->home.seniors, "Seniors");
  home->add_option("--robots", options->home.robots, "Robots");
  home->add_option("--objects", options->home.objects, "Portable objects");
  home->add_option("--stressed", options->home.stressed, "Seniors to comfort (the goals)");
  home->add_option("--seed", options->home.seed, "Random seed (same seed, same home)");
  home->add_option("--iot-share", options->home.iot_share,
                   "Share of the portable objects with an IoT tag (they report place and availability)");
  home->add_option("--scatter", options->home.scatter,
                   "Share of the portable objects left in another room than their type's (0: none, as before)");
  home->add_flag("--battery", options->battery,
                 "For the battery domain (domains/assisted_living/battery/): a dock and the default batteries");
  home->add_option("--out", options->out, "Write the problem here instead of stdout");
  home->callback([options, &exit_code] { exit_code = run(*options); });
}

}  // namespace alplan::cli
