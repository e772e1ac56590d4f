// Loads a TensorFlow.js graph model (https://www.tensorflow.org/js/guide/
// conversion: model.json holding `modelTopology`, a GraphDef in the proto3
// JSON mapping, and `weightsManifest`, the .bin weight shards) into an
// OpenCV cv::dnn::Net, in C++ alone.
//
// The route: the weights are read and dequantised (tfjs_weights.h) and put
// on the Const nodes as tensors; the tfjs-only fused ops are split into
// plain TensorFlow ops (tfjs_graph_rewrite.h); only the nodes the requested
// outputs need are kept, so post-processing ops OpenCV lacks (TopKV2,
// GatherV2, ...) can be cut off; the result is serialised as a binary
// GraphDef and given to cv::dnn::readNetFromTensorflow.
//
// Every failure is a ModelFormatError naming the file and, where there is
// one, the node or weight: unreadable or malformed JSON, a missing or
// truncated shard, an absurd shape, an op OpenCV cannot import.
#pragma once

#include <filesystem>
#include <opencv2/dnn.hpp>
#include <string>
#include <vector>

#include "perception/tfjs/model_format_error.h"

namespace alplan::perception {

struct TfjsGraphModel {
  cv::dnn::Net net;
  // For each requested output, the name to pass to Net::forward: OpenCV's
  // importer drops Identity nodes, so an Identity output is named by the
  // node it copies.
  std::vector<std::string> output_layers;
};

// `outputs` are node names of the graph (its signature's outputs, or any
// inner node).
TfjsGraphModel load_tfjs_graph_model(const std::filesystem::path& model_json, const std::vector<std::string>& outputs);

// The binary GraphDef load_tfjs_graph_model gives OpenCV, for inspection.
std::string tfjs_model_to_graph_def(const std::filesystem::path& model_json, const std::vector<std::string>& outputs);

}  // namespace alplan::perception
