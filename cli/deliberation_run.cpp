#include "cli/deliberation_run.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "cli/paper_format.h"
#include "cli/perceive_common.h"
#include "domains/mission_run.h"
#include "perception/common/emotion.h"
#include "repair/repair_strategy.h"

namespace alplan::cli {
namespace {

std::vector<repair::ExogenousEvent> scripted_events(const std::vector<std::string>& specs) {
  std::vector<repair::ExogenousEvent> events;
  for (const std::string& spec : specs) {
    const std::size_t at = spec.find('@');
    double time = 0;
    try {
      if (at == std::string::npos) throw std::invalid_argument("no @");
      time = std::stod(spec.substr(at + 1));
    } catch (const std::exception&) {
      throw CommandInputError("--unavailable " + spec + ": expected OBJECT@TIME, e.g. glass_id05@140");
    }
    events.push_back(repair::becomes_unavailable(time, spec.substr(0, at)));
  }
  return events;
}

void print_mission(const domains::MissionRun& run) {
  std::cout << "\n[plan] the initial plan:\n" << paper_format(run.initial_plan) << "\n";
  for (const std::string& e : run.report.events) std::cout << "  " << e << "\n";
  for (const repair::RepairRecord& r : run.report.repairs) {
    for (const repair::RecognizedObject& seen : r.integrated) {
      std::cout << "\n[perception] the camera saw " << seen.name << " (" << seen.type << ") at " << seen.location << "\n";
    }
    if (!r.repaired) {
      std::cout << (r.deferred ? "\nNo repair yet (" : "\nFailed repair (") << r.strategy << "):\n" << r.explanation.text();
      continue;
    }
    std::cout << "\nRepaired plan (" << r.strategy << "):\n" << paper_format(r.plan_text) << "\n" << r.explanation.text();
  }
  std::cout << "\nOutcome: " << run.report.outcome << "\n";
}

}  // namespace

void add_deliberation_options(CLI::App& cmd, DeliberationSettings& s) {
  cmd.add_option("--domains-dir", s.dir, "Folder with domain.pddl, types.ttl and the problems");
  cmd.add_option("--problem", s.problem, "The home's problem file in that folder (its goal is replaced)");
  cmd.add_option("--face", s.face, "An image of the senior's face (the pretrained emotion network reads it)");
  cmd.add_option("--emotion", s.emotion, "The emotion, when no face image is at hand (said to be given)");
  cmd.add_option("--looks", s.looks,
                 "Looks at the face per stress event, --look-interval apart (the boredom rule needs neutral looks at "
                 "several times; one image read at one instant is one look)");
  cmd.add_option("--look-interval", s.look_interval, "Seconds the robot waits between two looks at the face")
      ->check(CLI::Range(0.0, 3600.0));
  cmd.add_option("--camera", s.camera, "Folder with a subfolder of images per location: what the robot's camera sees");
  cmd.add_option("--unavailable", s.unavailable, "OBJECT@TIME: the object becomes unavailable then (repeatable)");
  cmd.add_option("--strategy", s.strategy, "Repair strategy: " + repair::strategy_list());
}

namespace {

home::DeliberatorSettings library_settings(const DeliberationSettings& s) {
  home::DeliberatorSettings out;
  out.dir = s.dir;
  out.problem = s.problem;
  out.face = s.face;
  out.emotion = s.emotion;
  out.looks = s.looks;
  out.look_interval_s = s.look_interval;
  out.camera = s.camera;
  out.events = scripted_events(s.unavailable);
  out.strategy = s.strategy;
  return out;
}

// The library's refusals of settings are the command's input errors.
home::Deliberator make(const DeliberationSettings& settings) {
  try {
    return home::Deliberator(library_settings(settings));
  } catch (const std::invalid_argument& e) {
    throw CommandInputError(e.what());
  }
}

}  // namespace

Deliberator::Deliberator(const DeliberationSettings& settings) : deliberator_(make(settings)) {}

int Deliberator::on_stress(const std::string& senior, const perception::StressState& stress) {
  home::Deliberation d;
  try {
    d = deliberator_.on_stress(senior, stress);
  } catch (const std::invalid_argument& e) {
    throw CommandInputError(e.what());
  }
  for (const std::string& note : d.notes) std::printf("%s\n", note.c_str());
  if (!d.emotion) return kExitOk;  // no face seen
  if (!d.goal) {
    std::printf("[goal] none: %s generates no goal for a stressed senior\n",
                std::string(perception::emotion_name(d.emotion->top)).c_str());
    return kExitOk;
  }
  std::printf("[goal] (%s %s): %s, decided by %s\n", d.goal->goal.atom.name.c_str(), senior.c_str(),
              d.goal->motivation.c_str(), d.goal->decided_by.c_str());
  if (!d.run) {
    // Deliberation ends here, explained: the goal perception chose has no
    // plan in this home, so the robot does nothing rather than fail.
    std::cout << "\n[plan] no plan: " << d.no_plan << "\n[outcome] the robot cannot comfort " << senior << " in this home: "
              << d.goal->motivation << "\n";
    return kExitInvalid;
  }
  print_mission(*d.run);
  return d.comforted() ? kExitOk : kExitInvalid;
}

}  // namespace alplan::cli
