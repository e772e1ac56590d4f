// alplan perceive stress --evaluate | simulate | train | evaluate | detect:
// learning stress from PPG as the paper's Section 6.1 and Tables 1-2 do,
// on the simulated database or on a user's CSV recordings.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/perceive_common.h"
#include "perception/stress/stress_detector.h"
#include "perception/stress/stress_runs.h"

namespace alplan::cli {
namespace {

struct StressCommandOptions {
  bool evaluate = false;
  perception::StressSimulationOptions simulation;
  std::string features = "paper";
  std::string model_kind = "logistic";
  std::vector<int> k_values = {2, 3, 4, 5, 6, 8, 10};
  std::string save;
  bool json = false;
};

void apply_common(StressCommandOptions& o) {
  o.simulation.features = perception::feature_set_from_name(o.features);
  o.simulation.evaluation.classifier.kind = perception::model_kind_from_name(o.model_kind);
  o.simulation.evaluation.classifier.features = o.simulation.features;
  o.simulation.evaluation.k_values = o.k_values;
  o.simulation.evaluation.seed = static_cast<unsigned>(o.simulation.seed);
}

void print_cross_validation(const perception::StressEvaluation& e) {
  std::printf("k-fold cross-validation on the %zu training subjects (%zu windows), by subject:\n",
              e.train_subjects.size(), e.train_windows);
  for (const perception::FoldScore& f : e.cross_validation) {
    std::printf("  k = %2d: accuracy %.3f +- %.3f%s\n", f.k, f.mean_accuracy, f.sd_accuracy,
                f.k == e.chosen_k ? "   <- best (the paper found k = 4)" : "");
  }
}

int run_evaluate(StressCommandOptions o) {
  apply_common(o);
  const perception::StressRunReport r = perception::evaluate_stress_on_simulation(o.simulation);
  if (!o.save.empty()) r.evaluation.model.save(o.save);
  if (o.json) {
    std::cout << r.json().dump(2) << "\n";
    return kExitOk;
  }
  std::printf("Simulated stress database: %zu subjects, one calm and one stressed recording of %.0f s each at %.0f Hz;\n"
              "features %s from the wristband core's 30 s windows every 5 s; model %s; split 80/20 by subject.\n\n",
              o.simulation.subjects, o.simulation.duration_s, o.simulation.sample_rate_hz, o.features.c_str(),
              o.model_kind.c_str());
  print_cross_validation(r.evaluation);
  std::printf("\nTable 1 form: validation on the database (%zu test subjects, %zu windows, %zu windows rejected as "
              "artefacts in all)\n\n%s\naccuracy %.3f, average precision %.3f, average recall %.3f\n",
              r.evaluation.test_subjects.size(), r.evaluation.test_windows, r.evaluation.rejected_windows,
              r.evaluation.test.markdown().c_str(), r.evaluation.test.accuracy(), r.evaluation.test.macro_precision(),
              r.evaluation.test.macro_recall());
  std::printf("\nTable 2 form: the same model on %zu other subjects wearing the wristband (motion %.1f bursts/min at "
              "%.1fx the pulse, noise %.2f): %zu windows used, %zu rejected as artefacts\n\n%s\naccuracy %.3f, average "
              "precision %.3f, average recall %.3f\n",
              o.simulation.wristband_subjects, o.simulation.wristband_motion.bursts_per_minute,
              o.simulation.wristband_motion.strength, o.simulation.wristband_noise_sd, r.wristband_windows,
              r.wristband_rejected, r.wristband.markdown().c_str(), r.wristband.accuracy(), r.wristband.macro_precision(),
              r.wristband.macro_recall());
  std::printf("\nWithout artefact rejection (the motion-flagged windows classified too):\n\n%s\naccuracy %.3f, average "
              "precision %.3f, average recall %.3f\n",
              r.wristband_unfiltered.markdown().c_str(), r.wristband_unfiltered.accuracy(),
              r.wristband_unfiltered.macro_precision(), r.wristband_unfiltered.macro_recall());
  if (!o.save.empty()) std::printf("\nmodel saved to %s\n", o.save.c_str());
  std::printf("(%.1f s)\n", r.seconds);
  return kExitOk;
}

int run_simulate(const StressCommandOptions& o, const std::string& out) {
  perception::DatabaseSpec spec;
  spec.subjects = o.simulation.subjects;
  spec.recordings_per_state = 1;
  spec.conditions.duration_s = o.simulation.duration_s;
  spec.conditions.sample_rate_hz = o.simulation.sample_rate_hz;
  spec.seed = o.simulation.seed;
  perception::write_simulated_recordings(perception::generate_labelled_database(spec), out);
  std::printf("wrote %zu subjects x 2 recordings (time,ppg,label) to %s\n", spec.subjects, out.c_str());
  return kExitOk;
}

int run_train(StressCommandOptions o, const std::string& data, const std::string& out) {
  apply_common(o);
  const auto subjects = perception::windows_by_subject(perception::read_recordings(data), o.simulation.features);
  const perception::StressEvaluation e = perception::evaluate_stress(subjects, o.simulation.evaluation);
  if (o.json) {
    std::cout << nlohmann::json{{"chosen_k", e.chosen_k}, {"test", e.test.json()}}.dump(2) << "\n";
  } else {
    print_cross_validation(e);
    std::printf("\nTable 1 form, on the %zu test subjects:\n\n%s\naccuracy %.3f\n", e.test_subjects.size(),
                e.test.markdown().c_str(), e.test.accuracy());
  }
  e.model.save(out);
  if (!o.json) std::printf("model (trained on the training subjects) saved to %s\n", out.c_str());
  return kExitOk;
}

int run_model_evaluate(const StressCommandOptions& o, const std::string& model_path, const std::string& data) {
  const perception::StressClassifier model = perception::StressClassifier::load(model_path);
  const auto subjects = perception::windows_by_subject(perception::read_recordings(data), model.options().features);
  const perception::ConfusionMatrix m = perception::stress_confusion(model, subjects);
  if (o.json) {
    std::cout << m.json().dump(2) << "\n";
  } else {
    std::printf("%s\naccuracy %.3f, average precision %.3f, average recall %.3f\n", m.markdown().c_str(), m.accuracy(),
                m.macro_precision(), m.macro_recall());
  }
  return kExitOk;
}

int run_detect(const std::string& model_path, const std::string& recording_path, bool json, bool no_baseline) {
  perception::ClassifierStressDetector detector(perception::StressClassifier::load(model_path), {},
                                                no_baseline ? perception::StressCalibration{0, 0} : perception::StressCalibration{});
  const perception::PpgRecording recording = perception::read_ppg_csv_file(recording_path);
  nlohmann::json out = nlohmann::json::array();
  for (const perception::StressWindow& w : perception::stress_windows(recording)) {
    const perception::StressObservation seen = detector.observe("senior", w.features);
    out.push_back({{"end_s", w.end_s}, {"hr_bpm", w.features.mean_hr_bpm}, {"usable", w.usable},
                   {"stressed", seen.state.stressed}, {"calibrating", seen.state.calibrating}, {"event", seen.changed}});
    if (json) continue;
    std::printf("%7.1f s  HR %5.1f  %s%s%s\n", w.end_s, static_cast<double>(w.features.mean_hr_bpm),
                w.usable ? "" : "(not used: motion or too few beats) ",
                seen.state.calibrating ? "learning the senior's baseline" : seen.state.stressed ? "stressed" : "calm",
                seen.changed ? (seen.state.stressed ? "   <- stress event" : "   <- calm again") : "");
  }
  if (json) std::cout << out.dump(2) << "\n";
  return kExitOk;
}

void add_simulation_options(CLI::App& cmd, StressCommandOptions& o) {
  cmd.add_option("--subjects", o.simulation.subjects, "Simulated subjects")->check(CLI::PositiveNumber);
  cmd.add_option("--duration", o.simulation.duration_s, "Seconds per recording")->check(CLI::Range(40.0, 3600.0));
  cmd.add_option("--rate", o.simulation.sample_rate_hz, "Sample rate, Hz")->check(CLI::Range(25.0, 500.0));
  cmd.add_option("--seed", o.simulation.seed, "Seed of the simulator and the split");
}

void add_model_options(CLI::App& cmd, StressCommandOptions& o) {
  cmd.add_option("--features", o.features, "paper (HR, IBI) or paper+hrv (with SDNN, RMSSD)")
      ->check(CLI::IsMember({"paper", "paper+hrv"}));
  cmd.add_option("--model-kind", o.model_kind, "logistic or svm (OpenCV ml)")->check(CLI::IsMember({"logistic", "svm"}));
  cmd.add_option("--k", o.k_values, "The k to try in k-fold cross-validation")->delimiter(',');
  cmd.add_flag("--json", o.json, "Print JSON");
}

}  // namespace

void add_perceive_stress_command(CLI::App& perceive, int& exit_code) {
  auto o = std::make_shared<StressCommandOptions>();
  CLI::App* stress = perceive.add_subcommand("stress", "Stress from PPG: the paper's protocol and Tables 1-2");
  stress->add_flag("--evaluate", o->evaluate, "Train and validate on the simulated database (Tables 1 and 2)");
  add_simulation_options(*stress, *o);
  add_model_options(*stress, *o);
  stress->add_option("--save", o->save, "Save the model trained on the training subjects");
  stress->add_option("--wristband-subjects", o->simulation.wristband_subjects, "Subjects of the wristband validation");
  stress->callback([stress, o, &exit_code] {
    if (!stress->get_subcommands().empty()) return;
    if (!o->evaluate) {
      std::cerr << "error: perceive stress needs --evaluate or a subcommand (simulate, train, evaluate, detect)\n";
      exit_code = kExitInputError;
      return;
    }
    exit_code = guarded([&] { return run_evaluate(*o); }, "the simulated database");
  });

  auto sim = std::make_shared<std::string>();
  CLI::App* simulate = stress->add_subcommand("simulate", "Write the simulated database as CSV recordings (time,ppg,label)");
  simulate->add_option("--out", *sim, "Folder to write, one subfolder per subject")->required();
  add_simulation_options(*simulate, *o);
  simulate->callback([o, sim, &exit_code] { exit_code = guarded([&] { return run_simulate(*o, *sim); }, *sim); });

  auto paths = std::make_shared<std::pair<std::string, std::string>>();
  CLI::App* train = stress->add_subcommand("train", "Train on labelled CSV recordings (a file or folder per subject)");
  train->add_option("--data", paths->first, "Folder of recordings")->required();
  train->add_option("--out", paths->second, "Save the model here")->required();
  add_model_options(*train, *o);
  train->callback([o, paths, &exit_code] {
    exit_code = guarded([&] { return run_train(*o, paths->first, paths->second); }, paths->first);
  });

  auto eval_paths = std::make_shared<std::pair<std::string, std::string>>();
  CLI::App* evaluate = stress->add_subcommand("evaluate", "Confusion matrix of a saved model on labelled recordings");
  evaluate->add_option("--model", eval_paths->first, "A model saved by train or --save")->required();
  evaluate->add_option("--data", eval_paths->second, "Folder of recordings")->required();
  evaluate->add_flag("--json", o->json, "Print JSON");
  evaluate->callback([o, eval_paths, &exit_code] {
    exit_code = guarded([&] { return run_model_evaluate(*o, eval_paths->first, eval_paths->second); }, eval_paths->second);
  });

  add_stress_alarms_command(*stress, exit_code);

  auto detect_paths = std::make_shared<std::pair<std::string, std::string>>();
  CLI::App* detect = stress->add_subcommand("detect", "Stress decisions window by window on one recording");
  detect->add_option("--model", detect_paths->first, "A saved stress model")->required();
  detect->add_option("recording", detect_paths->second, "A CSV recording (time,ppg)")->required();
  detect->add_flag("--json", o->json, "Print JSON");
  auto no_baseline = std::make_shared<bool>(false);
  detect->add_flag("--no-baseline", *no_baseline, "Judge readings as they are, not against the first 24 (the senior's baseline)");
  detect->callback([o, detect_paths, no_baseline, &exit_code] {
    exit_code = guarded([&] { return run_detect(detect_paths->first, detect_paths->second, o->json, *no_baseline); },
                        detect_paths->second);
  });
}

}  // namespace alplan::cli
