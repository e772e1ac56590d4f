// alplan perceive emotion train|evaluate, perceive objects train|evaluate,
// perceive trainer-check: the paper's CNN on user data (KDEF, folders of
// classes), on generated object images, and on Fashion-MNIST as a check
// that the trainer learns. Models are saved to files and loaded by path.
#include <CLI/CLI.hpp>

#include <unistd.h>

#include <functional>

#include <cstdio>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/perceive_common.h"
#include "perception/vision/cnn_runs.h"
#include "planner/progress_meter.h"

namespace alplan::cli {
namespace {

struct LearningOptions {
  std::string data;
  std::string layout;
  std::string out;
  std::string model;
  std::size_t limit = 0;
  std::size_t per_class = 200;
  perception::CnnRunOptions run;
  std::string l2_mode = "decoupled";
  bool json = false;
  double threshold = 0.88;
};

void add_training_options(CLI::App& cmd, LearningOptions& o) {
  cmd.add_option("--epochs", o.run.training.epochs, "Training epochs at most")->check(CLI::PositiveNumber);
  cmd.add_option("--batch", o.run.training.batch_size, "Mini-batch size")->check(CLI::PositiveNumber);
  cmd.add_option("--lr", o.run.training.learning_rate, "Adam's learning rate")->check(CLI::PositiveNumber);
  cmd.add_option("--l2", o.run.training.l2, "L2 regularisation (the paper: 0.01)")->check(CLI::NonNegativeNumber);
  cmd.add_option("--l2-mode", o.l2_mode, "decoupled (AdamW weight decay) or penalty (lambda * sum w^2 in the loss)")
      ->check(CLI::IsMember({"decoupled", "penalty"}));
  cmd.add_option("--patience", o.run.training.patience, "Epochs without a better validation loss before stopping");
  cmd.add_option("--min-delta", o.run.training.min_delta, "What counts as better");
  cmd.add_option("--test-fraction", o.run.test_fraction, "Held out for the test (the paper: 0.2)")->check(CLI::Range(0.05, 0.9));
  cmd.add_option("--seed", o.run.seed, "Seed of the split and the initial weights");
  cmd.add_option("--threads", o.run.training.threads, "Torch threads (0: all cores)");
  cmd.add_option("--input-size", o.run.architecture.input_size, "Input side in pixels (the paper: 48)")->check(CLI::Range(8, 512));
  cmd.add_flag("--dropout-every-layer", o.run.architecture.dropout_every_hidden_layer, "Dropout after every hidden layer too");
  cmd.add_option("--limit", o.limit, "Read at most this many images");
  cmd.add_flag("--json", o.json, "Print JSON");
}

void print_run(const perception::CnnRunReport& r, const std::string& title, bool json) {
  if (json) {
    std::cout << r.json().dump(2) << "\n";
    return;
  }
  std::printf("%s: %zu training and %zu test images, %zu parameters, %.1f s\n", title.c_str(), r.train_samples,
              r.test_samples, r.parameters, r.seconds);
  for (const perception::EpochReport& e : r.training.epochs) {
    std::printf("  epoch %2d  train loss %.4f  validation loss %.4f  accuracy %.4f  (%.1f s)\n", e.epoch, e.train_loss,
                e.validation_loss, e.validation_accuracy, e.seconds);
  }
  std::printf("  weights of epoch %d kept%s\n\n%s\n", r.training.best_epoch, r.training.stopped_early ? " (stopped early)" : "",
              r.test.markdown().c_str());
  std::printf("test accuracy %.4f, macro precision %.4f, macro recall %.4f\n", r.test.accuracy(), r.test.macro_precision(),
              r.test.macro_recall());
}

void print_evaluation(const perception::ConfusionMatrix& m, bool json) {
  if (json) {
    std::cout << m.json().dump(2) << "\n";
    return;
  }
  std::printf("%s\naccuracy %.4f, macro precision %.4f, macro recall %.4f\n", m.markdown().c_str(), m.accuracy(),
              m.macro_precision(), m.macro_recall());
}

// Training as a progress meter on stderr: a bar on a terminal, a line an
// epoch elsewhere. The run may stop early; the bar then ends short.
std::function<void(const perception::EpochReport&)> epoch_meter(ProgressMeter& meter) {
  return [&meter](const perception::EpochReport& e) {
    char line[96];
    std::snprintf(line, sizeof line, "epoch %d done (%.0f s)", e.epoch, e.seconds);
    meter.update(e.epoch, line);
  };
}

int train(LearningOptions o, bool grey, const std::string& title) {
  o.run.training.l2_mode =
      o.l2_mode == "penalty" ? perception::L2Mode::LossPenalty : perception::L2Mode::DecoupledWeightDecay;
  o.run.architecture.channels = grey ? 1 : 3;
  o.run.training.seed = o.run.seed;
  ProgressMeter meter(std::cerr, o.run.training.epochs, "epochs", isatty(STDERR_FILENO) != 0);
  if (!o.json) o.run.training.on_epoch = epoch_meter(meter);
  const perception::ImageDataset data = perception::read_image_data(o.layout, o.data, grey, o.limit);
  auto [model, report] = perception::train_and_test_cnn(data, o.run);
  meter.finish();
  print_run(report, title, o.json);
  if (!o.out.empty()) {
    model.save(o.out);
    if (!o.json) std::cout << "model saved to " << o.out << "\n";
  }
  return kExitOk;
}

int evaluate(const LearningOptions& o, bool grey) {
  const perception::CnnClassifier model = perception::CnnClassifier::load(o.model);
  perception::ImageDataset data = perception::read_image_data(o.layout, o.data, grey, o.limit);
  if (data.classes != model.classes()) {
    throw std::invalid_argument(o.data + ": its classes differ from the model's (" + std::to_string(data.classes.size()) +
                                " against " + std::to_string(model.classes().size()) + ")");
  }
  print_evaluation(model.evaluate(data), o.json);
  return kExitOk;
}

void add_learning_pair(CLI::App& parent, int& exit_code, bool grey, const std::string& what,
                       const std::vector<std::string>& layouts, const std::string& default_layout) {
  auto t = std::make_shared<LearningOptions>();
  t->layout = default_layout;
  CLI::App* train_cmd = parent.add_subcommand("train", "Train the paper's CNN on " + what + " (80/20 split), print the confusion matrix, save");
  train_cmd->add_option("--data", t->data, "The dataset's folder");
  train_cmd->add_option("--layout", t->layout, "Dataset layout")->check(CLI::IsMember(layouts));
  train_cmd->add_option("--out", t->out, "Save the trained model here");
  add_training_options(*train_cmd, *t);
  train_cmd->callback([t, grey, what, &exit_code] {
    if (t->data.empty() && t->layout != "generated") {
      std::cerr << "error: --data is required for layout " << t->layout << "\n";
      exit_code = kExitInputError;
      return;
    }
    exit_code = guarded([&] { return train(*t, grey, "the paper's CNN on " + what); }, t->data);
  });

  auto e = std::make_shared<LearningOptions>();
  e->layout = default_layout;
  CLI::App* eval_cmd = parent.add_subcommand("evaluate", "Confusion matrix of a trained model on " + what);
  eval_cmd->add_option("--model", e->model, "A model saved by train")->required();
  eval_cmd->add_option("--data", e->data, "The dataset's folder");
  eval_cmd->add_option("--layout", e->layout, "Dataset layout")->check(CLI::IsMember(layouts));
  eval_cmd->add_option("--limit", e->limit, "Read at most this many images");
  eval_cmd->add_flag("--json", e->json, "Print JSON");
  eval_cmd->callback([e, grey, &exit_code] { exit_code = guarded([&] { return evaluate(*e, grey); }, e->model); });
}

int trainer_check(LearningOptions o) {
  o.run.training.seed = o.run.seed;
  o.run.architecture.channels = 1;
  o.run.training.l2_mode =
      o.l2_mode == "penalty" ? perception::L2Mode::LossPenalty : perception::L2Mode::DecoupledWeightDecay;
  ProgressMeter meter(std::cerr, o.run.training.epochs, "epochs", isatty(STDERR_FILENO) != 0);
  if (!o.json) o.run.training.on_epoch = epoch_meter(meter);
  perception::ReadOptions read;
  read.limit = o.limit;
  const std::string dir = o.data.empty() ? "/usr/share/datasets/fashion-mnist" : o.data;
  const perception::ImageDataset train_set = perception::read_fashion_mnist(true, read, dir);
  const perception::ImageDataset test_set = perception::read_fashion_mnist(false, {}, dir);
  auto [model, report] = perception::train_and_test_cnn(train_set, test_set, o.run);
  meter.finish();
  print_run(report, "the paper's CNN on Fashion-MNIST (Debian dataset-fashion-mnist, its 10,000 test images)", o.json);
  const bool passed = report.test.accuracy() >= o.threshold;
  if (!o.json) std::printf("%s: test accuracy %.4f %s %.2f\n", passed ? "PASS" : "FAIL", report.test.accuracy(), passed ? ">=" : "<", o.threshold);
  if (!o.out.empty()) model.save(o.out);
  return passed ? kExitOk : kExitInvalid;
}

}  // namespace

void add_emotion_learning_commands(CLI::App& emotion, int& exit_code) {
  add_learning_pair(emotion, exit_code, true, "faces (KDEF or a folder per emotion, e.g. with UMB-DB's bored)",
                    {"kdef", "folders"}, "kdef");
}

void add_object_learning_commands(CLI::App& objects, int& exit_code) {
  add_learning_pair(objects, exit_code, false, "object images (a folder per type, or the generated set)",
                    {"folders", "generated"}, "folders");
}

void add_trainer_check_command(CLI::App& perceive, int& exit_code) {
  auto o = std::make_shared<LearningOptions>();
  o->run.training.epochs = 4;
  CLI::App* cmd = perceive.add_subcommand("trainer-check",
                                          "Train the paper's CNN on Fashion-MNIST and check it reaches a test accuracy");
  cmd->add_option("--data", o->data, "Folder with Fashion-MNIST's IDX files (default: Debian's)");
  cmd->add_option("--threshold", o->threshold, "Accuracy to reach (default 0.88)");
  cmd->add_option("--out", o->out, "Save the trained model here");
  add_training_options(*cmd, *o);
  cmd->callback([o, &exit_code] { exit_code = guarded([&] { return trainer_check(*o); }, "Fashion-MNIST"); });
}

}  // namespace alplan::cli
