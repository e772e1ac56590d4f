// alplan perceive stress false-alarms: the stress detectors over simulated
// seniors wearing the wristband for a long while, calm ones and ones who
// become stressed; false alarms, detections and latency, one row per
// detector, all on the same readings (perception/stress/stress_alarm_study.h).
#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "cli/perceive_common.h"
#include "perception/stress/stress_alarm_study.h"

namespace alplan::cli {
namespace {

struct AlarmCommandOptions {
  perception::AlarmStudyOptions study;
  std::size_t calibration = 24;
  std::size_t follow = 30;
  std::string model_kind = "logistic";
  bool json = false;
};

int run_alarms(AlarmCommandOptions o) {
  o.study.training.classifier.kind = perception::model_kind_from_name(o.model_kind);
  for (perception::AlarmStudyDetector& d : o.study.detectors) {
    if (d.calibration.readings > 0) d.calibration.readings = o.calibration;
    if (d.calibration.follow_readings > 0) d.calibration.follow_readings = o.follow;
  }
  const perception::AlarmStudyReport r = perception::run_alarm_study(o.study);
  if (o.json) {
    std::cout << r.json().dump(2) << "\n";
    return kExitOk;
  }
  std::printf("%zu calm seniors (seeds %llu-%llu, %.0f min calm) and the same %zu seniors calm for %.0f min, then "
              "stressed for %.0f min;\n%.0f Hz, motion %.1f bursts/min, resting rate drifting by up to %.0f bpm; models %s trained on the simulator's database "
              "(%zu subjects, seed %llu); readings every 5 s.\n\n%s",
              o.study.seniors, static_cast<unsigned long long>(o.study.first_seed),
              static_cast<unsigned long long>(o.study.first_seed + o.study.seniors - 1), o.study.minutes,
              o.study.seniors, o.study.onset_minutes, o.study.minutes - o.study.onset_minutes,
              o.study.conditions.sample_rate_hz, o.study.conditions.motion.bursts_per_minute, o.study.drift_bpm,
              o.model_kind.c_str(),
              o.study.training.subjects, static_cast<unsigned long long>(o.study.training.seed), r.markdown().c_str());
  for (const perception::AlarmStudyRow& row : r.rows) {
    if (row.alarmed_seeds.empty()) continue;
    std::printf("\ncalm seniors alarmed by %s: seeds", row.detector.name().c_str());
    for (const std::uint64_t s : row.alarmed_seeds) std::printf(" %llu", static_cast<unsigned long long>(s));
  }
  std::printf("\n(%.1f s)\n", r.seconds);
  return kExitOk;
}

}  // namespace

void add_stress_alarms_command(CLI::App& stress, int& exit_code) {
  auto o = std::make_shared<AlarmCommandOptions>();
  CLI::App* cmd = stress.add_subcommand(
      "false-alarms", "False alarms on calm simulated seniors, detection and latency on stressed ones, per detector");
  cmd->add_option("--seniors", o->study.seniors, "Calm seniors, and as many stressed ones")->check(CLI::Range(1, 1000));
  cmd->add_option("--seed", o->study.first_seed, "The first senior's seed (the others follow)");
  cmd->add_option("--minutes", o->study.minutes, "Minutes each senior wears the wristband")->check(CLI::Range(2.0, 600.0));
  cmd->add_option("--onset", o->study.onset_minutes, "Minutes before the stressed seniors become stressed");
  cmd->add_option("--motion", o->study.conditions.motion.bursts_per_minute, "Motion bursts per minute")
      ->check(CLI::Range(0.0, 30.0));
  cmd->add_option("--drift", o->study.drift_bpm, "Resting heart rate swinging slowly by up to this many bpm")
      ->check(CLI::Range(0.0, 30.0));
  cmd->add_option("--calibration", o->calibration, "Readings in a senior's own baseline")->check(CLI::Range(1, 10000));
  cmd->add_option("--follow", o->follow, "Readings the following baseline averages over")->check(CLI::Range(1, 100000));
  cmd->add_option("--training-seed", o->study.training.seed, "Seed of the models' training database");
  cmd->add_option("--model-kind", o->model_kind, "logistic or svm")->check(CLI::IsMember({"logistic", "svm"}));
  cmd->add_flag("--json", o->json, "Print JSON");
  cmd->callback([o, &exit_code] { exit_code = guarded([&] { return run_alarms(*o); }, "the simulated seniors"); });
}

}  // namespace alplan::cli
