// alplan parse DOMAIN [PROBLEM] [--print] [--json]
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "cli/task_files.h"
#include "pddl_parser/summary.h"
#include "pddl_parser/writer.h"

namespace alplan::cli {
namespace {

struct ParseOptions {
  std::string domain;
  std::string problem;
  bool print = false;
  bool json = false;
  bool quiet = false;
};

nlohmann::json to_json(const pddl::Summary& s) {
  nlohmann::json j;
  j["domain"] = {{"name", s.domain_name},
                 {"requirements", s.requirements},
                 {"types", s.types},
                 {"constants", s.constants},
                 {"predicates", s.predicates},
                 {"functions", s.functions},
                 {"actions", s.actions},
                 {"durative_actions", s.durative_actions},
                 {"derived_predicates", s.derived_predicates}};
  if (s.has_problem) {
    j["problem"] = {{"name", s.problem_name},
                    {"objects", s.objects},
                    {"init_facts", s.init_facts},
                    {"numeric_facts", s.numeric_facts},
                    {"timed_initial_literals", s.timed_literals},
                    {"goal_size", s.goal_size},
                    {"metric", s.metric.empty() ? nlohmann::json() : nlohmann::json(s.metric)}};
  }
  return j;
}

void print_summary(const pddl::Summary& s, std::ostream& out) {
  out << "domain: " << s.domain_name << "\nrequirements:";
  for (const std::string& r : s.requirements) out << ' ' << r;
  out << "\ntypes: " << s.types << "  constants: " << s.constants << "  predicates: " << s.predicates
      << "  functions: " << s.functions << "\nactions: " << s.actions
      << "  durative actions: " << s.durative_actions << "  derived predicates: " << s.derived_predicates
      << '\n';
  if (!s.has_problem) return;
  out << "problem: " << s.problem_name << "\nobjects: " << s.objects << "  init facts: " << s.init_facts
      << "  numeric facts: " << s.numeric_facts << "  timed initial literals: " << s.timed_literals
      << "\ngoal size: " << s.goal_size << "  metric: " << (s.metric.empty() ? "none" : s.metric) << '\n';
}

int run(const ParseOptions& options) {
  const auto task = load_task_files(options.domain, options.problem, std::cerr, {!options.quiet});
  if (!task) return kExitInputError;
  if (options.print) {
    std::cout << pddl::write_domain(*task->domain);
    if (task->problem) std::cout << '\n' << pddl::write_problem(*task->problem);
    return kExitOk;
  }
  const pddl::Summary summary = pddl::summarize(*task->domain, task->problem.get());
  if (options.json) {
    std::cout << to_json(summary).dump(2) << '\n';
  } else {
    print_summary(summary, std::cout);
  }
  return kExitOk;
}

}  // namespace

void add_parse_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<ParseOptions>();
  CLI::App* cmd = app.add_subcommand("parse", "Parse and check a PDDL domain and problem; print a summary");
  cmd->add_option("DOMAIN", options->domain, "Domain file")->required();
  cmd->add_option("PROBLEM", options->problem, "Problem file");
  cmd->add_flag("--print", options->print, "Write the files back as canonical PDDL");
  cmd->add_flag("--json", options->json, "Write the summary as JSON");
  cmd->add_flag("-q,--quiet", options->quiet, "Do not print warnings");
  cmd->callback([options, &exit_code] { exit_code = run(*options); });
}

}  // namespace alplan::cli
