#include "benchmarks/harness/external_planner.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <stdexcept>


namespace alplan::bench {
namespace {

// 'path' with every ' closed, escaped and reopened: safe inside /bin/sh.
std::string shell_quoted(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

void replace_all(std::string& text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
}

}  // namespace

ExternalPlanner parse_external_planner(const std::string& spec) {
  const std::size_t eq = spec.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw std::invalid_argument("--planner takes NAME=COMMAND, e.g. optic='optic-clp {domain} {problem} > {plan}'; got '" +
                                spec + "'");
  }
  ExternalPlanner planner{spec.substr(0, eq), spec.substr(eq + 1)};
  const bool name_ok = std::all_of(planner.name.begin(), planner.name.end(), [](unsigned char c) {
    return std::isalnum(c) || c == '-' || c == '_';
  });
  if (!name_ok) throw std::invalid_argument("--planner " + planner.name + ": a name is letters, digits, '-' and '_'");
  if (planner.name == "ours") throw std::invalid_argument("--planner: 'ours' names alplan's own column");
  for (const char* placeholder : {"{domain}", "{problem}", "{plan}"}) {
    if (planner.command.find(placeholder) == std::string::npos) {
      throw std::invalid_argument("--planner " + planner.name + ": the command has no " + placeholder +
                                  " (the planner must read {domain} and {problem} and write its plan to {plan})");
    }
  }
  return planner;
}

std::string external_command(const ExternalPlanner& planner, const std::string& domain, const std::string& problem,
                             const std::string& plan) {
  std::string command = planner.command;
  replace_all(command, "{domain}", shell_quoted(domain));
  replace_all(command, "{problem}", shell_quoted(problem));
  replace_all(command, "{plan}", shell_quoted(plan));
  return command;
}

ExternalRun run_external_planner(const ExternalPlanner& planner, const SuiteProblem& problem,
                                 const std::string& plan_file, const RunLimits& limits, const std::string& alplan) {
  std::filesystem::remove(plan_file);
  const RunResult r = run_process(
      {"/bin/sh", "-c", external_command(planner, problem.domain_file, problem.problem_file, plan_file)}, limits);
  ExternalRun run;
  run.seconds = r.wall_seconds;
  run.max_rss_kib = r.max_rss_kib;
  const bool wrote_plan = std::filesystem::exists(plan_file) && std::filesystem::file_size(plan_file) > 0;
  // A planner that runs out of memory ends in its own way; only the clock is
  // ours to tell apart.
  if (r.timed_out) {
    run.status = "limit";
    return run;
  }
  if (!wrote_plan) {
    run.status = "unsolved";
    run.message = "exit " + std::to_string(r.exit_code) + ": " + r.err.substr(0, 300);
    return run;
  }
  const RunResult v = run_process({alplan, "validate", "--json", problem.domain_file, problem.problem_file, plan_file},
                                  {60, 4096});
  const nlohmann::json j = nlohmann::json::parse(v.out, nullptr, false);
  if (v.exit_code == 0 && j.is_object() && j.value("valid", false)) {
    run.status = "solved";
    run.value = j.at("value").get<double>();
  } else {
    run.status = "invalid";
    run.message = (v.out + v.err).substr(0, 300);
  }
  return run;
}

}  // namespace alplan::bench
