#include "perception/tfjs/tfjs_graph_model.h"

#include <catch2/catch.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "tests/perception/tfjs/tfjs_test_files.h"

using namespace alplan::perception;
using namespace alplan::test;
using Catch::Matchers::Contains;
using nlohmann::json;

namespace {

const std::string kModels = ALPLAN_MODELS_DIR;
const std::string kSkimageData = "/usr/lib/python3/dist-packages/skimage/data/";

json const_node(const std::string& name, const std::string& dtype, const std::vector<std::int64_t>& shape) {
  return {{"name", name},
          {"op", "Const"},
          {"attr",
           {{"dtype", {{"type", dtype}}},
            {"value", {{"tensor", {{"dtype", dtype}, {"tensorShape", tensor_shape_json(shape)}}}}}}}};
}

json fused_conv_node(const std::string& fused_ops_base64_second) {
  return {{"name", "conv"},
          {"op", "_FusedConv2D"},
          {"input", {"x", "w", "b"}},
          {"attr",
           {{"T", {{"type", "DT_FLOAT"}}},
            {"strides", {{"list", {{"i", {"1", "1", "1", "1"}}}}}},
            {"dilations", {{"list", {{"i", {"1", "1", "1", "1"}}}}}},
            {"padding", {{"s", "VkFMSUQ="}}},      // VALID
            {"data_format", {{"s", "TkhXQw=="}}},  // NHWC
            {"num_args", {{"i", "1"}}},
            {"fused_ops", {{"list", {{"s", {"Qmlhc0FkZA==", fused_ops_base64_second}}}}}}}}};
}

// x[1,2,2,1] -> _FusedConv2D 1x1 (uint8-quantised filter, float16 bias,
// BiasAdd+Relu6) -> Mean over H,W (int32 axes) -> Mul by a uint16-quantised
// scalar -> Identity; plus an op OpenCV lacks that the output does not need.
json tiny_model(const std::string& second_fused_op = "UmVsdTY=" /* Relu6 */) {
  json nodes = json::array();
  nodes.push_back(
      {{"name", "x"},
       {"op", "Placeholder"},
       {"attr", {{"dtype", {{"type", "DT_FLOAT"}}}, {"shape", {{"shape", tensor_shape_json({1, 2, 2, 1})}}}}}});
  nodes.push_back(const_node("w", "DT_FLOAT", {1, 1, 1, 2}));
  nodes.push_back(const_node("b", "DT_FLOAT", {2}));
  nodes.push_back(fused_conv_node(second_fused_op));
  nodes.push_back(const_node("axes", "DT_INT32", {2}));
  nodes.push_back(
      {{"name", "mean"},
       {"op", "Mean"},
       {"input", {"conv", "axes"}},
       {"attr", {{"keep_dims", {{"b", true}}}, {"T", {{"type", "DT_FLOAT"}}}, {"Tidx", {{"type", "DT_INT32"}}}}}});
  nodes.push_back(const_node("s", "DT_FLOAT", {}));
  nodes.push_back(
      {{"name", "scaled"}, {"op", "Mul"}, {"input", {"mean", "s"}}, {"attr", {{"T", {{"type", "DT_FLOAT"}}}}}});
  nodes.push_back(
      {{"name", "out"}, {"op", "Identity"}, {"input", {"scaled"}}, {"attr", {{"T", {{"type", "DT_FLOAT"}}}}}});
  nodes.push_back({{"name", "unused"}, {"op", "Unique"}, {"input", {"x"}}, {"attr", {{"T", {{"type", "DT_FLOAT"}}}}}});
  const json weights = {{{"name", "w"},
                         {"shape", {1, 1, 1, 2}},
                         {"dtype", "float32"},
                         {"quantization", {{"dtype", "uint8"}, {"min", -1.0}, {"scale", 0.5}}}},
                        {{"name", "b"}, {"shape", {2}}, {"dtype", "float32"}, {"quantization", {{"dtype", "float16"}}}},
                        {{"name", "axes"}, {"shape", {2}}, {"dtype", "int32"}},
                        {{"name", "s"},
                         {"shape", json::array()},
                         {"dtype", "float32"},
                         {"quantization", {{"dtype", "uint16"}, {"min", 0.0}, {"scale", 0.001}}}}};
  return {{"format", "graph-model"},
          {"modelTopology", {{"node", nodes}, {"versions", json::object()}}},
          {"weightsManifest", {{{"paths", {"tiny.bin"}}, {"weights", weights}}}}};
}

// w = [-0.5, 2] (uint8 1, 6 at min -1, scale 0.5); b = [0.25, -1] (half);
// axes = [1, 2]; s = 1.5 (uint16 1500 at scale 0.001).
std::string tiny_weights() {
  return uint8_bytes({1, 6}) + uint16_bytes({0x3400, 0xBC00}) + int32_bytes({1, 2}) + uint16_bytes({1500});
}

cv::Mat forward(TfjsGraphModel& model, const cv::Mat& blob, std::size_t output = 0) {
  model.net.setInput(blob);
  return model.net.forward(model.output_layers.at(output));
}

}  // namespace

