#include "perception/stress/stress_evaluation.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <random>
#include <stdexcept>

namespace alplan::perception {
namespace {

constexpr std::size_t kStressedRow = 0;  // Table 1 lists Stressed first
constexpr std::size_t kCalmRow = 1;

std::size_t row_of(int stressed) { return stressed == 1 ? kStressedRow : kCalmRow; }

void add_windows(SubjectWindows& subject, const PpgRecording& recording, StressFeatureSet features,
                 const WindowingOptions& windowing) {
  for (const StressWindow& w : stress_windows(recording, windowing)) {
    if (w.label != 0 && w.label != 1) continue;
    if (!w.usable) {
      subject.rejected += 1;
      if (w.features.has_heart_rate) subject.flagged.push_back({feature_vector(w.features, features), w.label});
      continue;
    }
    subject.examples.push_back({feature_vector(w.features, features), w.label});
  }
}

std::vector<StressExample> pooled(const std::vector<const SubjectWindows*>& subjects) {
  std::vector<StressExample> all;
  for (const SubjectWindows* s : subjects) all.insert(all.end(), s->examples.begin(), s->examples.end());
  return all;
}

double accuracy_on(const StressClassifier& model, const std::vector<const SubjectWindows*>& subjects) {
  std::size_t right = 0, total = 0;
  for (const SubjectWindows* s : subjects) {
    for (const StressExample& e : s->examples) {
      right += model.predict(e.features) == e.stressed;
      total += 1;
    }
  }
  return total == 0 ? 0.0 : static_cast<double>(right) / static_cast<double>(total);
}

// Group k-fold over subjects: mean and deviation of the held-out accuracy.
FoldScore cross_validate(const std::vector<const SubjectWindows*>& subjects, int k,
                         const StressClassifierOptions& classifier) {
  std::vector<double> scores;
  for (int fold = 0; fold < k; ++fold) {
    std::vector<const SubjectWindows*> train, held_out;
    for (std::size_t i = 0; i < subjects.size(); ++i) {
      (static_cast<int>(i % static_cast<std::size_t>(k)) == fold ? held_out : train).push_back(subjects[i]);
    }
    const StressClassifier model = StressClassifier::train(pooled(train), classifier);
    scores.push_back(accuracy_on(model, held_out));
  }
  FoldScore score;
  score.k = k;
  score.mean_accuracy = std::accumulate(scores.begin(), scores.end(), 0.0) / static_cast<double>(k);
  double var = 0;
  for (double s : scores) var += (s - score.mean_accuracy) * (s - score.mean_accuracy);
  score.sd_accuracy = std::sqrt(var / static_cast<double>(k));
  return score;
}

}  // namespace

std::vector<SubjectWindows> windows_by_subject(const std::vector<LabelledRecording>& recordings,
                                               StressFeatureSet features, const WindowingOptions& windowing) {
  std::vector<SubjectWindows> out;
  std::map<std::string, std::size_t> index;
  for (const LabelledRecording& r : recordings) {
    auto [it, inserted] = index.emplace(r.subject_id, out.size());
    if (inserted) out.push_back({r.subject_id, {}, 0, {}});
    add_windows(out[it->second], r.simulated.recording, features, windowing);
  }
  return out;
}

std::vector<SubjectWindows> windows_by_subject(const std::vector<std::pair<std::string, PpgRecording>>& recordings,
                                               StressFeatureSet features, const WindowingOptions& windowing) {
  std::vector<SubjectWindows> out;
  std::map<std::string, std::size_t> index;
  for (const auto& [subject, recording] : recordings) {
    if (!recording.has_labels()) throw std::invalid_argument("recording of " + subject + " has no label column");
    auto [it, inserted] = index.emplace(subject, out.size());
    if (inserted) out.push_back({subject, {}, 0, {}});
    add_windows(out[it->second], recording, features, windowing);
  }
  return out;
}

StressEvaluation evaluate_stress(const std::vector<SubjectWindows>& subjects, const StressEvaluationOptions& options) {
  if (options.k_values.empty()) throw std::invalid_argument("stress evaluation: no k to try");
  std::vector<const SubjectWindows*> order;
  for (const SubjectWindows& s : subjects) {
    if (!s.examples.empty()) order.push_back(&s);
  }
  std::mt19937 rng(options.seed);
  std::shuffle(order.begin(), order.end(), rng);
  const auto test_count = static_cast<std::size_t>(std::lround(options.test_fraction * static_cast<double>(order.size())));
  const int largest_k = *std::max_element(options.k_values.begin(), options.k_values.end());
  if (test_count < 1 || order.size() - test_count < static_cast<std::size_t>(std::max(2, largest_k))) {
    throw std::invalid_argument("stress evaluation: " + std::to_string(order.size()) +
                                " subjects with usable windows are too few for a " +
                                std::to_string(options.test_fraction) + " test split and " +
                                std::to_string(largest_k) + "-fold cross-validation");
  }
  const std::vector<const SubjectWindows*> test(order.begin(), order.begin() + static_cast<long>(test_count));
  const std::vector<const SubjectWindows*> train(order.begin() + static_cast<long>(test_count), order.end());

  StressEvaluation result{{}, 0, ConfusionMatrix({"Stressed", "Un-stressed"}), {}, {}, 0, 0, 0,
                          StressClassifier::train(pooled(train), options.classifier)};
  double best = -1.0;
  for (int k : options.k_values) {
    if (k < 2) throw std::invalid_argument("stress evaluation: k must be at least 2");
    const FoldScore score = cross_validate(train, k, options.classifier);
    result.cross_validation.push_back(score);
    if (score.mean_accuracy > best) best = score.mean_accuracy, result.chosen_k = k;
  }
  for (const SubjectWindows* s : train) result.train_subjects.push_back(s->subject), result.train_windows += s->examples.size();
  for (const SubjectWindows* s : test) result.test_subjects.push_back(s->subject), result.test_windows += s->examples.size();
  for (const SubjectWindows& s : subjects) result.rejected_windows += s.rejected;
  std::vector<SubjectWindows> test_copy;
  for (const SubjectWindows* s : test) test_copy.push_back(*s);
  result.test = stress_confusion(result.model, test_copy);
  return result;
}

ConfusionMatrix stress_confusion(const StressClassifier& model, const std::vector<SubjectWindows>& subjects,
                                 bool include_flagged) {
  ConfusionMatrix matrix({"Stressed", "Un-stressed"});
  for (const SubjectWindows& s : subjects) {
    for (const StressExample& e : s.examples) matrix.add(row_of(e.stressed), row_of(model.predict(e.features)));
    if (!include_flagged) continue;
    for (const StressExample& e : s.flagged) matrix.add(row_of(e.stressed), row_of(model.predict(e.features)));
  }
  return matrix;
}

}  // namespace alplan::perception
