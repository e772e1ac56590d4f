#include "perception/tfjs/tfjs_weights.h"

#include <catch2/catch.hpp>
#include <cstring>

#include "perception/tfjs/model_format_error.h"
#include "tests/perception/tfjs/tfjs_test_files.h"

using namespace alplan::perception;
using alplan::test::ScratchFolder;
using Catch::Matchers::Contains;
using nlohmann::json;

namespace {

template <typename Value>
std::vector<Value> values_of(const TfTensor& tensor) {
  std::vector<Value> values(tensor.content.size() / sizeof(Value));
  std::memcpy(values.data(), tensor.content.data(), values.size() * sizeof(Value));
  return values;
}

json weight(const std::string& name, const std::vector<std::int64_t>& shape, const std::string& dtype) {
  return {{"name", name}, {"shape", shape}, {"dtype", dtype}};
}

}  // namespace

TEST_CASE("tfjs weights are read across shards and restored from their quantisation") {
  ScratchFolder folder("tfjs-weights");
  using namespace alplan::test;
  const std::string bytes = float32_bytes({1.5F, -2.0F}) + int32_bytes({7, -1, 100000}) + uint8_bytes({0, 2, 255}) +
                            uint16_bytes({1500, 65535}) + uint8_bytes({4, 3}) + uint16_bytes({0x3C00, 0xC000}) +
                            uint8_bytes({1, 0}) + float32_bytes({0.25F});
  // The split falls inside the int32 weight: shards are one byte stream.
  write_file(folder.path() / "group1-shard1of2.bin", bytes.substr(0, 13));
  write_file(folder.path() / "group1-shard2of2.bin", bytes.substr(13));
  json q8 = weight("q8", {3}, "float32");
  q8["quantization"] = {{"dtype", "uint8"}, {"min", -1.0}, {"scale", 0.5}, {"original_dtype", "float32"}};
  json q16 = weight("q16", {2}, "float32");
  q16["quantization"] = {{"dtype", "uint16"}, {"min", 0.0}, {"scale", 0.001}};
  json q8_int = weight("q8_int", {2}, "int32");
  q8_int["quantization"] = {{"dtype", "uint8"}, {"min", 0.0}, {"scale", 0.4}};
  json half = weight("half", {2, 1}, "float32");
  half["quantization"] = {{"dtype", "float16"}};
  const json manifest = json::array({{{"paths", {"group1-shard1of2.bin", "group1-shard2of2.bin"}},
                                      {"weights",
                                       {weight("f", {2}, "float32"), weight("i", {3}, "int32"), q8, q16, q8_int, half,
                                        weight("flags", {2}, "bool"), weight("scalar", {}, "float32")}}}});

  const auto weights = read_tfjs_weights(manifest, folder.path() / "model.json");
  REQUIRE(weights.size() == 8);
  CHECK(values_of<float>(weights.at("f")) == std::vector<float>{1.5F, -2.0F});
  CHECK(weights.at("i").dtype == TfDataType::Int32);
  CHECK(values_of<std::int32_t>(weights.at("i")) == std::vector<std::int32_t>{7, -1, 100000});
  CHECK(values_of<float>(weights.at("q8")) == std::vector<float>{-1.0F, 0.0F, 126.5F});
  const auto q16_values = values_of<float>(weights.at("q16"));
  REQUIRE(q16_values.size() == 2);
  CHECK(q16_values[0] == Approx(1.5F));
  CHECK(q16_values[1] == Approx(65.535F));
  // int32 weights quantised to uint8 are rounded back (1.6 -> 2, 1.2 -> 1).
  CHECK(weights.at("q8_int").dtype == TfDataType::Int32);
  CHECK(values_of<std::int32_t>(weights.at("q8_int")) == std::vector<std::int32_t>{2, 1});
  CHECK(values_of<float>(weights.at("half")) == std::vector<float>{1.0F, -2.0F});
  CHECK(weights.at("half").shape == std::vector<std::int64_t>{2, 1});
  CHECK(weights.at("flags").dtype == TfDataType::Bool);
  CHECK(weights.at("flags").content == std::string("\x01\x00", 2));
  CHECK(weights.at("scalar").shape.empty());
  CHECK(values_of<float>(weights.at("scalar")) == std::vector<float>{0.25F});
}

TEST_CASE("malformed weight manifests and shards are reported with the file and the weight") {
  ScratchFolder folder("tfjs-bad-weights");
  using namespace alplan::test;
  const auto model_json = folder.path() / "model.json";
  write_file(folder.path() / "w.bin", float32_bytes({1, 2, 3, 4}));
  const auto error_for = [&](const json& weights, const json& paths = json::array({"w.bin"})) {
    return model_format_error_of([&] {
      read_tfjs_weights(json::array({{{"paths", paths}, {"weights", weights}}}), model_json);
    });
  };

  CHECK_THAT(error_for(json::array({weight("a", {4}, "float32")}), json::array({"missing.bin"})),
             Contains(model_json.string()) && Contains("missing.bin"));
  CHECK_THAT(error_for(json::array({weight("a", {2}, "float32"), weight("b", {3}, "float32")})),
             Contains("weight 'b'") && Contains("truncated"));
  CHECK_THAT(error_for(json::array({weight("huge", {1000000000, 1000000000, 1000000000}, "float32")})),
             Contains("weight 'huge'"));
  CHECK_THAT(error_for(json::array({weight("neg", {-4}, "float32")})), Contains("weight 'neg'") && Contains(">= 0"));
  CHECK_THAT(error_for(json::array({weight("a", {3}, "float32")})), Contains("4 bytes more"));
  CHECK_THAT(error_for(json::array({weight("s", {4}, "string")})),
             Contains("weight 's'") && Contains("unsupported dtype"));
  json no_scale = weight("q", {16}, "float32");
  no_scale["quantization"] = {{"dtype", "uint8"}, {"min", 0}};
  CHECK_THAT(error_for(json::array({no_scale})), Contains("weight 'q'") && Contains("min and scale"));
  CHECK_THAT(error_for(json::array({weight("a", {2}, "float32"), weight("a", {2}, "float32")})),
             Contains("listed twice"));
  CHECK_THAT(error_for(json::array({{{"shape", {4}}}})), Contains("no name"));
  CHECK_THAT(model_format_error_of([&] { read_tfjs_weights(json::object(), model_json); }), Contains("not a list"));
}