TEST_CASE("a tfjs graph with fused, quantised and pruned parts computes what TensorFlow would") {
  ScratchFolder folder("tfjs-tiny");
  write_json(folder.path() / "tiny.json", tiny_model());
  write_file(folder.path() / "tiny.bin", tiny_weights());
  TfjsGraphModel model = load_tfjs_graph_model(folder.path() / "tiny.json", {"out", "conv"});
  CHECK(model.output_layers == std::vector<std::string>{"scaled", "conv"});

  const float input[] = {-1.0F, 0.5F, 2.0F, 4.0F};
  const cv::Mat blob(std::vector<int>{1, 1, 2, 2}, CV_32F, const_cast<float*>(input));
  model.net.setInput(blob);
  std::vector<cv::Mat> outputs;
  model.net.forward(outputs, model.output_layers);
  // conv: relu6(-0.5 x + 0.25) = [0.75 0 0 0]; relu6(2 x - 1) = [0 0 3 6].
  const cv::Mat& conv = outputs[1];
  REQUIRE(conv.total() == 8);
  const std::vector<float> conv_values(conv.ptr<float>(), conv.ptr<float>() + 8);
  CHECK(conv_values == std::vector<float>{0.75F, 0, 0, 0, 0, 0, 3, 6});
  // out: mean over H,W times 1.5.
  REQUIRE(outputs[0].total() == 2);
  CHECK(outputs[0].ptr<float>()[0] == Approx(0.1875 * 1.5));
  CHECK(outputs[0].ptr<float>()[1] == Approx(2.25 * 1.5));
}

// The reference numbers were computed by TensorFlow.js 4.22 itself (cpu
// backend, tf.loadGraphModel + execute) on the same input tensors, which the
// tests rebuild here with OpenCV.
TEST_CASE("the pretrained emotion model computes what TensorFlow.js computes") {
  TfjsGraphModel model = load_tfjs_graph_model(kModels + "/emotion.json", {"Identity"});
  const cv::Mat image = cv::imread(kSkimageData + "astronaut.png");
  REQUIRE_FALSE(image.empty());
  cv::Mat grey;
  cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
  cv::resize(grey, grey, {64, 64}, 0, 0, cv::INTER_AREA);
  grey.convertTo(grey, CV_32F, 2.0 / 255, -1.0);
  const cv::Mat scores = forward(model, cv::dnn::blobFromImage(grey));
  const std::vector<double> tfjs = {0.13170871138572693,  1.5584436141580227e-7, 0.046397022902965546,
                                    0.019824126735329628, 0.7001526951789856,    0.020554210990667343,
                                    0.08136307448148727};
  REQUIRE(scores.total() == tfjs.size());
  for (std::size_t i = 0; i < tfjs.size(); ++i) CHECK(scores.ptr<float>()[i] == Approx(tfjs[i]).margin(1e-5));
}

TEST_CASE("the pretrained CenterNet computes what TensorFlow.js computes") {
  TfjsGraphModel model = load_tfjs_graph_model(kModels + "/centernet.json", {"tower_0/keypoints", "tower_0/wh"});
  const cv::Mat image = cv::imread(kSkimageData + "coffee.png");
  REQUIRE_FALSE(image.empty());
  cv::Mat rgb;
  cv::cvtColor(image, rgb, cv::COLOR_BGR2RGB);
  cv::resize(rgb, rgb, {512, 512}, 0, 0, cv::INTER_LINEAR);
  model.net.setInput(cv::dnn::blobFromImage(rgb));
  std::vector<cv::Mat> outputs;
  model.net.forward(outputs, model.output_layers);
  REQUIRE(outputs.size() == 2);
  const cv::Mat& heatmap = outputs[0];  // NCHW: 1 x 80 x 128 x 128
  REQUIRE(heatmap.size[1] == 80);
  REQUIRE(heatmap.size[2] == 128);
  // The strongest cell of the whole heatmap: class 41 (cup) at row 45, column 61.
  double max_score = 0;
  cv::minMaxLoc(heatmap.reshape(1, 80 * 128), nullptr, &max_score);
  CHECK(max_score == Approx(0.4570617377758026).margin(1e-5));
  CHECK(heatmap.ptr<float>(0, 41)[45 * 128 + 61] == Approx(0.4570617377758026).margin(1e-5));
  CHECK(heatmap.ptr<float>(0, 60)[63 * 128 + 63] == Approx(0.4061555862426758).margin(1e-5));
  const double tfjs_wh[] = {102.41400146484375, 153.62413024902344, 106.37255096435547, 147.6158905029297};
  for (int channel = 0; channel < 4; ++channel)
    CHECK(outputs[1].ptr<float>(0, channel)[45 * 128 + 61] == Approx(tfjs_wh[channel]).margin(1e-2));
}

