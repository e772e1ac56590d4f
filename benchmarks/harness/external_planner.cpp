#include "benchmarks/harness/external_planner.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <utility>

namespace alplan::bench {

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

// One pass over the template, so that a path holding "{problem}" is left as it is.
std::string external_command(const ExternalPlanner& planner, const std::string& domain, const std::string& problem,
                             const std::string& plan) {
  const std::pair<const char*, const std::string*> fields[] = {{"{domain}", &domain}, {"{problem}", &problem}, {"{plan}", &plan}};
  std::string command;
  const std::string& t = planner.command;
  for (std::size_t i = 0; i < t.size();) {
    bool replaced = false;
    for (const auto& [placeholder, value] : fields) {
      if (t.compare(i, std::char_traits<char>::length(placeholder), placeholder) == 0) {
        command += shell_quoted(*value);
        i += std::char_traits<char>::length(placeholder);
        replaced = true;
        break;
      }
    }
    if (!replaced) command += t[i++];
  }
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
  // An anytime planner is often stopped by the clock with its plan written:
  // that plan counts. A planner that runs out of memory ends in its own
  // way; only the clock is ours to tell apart.
  if (!wrote_plan) {
    run.status = r.timed_out ? "limit" : "unsolved";
    if (!r.timed_out) run.message = "exit " + std::to_string(r.exit_code) + ": " + r.err.substr(0, 300);
    return run;
  }
  const RunResult v = run_process({alplan, "validate", "--json", problem.domain_file, problem.problem_file, plan_file},
                                  {600, 4096});
  const nlohmann::json j = nlohmann::json::parse(v.out, nullptr, false);
  const bool valid = v.exit_code == 0 && j.is_object() && j.value("valid", false);
  if (valid && j.contains("value") && j["value"].is_number()) {
    run.status = "solved";
    run.value = j["value"].get<double>();
  } else {
    run.status = v.timed_out ? "unvalidated" : "invalid";
    run.message = v.timed_out ? "our validator took over 600 s" : (v.out + v.err).substr(0, 300);
  }
  return run;
}

}  // namespace alplan::bench
