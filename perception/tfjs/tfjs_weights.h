// The weights of a TensorFlow.js model: model.json's `weightsManifest` lists
// groups of binary shards; each group's shards, concatenated in order, hold
// its weights one after another, little-endian, each as many elements as
// its shape says. Follows tfjs-core's io/io_utils decodeWeights: float32,
// int32 and bool weights, and weights quantised by the converter
// (`quantization.dtype` uint8 or uint16 with value = q * scale + min,
// rounded for int32 weights; or float16) restored to their original type.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "perception/tfjs/tensorflow_graph.h"

namespace alplan::perception {

// Every weight of `manifest`, by name, as a float32, int32 or bool tensor;
// shard paths are relative to the folder of `model_json`. Throws
// ModelFormatError naming model_json and the weight or shard when the
// manifest is malformed, a shard is missing or holds fewer (or more) bytes
// than the weights need, or a shape is negative or absurd.
std::map<std::string, TfTensor> read_tfjs_weights(const nlohmann::json& manifest,
                                                  const std::filesystem::path& model_json);

// IEEE 754 binary16 -> binary32, exact (subnormals, infinities, NaN).
float half_to_float(std::uint16_t half);

}  // namespace alplan::perception
