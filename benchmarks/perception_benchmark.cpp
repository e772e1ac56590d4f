// Perception latencies on python3-skimage's photos: face detection (Haar
// cascade) on the astronaut, emotion inference per face (mini-Xception on
// her 64x64 crop, and the paper's CNN on the 48x48 crop) and for the whole
// image, COCO detection (CenterNet) on the coffee cup, the paper's CNN on one
// object image, loading both tfjs models; and stress per window: the
// wristband core's features and the classifier's verdict.
// The CNNs run with their initial weights: inference costs the same trained
// or not, and a benchmark must not depend on a training run.
//   build/benchmarks/perception_benchmark --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <opencv2/core/utility.hpp>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>
#include <string>

#include "perception/stress/ppg_simulator.h"
#include "perception/stress/simulated_stress_model.h"
#include "perception/stress/stress_classifier.h"
#include "perception/stress/stress_features.h"
#include "perception/tfjs/tfjs_graph_model.h"
#include "perception/vision/cnn_classifier.h"
#include "perception/vision/coco_detector.h"
#include "perception/vision/face_detector.h"
#include "perception/vision/object_image_generator.h"
#include "perception/vision/pretrained_emotion_recognizer.h"

namespace {

using namespace alplan::perception;

const std::string kSkimageData = "/usr/lib/python3/dist-packages/skimage/data/";

cv::Mat photo(const std::string& name) {
  cv::Mat image = cv::imread(kSkimageData + name);
  if (image.empty()) throw std::runtime_error("cannot read " + kSkimageData + name);
  return image;
}

void BM_FaceDetection(benchmark::State& state) {
  FaceDetector detector;
  const cv::Mat image = photo("astronaut.png");
  for (auto _ : state) benchmark::DoNotOptimize(detector.detect(image));
}
BENCHMARK(BM_FaceDetection)->Unit(benchmark::kMillisecond);

void BM_EmotionPerFace(benchmark::State& state) {
  PretrainedEmotionRecognizer recognizer;
  FaceDetector detector;
  const auto faces = detector.detect(photo("astronaut.png"));
  if (faces.size() != 1) throw std::runtime_error("expected the astronaut's face");
  for (auto _ : state) benchmark::DoNotOptimize(recognizer.classify_face(faces.front().grey_crop));
}
BENCHMARK(BM_EmotionPerFace)->Unit(benchmark::kMillisecond);

void BM_EmotionWholeImage(benchmark::State& state) {
  PretrainedEmotionRecognizer recognizer;
  const cv::Mat image = photo("astronaut.png");
  for (auto _ : state) benchmark::DoNotOptimize(recognizer.recognize(image));
}
BENCHMARK(BM_EmotionWholeImage)->Unit(benchmark::kMillisecond);

void BM_CocoDetection(benchmark::State& state) {
  CocoDetector detector;
  const cv::Mat image = photo("coffee.png");
  for (auto _ : state) benchmark::DoNotOptimize(detector.detect(image));
}
BENCHMARK(BM_CocoDetection)->Unit(benchmark::kMillisecond);

void BM_PaperCnnEmotionPerFace(benchmark::State& state) {
  CnnClassifier cnn({"angry", "disgusted", "happy", "neutral", "sad", "surprised", "terrified"}, CnnArchitecture{});
  FaceDetector detector;
  const auto faces = detector.detect(photo("astronaut.png"));
  if (faces.size() != 1) throw std::runtime_error("expected the astronaut's face");
  for (auto _ : state) benchmark::DoNotOptimize(cnn.scores(faces.front().grey_crop));
}
BENCHMARK(BM_PaperCnnEmotionPerFace)->Unit(benchmark::kMillisecond);

// The object classifier as `alplan perceive objects train --generated` makes
// it: the paper's layers on 48x48 colour images of the 18 Table-4 classes.
void BM_PaperCnnPerObjectImage(benchmark::State& state) {
  ObjectImageOptions options;
  options.per_class = 1;
  const ImageDataset images = generate_object_images(options);
  CnnArchitecture architecture;
  architecture.channels = 3;
  CnnClassifier cnn(images.classes, architecture);
  const cv::Mat& image = images.samples.front().image;
  for (auto _ : state) benchmark::DoNotOptimize(cnn.scores(image));
}
BENCHMARK(BM_PaperCnnPerObjectImage)->Unit(benchmark::kMillisecond);

// Five minutes of 100 Hz PPG through the wristband core: the time per
// 30-s window (one every 5 s) is this divided by the windows counter.
void BM_StressFeaturesFiveMinutes(benchmark::State& state) {
  PpgSimulator simulator(7);
  RecordingConditions conditions;
  conditions.duration_s = 300.0;
  const SimulatedRecording simulated = simulator.simulate(simulator.random_subject(), conditions);
  std::size_t windows = 0;
  for (auto _ : state) {
    const auto result = stress_windows(simulated.recording);
    windows = result.size();
    benchmark::DoNotOptimize(result.data());
  }
  state.counters["windows"] = static_cast<double>(windows);
  state.counters["per_window_us"] = benchmark::Counter(
      static_cast<double>(windows) * static_cast<double>(state.iterations()),
      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_StressFeaturesFiveMinutes)->Unit(benchmark::kMillisecond);

StressClassifier trained_stress_classifier(StressModelKind kind) {
  SimulatedModelSpec spec;
  spec.classifier = {kind, StressFeatureSet::Paper, 5};
  return train_simulated_stress_classifier(spec);
}

void BM_StressVerdictPerWindow(benchmark::State& state, StressModelKind kind) {
  const StressClassifier classifier = trained_stress_classifier(kind);
  PpgSimulator simulator(8);
  RecordingConditions conditions;
  conditions.duration_s = 60.0;
  const auto windows = stress_windows(simulator.simulate(simulator.random_subject(), conditions).recording);
  const StressWindow& window = windows.back();
  for (auto _ : state) benchmark::DoNotOptimize(classifier.predict(window.features));
}
BENCHMARK_CAPTURE(BM_StressVerdictPerWindow, logistic, StressModelKind::LogisticRegression)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_StressVerdictPerWindow, svm, StressModelKind::Svm)->Unit(benchmark::kMicrosecond);

void BM_LoadModel(benchmark::State& state, const std::string& file, const std::vector<std::string>& outputs) {
  for (auto _ : state) benchmark::DoNotOptimize(load_tfjs_graph_model(std::string(ALPLAN_MODELS_DIR) + file, outputs));
}
BENCHMARK_CAPTURE(BM_LoadModel, emotion, "/emotion.json", std::vector<std::string>{"Identity"})
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_LoadModel, centernet, "/centernet.json",
                  std::vector<std::string>{"tower_0/keypoints", "tower_0/wh"})
    ->Unit(benchmark::kMillisecond);

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  benchmark::AddCustomContext("opencv_threads", std::to_string(cv::getNumThreads()));
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
