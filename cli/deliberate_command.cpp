// alplan deliberate: the paper's deliberation for one senior, end to end —
// the wristband's PPG (a CSV recording, or the simulator's) through the
// stress detector; on a stress event the senior's face through the emotion
// recogniser; the emotion to a goal; the goal into the planning problem;
// plan, execute, monitor and repair, with the robot's camera (a folder of
// images per location) as the object recogniser. Exit 0 when the senior is
// comforted or nothing needed doing, 1 when the run ends with an explained
// failure, 2 on bad input.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <memory>

#include "cli/commands.h"
#include "cli/deliberation_run.h"
#include "cli/perceive_common.h"
#include "home/deliberation.h"
#include "perception/stress/simulated_stress_model.h"
#include "perception/stress/stress_alarm_study.h"
#include "perception/stress/stress_features.h"

namespace alplan::cli {
namespace {

struct DeliberateOptions {
  DeliberationSettings settings;
  std::string senior = "senior1";
  std::string ppg;
  // Calm long enough for the detector to learn the senior's baseline (its
  // first 24 readings: about 150 s) and decide on calm readings too.
  double calm_s = 240, stressed_s = 120;
  bool calm_only = false;
  bool no_baseline = false;
  std::uint64_t seed = 7;
  std::string stress_model;
};

perception::StressClassifier stress_model(const DeliberateOptions& o) {
  if (!o.stress_model.empty()) return perception::StressClassifier::load(o.stress_model);
  perception::SimulatedModelSpec spec;
  spec.subjects = 24;
  spec.recording_s = 150;
  spec.seed = o.seed + 1;  // not the senior's own recordings
  spec.classifier = {};    // logistic regression on the paper's HR and IBI
  std::printf("[learning] stress model trained on the simulated database (24 subjects; --stress-model to load one)\n");
  return perception::train_simulated_stress_classifier(spec);
}

int run(const DeliberateOptions& o) {
  Deliberator deliberator(o.settings);
  // Layer 1: stress.
  perception::RecordingConditions conditions;
  conditions.sample_rate_hz = 50;
  // A calm senior is watched as long as a stressed one would be.
  const perception::PpgRecording ppg =
      !o.ppg.empty() ? perception::read_ppg_csv_file(o.ppg)
      : o.calm_only  ? perception::simulated_senior(o.seed, o.calm_s + o.stressed_s, 0.0, conditions)
                     : perception::simulated_senior(o.seed, o.calm_s, o.stressed_s, conditions);
  perception::ClassifierStressDetector detector(stress_model(o), {},
                                                o.no_baseline ? perception::StressCalibration{0, 0} : perception::StressCalibration{});
  const auto event = home::first_stress_event(detector, o.senior, perception::stress_windows(ppg));
  if (!event) {
    std::printf("[stress] %s's wristband: not stressed over %.0f s of readings; nothing to do\n", o.senior.c_str(),
                ppg.time_s.empty() ? 0.0 : ppg.time_s.back());
    return kExitOk;
  }
  std::printf("[stress] %s's wristband: stressed at %.0f s (%zu of the last %zu readings say so): stress event\n",
              o.senior.c_str(), event->time_s, static_cast<std::size_t>(event->state.stressed_fraction * static_cast<double>(event->state.votes) + 0.5),
              event->state.votes);
  return deliberator.on_stress(o.senior, event->state);
}

}  // namespace

void add_deliberate_command(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<DeliberateOptions>();
  CLI::App* cmd = app.add_subcommand("deliberate", "One senior end to end: stress, emotion, goal, plan, act, monitor, repair");
  add_deliberation_options(*cmd, o->settings);
  cmd->add_option("--senior", o->senior, "The senior wearing the wristband");
  cmd->add_option("--ppg", o->ppg, "The wristband's PPG (CSV time,ppg); default: the simulator's senior");
  cmd->add_option("--calm-seconds", o->calm_s, "Simulated senior: seconds calm first (the first ~150 s make the baseline)")->check(CLI::Range(0.0, 3600.0));
  cmd->add_option("--stressed-seconds", o->stressed_s, "Simulated senior: then seconds stressed")->check(CLI::Range(40.0, 3600.0));
  cmd->add_flag("--calm", o->calm_only, "Simulated senior: never stressed (watched calm + stressed seconds)");
  cmd->add_flag("--no-baseline", o->no_baseline,
                "Judge readings as they are, not against the senior's own first readings (false alarms: see perception/README.md)");
  cmd->add_option("--seed", o->seed, "Seed of the simulated senior");
  cmd->add_option("--stress-model", o->stress_model, "A stress model (perceive stress train/--save); default: trained on the simulator");
  cmd->callback([o, &exit_code] { exit_code = guarded([&] { return run(*o); }, o->settings.problem); });
}

}  // namespace alplan::cli
