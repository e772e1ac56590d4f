// alplan validate DOMAIN PROBLEM PLAN [--epsilon E] [--json]
// Exit 0 valid, 1 invalid, 2 input error.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "cli/task_files.h"
#include "oracle/judge.h"
#include "oracle/load.h"
#include "pddl_parser/parser.h"
#include "pddl_parser/writer.h"
#include "planner/normalize.h"
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
};

// The reference semantics (oracle/), which shares no code with the planner
// or its validator: a second opinion on a plan.
int run_reference(const ValidateOptions& options) {
  const oracle::LoadedTask task = oracle::load_task_files(options.domain, options.problem);
  if (!task.ok()) {
    std::cerr << task.error;
    return kExitInputError;
  }
  std::vector<pddl::Diagnostic> io;
  std::string text;
  if (!pddl::read_file(options.plan, text, io)) {
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

int run(const ValidateOptions& options) {
  if (options.reference) return run_reference(options);
  const auto files = load_task_files(options.domain, options.problem, std::cerr, {false});
  if (!files) return kExitInputError;
  std::vector<pddl::Diagnostic> io;
  std::string text;
  if (!pddl::read_file(options.plan, text, io)) {
    std::cerr << io.front().to_string() << "\n";
    return kExitInputError;
  }
  const PlanReadResult plan = read_plan(text, options.plan);
  if (!plan.ok()) {
    for (const pddl::Diagnostic& d : plan.diagnostics) std::cerr << d.to_string() << "\n";
    return kExitInputError;
  }
  auto lifted = std::make_shared<const NormalizedTask>(
      normalize(*files->domain, *files->problem, {options.domain, options.problem, {}}));
  PlanValidator validator(lifted, {options.epsilon, options.val_total_time});
  const ValidationResult result = validator.validate(plan.plan);
  if (options.json) {
    nlohmann::json j = {{"valid", result.valid}, {"happenings", result.happenings}};
    if (result.valid) {
      j["makespan"] = result.makespan;
      j["metric"] = result.metric ? nlohmann::json(*result.metric) : nlohmann::json();
      j["value"] = result.value;
      if (!result.preference_violations.empty()) j["preference_violations"] = result.preference_violations;
    } else {
      j["violation"] = to_json(*result.violation);
    }
    std::cout << j.dump(2) << "\n";
  } else if (result.valid) {
    std::cout << "Plan valid. Makespan: " << pddl::format_number(result.makespan)
              << ". Metric: " << (result.metric ? pddl::format_number(*result.metric) : std::string("none")) << ".\n";
    for (const auto& [name, count] : result.preference_violations) {
      std::cout << "Preference " << name << " violated " << pddl::format_number(count) << " times.\n";
    }
  } else {
    std::cout << "Plan invalid. " << result.violation->message() << "\n";
  }
  return result.valid ? kExitOk : kExitInvalid;
}

}  // namespace

void add_validate_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<ValidateOptions>();
  CLI::App* cmd = app.add_subcommand("validate", "Validate a plan with VAL's semantics (exit 0 valid, 1 invalid)");
  cmd->add_option("DOMAIN", options->domain, "Domain file")->required();
  cmd->add_option("PROBLEM", options->problem, "Problem file")->required();
  cmd->add_option("PLAN", options->plan, "Plan file (IPC format, or one (action args) a line)")->required();
  cmd->add_option("--epsilon", options->epsilon, "VAL's -t: happenings within epsilon/10 are one happening")
      ->check(CLI::PositiveNumber);
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
