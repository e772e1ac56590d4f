// alplan validate DOMAIN PROBLEM PLAN [-t|--epsilon E] [-v] [--json]
// Exit 0 valid, 1 invalid, 2 input error. Takes VAL's -t and -v, so that it
// can stand in for VAL's Validate in scripts; any one of the three files may
// be "-", standard input.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include "cli/commands.h"
#include "cli/task_files.h"
#include "oracle/judge.h"
#include "oracle/load.h"
#include "pddl_parser/parser.h"
#include "pddl_parser/writer.h"
#include "planner/normalize.h"
#include "planner/validation_trace.h"
#include "planner/validator.h"

namespace alplan::cli {
namespace {

struct ValidateOptions {
  std::string domain;
  std::string problem;
  std::string plan;
  double epsilon = 0.001;
  bool json = false;
  bool val_total_time = false;
  bool reference = false;
  bool exact = false;
  bool verbose = false;
};

// The reference semantics (oracle/), which shares no code with the planner
// or its validator: a second opinion on a plan.
int run_reference(const ValidateOptions& options) {
  if (options.domain == pddl::kStandardInput || options.problem == pddl::kStandardInput) {
    std::cerr << "-: error: --reference reads the domain and the problem from files, not standard input\n";
    return kExitInputError;
  }
  const oracle::LoadedTask task = oracle::load_task_files(options.domain, options.problem);
  if (!task.ok()) {
    std::cerr << task.error;
    return kExitInputError;
  }
  std::vector<pddl::Diagnostic> io;
  std::string text;
  if (!pddl::read_input(options.plan, text, io)) {
    std::cerr << io.front().to_string() << "\n";
    return kExitInputError;
  }
  const oracle::TimedPlanRead plan = oracle::read_timed_plan(text);
  if (!plan.ok()) {
    std::cerr << options.plan << ": " << plan.error << "\n";
    return kExitInputError;
  }
  oracle::JudgeOptions judge_options;
  judge_options.tolerance = options.epsilon;
  judge_options.exact = options.exact;
  const oracle::Verdict verdict = oracle::Judge(task.domain, task.problem, judge_options).judge(plan.plan);
  if (options.json) {
    nlohmann::json j = {{"valid", verdict.valid()}, {"judged", verdict.judged()}, {"semantics", "reference"}};
    if (verdict.valid()) {
      j["makespan"] = verdict.makespan;
      j["value"] = verdict.value;
      if (!verdict.preference_violations.empty()) j["preference_violations"] = verdict.preference_violations;
    } else {
      j["failure"] = oracle::to_string(verdict.failure);
      j["time"] = verdict.time;
      j["reason"] = verdict.reason;
    }
    std::cout << j.dump(2) << "\n";
  } else if (verdict.valid()) {
    std::cout << "Plan valid (reference semantics). Makespan: " << pddl::format_number(verdict.makespan)
              << ". Value: " << pddl::format_number(verdict.value) << ".\n";
  } else if (!verdict.judged()) {
    std::cout << "Plan not judged (reference semantics): " << verdict.reason << "\n";
    return kExitInputError;
  } else {
    std::cout << "Plan invalid (reference semantics, " << oracle::to_string(verdict.failure) << "). " << verdict.reason
              << "\n";
  }
  return verdict.valid() ? kExitOk : kExitInvalid;
}

nlohmann::json to_json(const Violation& v) {
  nlohmann::json j = {{"kind", to_string(v.kind)}, {"time", v.time},           {"action", v.action},
                      {"condition", v.condition}, {"message", v.message()}};
  if (v.kind == Violation::Kind::UnsatisfiedInvariant) j["until"] = v.until;
  if (!v.other_action.empty()) j["other_action"] = v.other_action;
  if (v.line) j["plan_line"] = v.line;
  return j;
}

// Standard input can be read once: two "-" would hand the second file an
// empty text and a baffling parse error.
bool one_standard_input(const ValidateOptions& options) {
  const int count = (options.domain == pddl::kStandardInput) + (options.problem == pddl::kStandardInput) +
                    (options.plan == pddl::kStandardInput);
  if (count <= 1) return true;
  std::cerr << "-: error: standard input ('-') is given for more than one file; it can be read once\n";
  return false;
}

void print_json(const ValidationResult& result) {
  nlohmann::json j = {{"status", result.valid ? "valid" : "invalid"}, {"valid", result.valid},
                      {"happenings", result.happenings}};
  if (result.valid) {
    j["makespan"] = result.makespan;
    j["metric"] = result.metric ? nlohmann::json(*result.metric) : nlohmann::json();
    j["value"] = result.value;
    if (!result.preference_violations.empty()) j["preference_violations"] = result.preference_violations;
  } else {
    j["violation"] = to_json(*result.violation);
    nlohmann::json all = nlohmann::json::array();
    for (const Violation& v : result.violations) all.push_back(to_json(v));
    j["violations"] = std::move(all);
  }
  std::cout << j.dump(2) << "\n";
}

void print_text(const ValidationResult& result) {
  if (result.valid) {
    std::cout << "Plan valid. Makespan: " << pddl::format_number(result.makespan)
              << ". Metric: " << (result.metric ? pddl::format_number(*result.metric) : std::string("none")) << ".\n";
    for (const auto& [name, count] : result.preference_violations) {
      std::cout << "Preference " << name << " violated " << pddl::format_number(count) << " times.\n";
    }
    return;
  }
  std::cout << "Plan invalid. " << result.violation->message() << "\n";
  if (result.violations.size() < 2) return;
  const std::size_t more = result.violations.size() - 1;
  std::cout << more << (more == 1 ? " more violation" : " more violations")
            << ", found going on with the effects applied (later ones may follow from earlier ones):\n";
  for (std::size_t i = 1; i < result.violations.size(); ++i) {
    std::cout << "  " << result.violations[i].message() << "\n";
  }
}

// Bad input (exit 2): already said on stderr; with --json also an object on
// stdout, so that a script reading stdout sees every outcome.
int input_error(const ValidateOptions& options, const std::string& diagnostics) {
  if (options.json) {
    nlohmann::json lines = nlohmann::json::array();
    std::istringstream in(diagnostics);
    for (std::string line; std::getline(in, line);) {
      if (!line.empty()) lines.push_back(line);
    }
    std::cout << nlohmann::json{{"status", "input_error"}, {"valid", nullptr}, {"diagnostics", lines}}.dump(2) << "\n";
  }
  return kExitInputError;
}

int run(const ValidateOptions& options) {
  if (!one_standard_input(options)) return input_error(options, "-: standard input given for more than one file");
  if (options.reference) return run_reference(options);
  std::ostringstream said;
  const auto files = load_task_files(options.domain, options.problem, said, {false});
  std::cerr << said.str();
  if (!files) return input_error(options, said.str());
  std::vector<pddl::Diagnostic> io;
  std::string text;
  if (!pddl::read_input(options.plan, text, io)) {
    std::cerr << io.front().to_string() << "\n";
    return input_error(options, io.front().to_string());
  }
  const PlanReadResult plan = read_plan(text, input_name(options.plan));
  if (!plan.ok()) {
    std::string diagnostics;
    for (const pddl::Diagnostic& d : plan.diagnostics) diagnostics += d.to_string() + "\n";
    std::cerr << diagnostics;
    return input_error(options, diagnostics);
  }
  auto lifted = std::make_shared<const NormalizedTask>(
      normalize(*files->domain, *files->problem, {options.domain, options.problem, {}}));
  ValidatorOptions validator_options;
  validator_options.epsilon = options.epsilon;
  validator_options.val_total_time = options.val_total_time;
  validator_options.report_all = true;
  PlanValidator validator(lifted, validator_options);
  HappeningObserver trace;
  if (options.verbose) {
    // Beside JSON the trace goes to standard error, so stdout stays one JSON document.
    std::ostream& out = options.json ? std::cerr : std::cout;
    trace = [&validator, &out](const HappeningRecord& h) { out << format_happening(validator.world(), h); };
  }
  const ValidationResult result = validator.validate(plan.plan, trace);
  if (options.json) {
    print_json(result);
  } else {
    print_text(result);
  }
  return result.valid ? kExitOk : kExitInvalid;
}

}  // namespace

void add_validate_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<ValidateOptions>();
  CLI::App* cmd = app.add_subcommand("validate", "Validate a plan with VAL's semantics (exit 0 valid, 1 invalid)");
  cmd->add_option("DOMAIN", options->domain, "Domain file ('-': standard input)")->required();
  cmd->add_option("PROBLEM", options->problem, "Problem file ('-': standard input)")->required();
  cmd->add_option("PLAN", options->plan,
                  "Plan file (IPC format, or one (action args) a line; '-': standard input)")
      ->required();
  cmd->add_option("-t,--epsilon", options->epsilon, "VAL's -t: happenings within epsilon/10 are one happening")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_flag("-v,--verbose", options->verbose,
                "Print a state trace, as VAL's -v: per happening its time, members, the facts it adds and "
                "deletes, the values it changes, its violations");
  cmd->add_flag("--json", options->json, "Print the result as JSON");
  cmd->add_flag("--val-total-time", options->val_total_time,
                "Count (total-time) in steps when the domain omits :durative-actions, as VAL does");
  cmd->add_flag("--reference", options->reference,
                "Judge with the reference semantics (oracle/), which shares no code with the planner; exit 2 when it "
                "cannot judge the plan");
  cmd->add_flag("--exact", options->exact,
                "With --reference: compare numbers exactly instead of with VAL's 0.0001 slack");
  cmd->callback([options, &exit_code] { exit_code = run(*options); });
}

}  // namespace alplan::cli
