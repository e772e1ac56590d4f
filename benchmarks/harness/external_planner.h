// Other planners beside ours in `bench planners`, as Downward Lab runs them:
// each by its own command line, one process per problem under the same time
// and memory limits as ours, its plan judged by our validator (`alplan
// validate --json`, a separate process). So a user compares OPTIC, POPF or a
// planner of their own with alplan on their suite without a baseline file.
//
// A planner is given as NAME=COMMAND; COMMAND runs under /bin/sh with
// {domain}, {problem} and {plan} replaced by the files' paths, quoted for
// the shell (so the placeholders are written without quotes), and must
// write one plan, in the IPC format, to {plan}: an anytime planner that
// prints each improvement must keep only its last there. A plan written
// before the time limit stopped the planner counts. What it prints is kept
// only for the message of a failed run.
#pragma once

#include <string>

#include "benchmarks/harness/process_runner.h"
#include "benchmarks/harness/suite.h"

namespace alplan::bench {

struct ExternalPlanner {
  std::string name;     // a column of the tables: letters, digits, '-', '_'
  std::string command;  // with {domain}, {problem}, {plan}
};

// NAME=COMMAND, or std::invalid_argument saying what is wrong with it.
ExternalPlanner parse_external_planner(const std::string& spec);

// The command with its placeholders replaced by the quoted paths.
std::string external_command(const ExternalPlanner& planner, const std::string& domain, const std::string& problem,
                             const std::string& plan);

struct ExternalRun {
  // solved (a plan our validator accepts), invalid (a plan it rejects),
  // limit (stopped at the time limit with no plan), unsolved (ended with no
  // plan), unvalidated (our validator did not finish within 600 s).
  std::string status;
  double seconds = 0.0;  // wall time of the process
  long max_rss_kib = 0;
  double value = 0.0;    // the validator's value (VAL's), when solved
  std::string message;
};

// Runs the planner on one problem; `alplan` is our executable, for validating.
ExternalRun run_external_planner(const ExternalPlanner& planner, const SuiteProblem& problem,
                                 const std::string& plan_file, const RunLimits& limits, const std::string& alplan);

}  // namespace alplan::bench
