// alplan ground DOMAIN PROBLEM [--dump] [--json]
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "cli/task_files.h"
#include "planner/ground_printer.h"
#include "planner/grounder.h"

namespace alplan::cli {
namespace {

struct GroundOptions {
  std::string domain;
  std::string problem;
  bool dump = false;
  bool json = false;
};

int run(const GroundOptions& options) {
  const auto files = load_task_files(options.domain, options.problem, std::cerr, {false});
  if (!files) return kExitInputError;
  std::shared_ptr<const GroundTask> task;
  try {
    task = ground(*files->domain, *files->problem, {{options.domain, options.problem, {}}, std::nullopt});
  } catch (const GroundingError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kExitInputError;
  }
  for (const std::string& m : task->lifted->unsupported) std::cerr << m << " (warning)\n";
  if (options.dump) {
    dump(*task, std::cout);
    return kExitOk;
  }
  const auto durative = std::count_if(task->actions.begin(), task->actions.end(),
                                      [](const GroundAction& a) { return a.durative; });
  const GroundingTimes& t = task->times;
  const double total = t.normalize + t.reachability + t.instantiate + t.axioms;
  if (options.json) {
    nlohmann::json j = {{"facts", task->facts.size()},
                        {"numeric_variables", task->numeric.size()},
                        {"actions", task->actions.size()},
                        {"durative_actions", durative},
                        {"axioms", task->axioms.size()},
                        {"axiom_strata", task->strata},
                        {"timed_initial_literals", task->timed_literals.size()},
                        {"seconds", {{"normalize", t.normalize},
                                     {"reachability", t.reachability},
                                     {"instantiate", t.instantiate},
                                     {"axioms", t.axioms},
                                     {"total", total}}}};
    std::cout << j.dump(2) << "\n";
    return kExitOk;
  }
  std::cout << "facts: " << task->facts.size() << "  numeric variables: " << task->numeric.size()
            << "\nactions: " << task->actions.size() << " (" << durative << " durative, "
            << task->actions.size() - static_cast<std::size_t>(durative) << " instantaneous)"
            << "\naxioms: " << task->axioms.size() << " in " << task->strata << " strata"
            << "\ntimed initial literals: " << task->timed_literals.size() << "\ntime: normalize " << t.normalize
            << " s, reachability " << t.reachability << " s, instantiate " << t.instantiate << " s, axioms "
            << t.axioms << " s, total " << total << " s\n";
  return kExitOk;
}

}  // namespace

void add_ground_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<GroundOptions>();
  CLI::App* cmd = app.add_subcommand("ground", "Ground a task; print its sizes and the time of each pass");
  cmd->add_option("DOMAIN", options->domain, "Domain file")->required();
  cmd->add_option("PROBLEM", options->problem, "Problem file")->required();
  cmd->add_flag("--dump", options->dump, "Print the grounded task readably");
  cmd->add_flag("--json", options->json, "Print the sizes and times as JSON");
  cmd->callback([options, &exit_code] { exit_code = run(*options); });
}

}  // namespace alplan::cli
