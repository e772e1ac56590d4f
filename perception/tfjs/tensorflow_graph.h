// A TensorFlow graph as plain data, read from the proto3 JSON mapping of a
// GraphDef (what TensorFlow.js keeps in model.json's `modelTopology`) and
// written as a binary GraphDef (tensorflow/core/framework/graph.proto,
// node_def.proto, attr_value.proto, tensor.proto, tensor_shape.proto) for
// OpenCV's TensorFlow importer.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace alplan::perception {

// The values of TensorFlow's DataType enum (types.proto) the loader meets.
enum class TfDataType : int {
  Float = 1,
  Double = 2,
  Int32 = 3,
  UInt8 = 4,
  Int16 = 5,
  Int8 = 6,
  String = 7,
  Int64 = 9,
  Bool = 10,
  UInt16 = 17,
  Half = 19,
};

// "DT_FLOAT" -> Float; nothing for names outside the table above.
std::optional<TfDataType> tf_data_type_from_name(std::string_view name);

// A constant tensor: its element bytes are little-endian, as in
// TensorProto.tensor_content.
struct TfTensor {
  TfDataType dtype = TfDataType::Float;
  std::vector<std::int64_t> shape;
  std::string content;
};

struct TfNode {
  std::string name;
  std::string op;
  // "node", "node:1" (the second output) or "^node" (a control input).
  std::vector<std::string> inputs;
  // name -> AttrValue in the proto3 JSON mapping, as model.json holds them.
  nlohmann::json attrs = nlohmann::json::object();
  // A Const's tensor; written as its "value" attr in place of any there.
  std::optional<TfTensor> value;
  // The model's node this one was split from by a rewrite, for messages;
  // empty if it is the model's own.
  std::string split_from;
};

// The node a tensor reference names: "n:1" -> "n", "^n" -> "n".
std::string producer_name(std::string_view input);

// Reads `graph["node"]`. Throws ModelFormatError naming `source` and the
// node when a node is not an object with a string name and op, a list of
// string inputs and an object of attrs.
std::vector<TfNode> nodes_from_json(const nlohmann::json& graph, const std::string& source);

// The binary GraphDef of `nodes`. Throws ModelFormatError naming `source`,
// the node and the attr when an attr value is not valid AttrValue JSON or
// uses something not written here (function attrs).
std::string encode_graph_def(const std::vector<TfNode>& nodes, const std::string& source);

}  // namespace alplan::perception
