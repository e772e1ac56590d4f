// Perception latencies on python3-skimage's photos: face detection (Haar
// cascade) on the astronaut, emotion inference per face (mini-Xception on
// her 64x64 crop) and for the whole image, COCO detection (CenterNet) on the
// coffee cup, and loading both tfjs models.
//   build/benchmarks/perception_benchmark --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <opencv2/core/utility.hpp>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>
#include <string>

#include "perception/coco_detector.h"
#include "perception/face_detector.h"
#include "perception/pretrained_emotion_recognizer.h"
#include "perception/tfjs_graph_model.h"

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