TEST_CASE("malformed tfjs models are reported with the file and the node, never crash") {
  ScratchFolder folder("tfjs-malformed");
  const auto model_json = folder.path() / "tiny.json";
  write_file(folder.path() / "tiny.bin", tiny_weights());
  const auto error_for = [&](const std::string& text, const std::vector<std::string>& outputs = {"out"}) {
    write_file(model_json, text);
    return model_format_error_of([&] { load_tfjs_graph_model(model_json, outputs); });
  };

  CHECK_THAT(model_format_error_of([&] { load_tfjs_graph_model(folder.path() / "absent.json", {"out"}); }),
             Contains("absent.json") && Contains("cannot open"));
  CHECK_THAT(error_for("{\"modelTopology\": {\"node\": ["),
             Contains(model_json.string()) && Contains("not valid JSON"));
  CHECK_THAT(error_for("[1, 2, 3]"), Contains("not a TensorFlow.js graph model"));
  CHECK_THAT(error_for(tiny_model().dump(), {"nowhere"}), Contains("no output node 'nowhere'"));

  json model = tiny_model();
  model["modelTopology"]["node"][3]["input"][0] = "ghost";
  CHECK_THAT(error_for(model.dump()), Contains("node 'conv'") && Contains("'ghost'"));

  model = tiny_model();
  model["modelTopology"]["node"][5].erase("op");
  CHECK_THAT(error_for(model.dump()), Contains("node 'mean' has no op"));

  CHECK_THAT(error_for(tiny_model("UHJlbHU=" /* Prelu */).dump()),
             Contains("node 'conv' (_FusedConv2D)") && Contains("Prelu") && Contains("not supported"));

  model = tiny_model();
  model["modelTopology"]["node"][3]["attr"]["padding"] = {{"s", "not base64!"}};
  CHECK_THAT(error_for(model.dump()), Contains("split from 'conv'") && Contains("attr 'padding'"));

  model = tiny_model();
  model["weightsManifest"][0]["weights"][0]["shape"] = {1, 1, 1, 4000000000000};
  CHECK_THAT(error_for(model.dump()), Contains("weight 'w'") && Contains("truncated shard or wrong shape"));

  model = tiny_model();
  model["weightsManifest"][0]["paths"] = {"gone.bin"};
  CHECK_THAT(error_for(model.dump()), Contains("gone.bin"));

  model = tiny_model();
  model["modelTopology"]["node"][1]["attr"]["value"]["tensor"]["tensorShape"] = tensor_shape_json({2, 1, 1, 1});
  CHECK_THAT(error_for(model.dump()), Contains("Const node 'w'") && Contains("[2,1,1,1]"));

  write_file(folder.path() / "tiny.bin", tiny_weights().substr(0, 7));
  CHECK_THAT(error_for(tiny_model().dump()), Contains("tiny.json") && Contains("truncated"));

  // An op OpenCV has no layer for, when an output needs it.
  write_file(folder.path() / "tiny.bin", tiny_weights());
  CHECK_THAT(error_for(tiny_model().dump(), {"unused"}), Contains("node 'unused'") && Contains("OpenCV"));

  // ConcatV2 whose axis is not a scalar: OpenCV would read past its values.
  model = tiny_model();
  model["modelTopology"]["node"].push_back(
      {{"name", "joined"}, {"op", "ConcatV2"}, {"input", {"x", "x", "axes"}}, {"attr", {{"N", {{"i", "2"}}}}}});
  CHECK_THAT(error_for(model.dump(), {"joined"}), Contains("node 'joined' (ConcatV2)") && Contains("'axes'"));
}
