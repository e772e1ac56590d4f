#include "perception/tfjs/tensorflow_graph.h"

#include <charconv>
#include <cstring>
#include <limits>
#include <utility>

#include "perception/tfjs/base64.h"
#include "perception/tfjs/model_format_error.h"
#include "perception/tfjs/protobuf_writer.h"

namespace alplan::perception {

namespace {

using nlohmann::json;

// Field numbers of the TensorFlow protos written here.
namespace graph_def {
constexpr int kNode = 1;
}
namespace node_def {
constexpr int kName = 1, kOp = 2, kInput = 3, kAttr = 5;
}
namespace map_entry {
constexpr int kKey = 1, kValue = 2;
}
namespace attr_value {
constexpr int kList = 1, kS = 2, kI = 3, kF = 4, kB = 5, kType = 6, kShape = 7, kTensor = 8, kPlaceholder = 9;
}
namespace list_value {
constexpr int kS = 2, kI = 3, kF = 4, kB = 5, kType = 6, kShape = 7, kTensor = 8;
}
namespace tensor_shape {
constexpr int kDim = 2, kUnknownRank = 3;
}
namespace dim {
constexpr int kSize = 1, kName = 2;
}
namespace tensor_proto {
constexpr int kDtype = 1, kShape = 2, kContent = 4, kFloatVal = 5, kIntVal = 7, kBoolVal = 11;
}

struct DataTypeName {
  std::string_view name;
  TfDataType type;
};
const DataTypeName kDataTypeNames[] = {
    {"DT_FLOAT", TfDataType::Float},   {"DT_DOUBLE", TfDataType::Double}, {"DT_INT32", TfDataType::Int32},
    {"DT_UINT8", TfDataType::UInt8},   {"DT_INT16", TfDataType::Int16},   {"DT_INT8", TfDataType::Int8},
    {"DT_STRING", TfDataType::String}, {"DT_INT64", TfDataType::Int64},   {"DT_BOOL", TfDataType::Bool},
    {"DT_UINT16", TfDataType::UInt16}, {"DT_HALF", TfDataType::Half},
};

[[noreturn]] void fail(const std::string& problem) { throw ModelFormatError(problem); }

// proto3 JSON writes int64 as a string, int32 as a number; both are accepted.
std::int64_t json_int64(const json& value) {
  if (value.is_number_integer()) return value.get<std::int64_t>();
  if (value.is_string()) {
    const auto& text = value.get_ref<const std::string&>();
    std::int64_t result = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), result);
    if (error == std::errc() && end == text.data() + text.size()) return result;
  }
  fail("expected an integer, found " + value.dump());
}

float json_float(const json& value) {
  if (value.is_number()) return value.get<float>();
  if (value == "NaN") return std::numeric_limits<float>::quiet_NaN();
  if (value == "Infinity") return std::numeric_limits<float>::infinity();
  if (value == "-Infinity") return -std::numeric_limits<float>::infinity();
  fail("expected a number, found " + value.dump());
}

std::int64_t json_data_type(const json& value) {
  if (value.is_number_integer()) return value.get<std::int64_t>();
  if (value.is_string()) {
    if (auto type = tf_data_type_from_name(value.get_ref<const std::string&>()))
      return static_cast<std::int64_t>(*type);
  }
  fail("unknown data type " + value.dump());
}

std::string json_bytes(const json& value) {
  if (value.is_string()) {
    if (auto bytes = decode_base64(value.get_ref<const std::string&>())) return *bytes;
  }
  fail("expected base64 bytes, found " + value.dump());
}

const json& json_array(const json& object, const char* key) {
  static const json kEmpty = json::array();
  if (!object.contains(key)) return kEmpty;
  const json& value = object.at(key);
  if (!value.is_array()) fail(std::string("\"") + key + "\" is not a list");
  return value;
}

ProtobufWriter encode_shape(const json& shape) {
  if (!shape.is_object()) fail("a shape is not an object: " + shape.dump());
  ProtobufWriter writer;
  for (const json& dimension : json_array(shape, "dim")) {
    if (!dimension.is_object()) fail("a shape dimension is not an object: " + dimension.dump());
    ProtobufWriter dim_writer;
    if (dimension.contains("size")) dim_writer.varint_field(dim::kSize, json_int64(dimension.at("size")));
    if (dimension.contains("name") && dimension.at("name").is_string())
      dim_writer.bytes_field(dim::kName, dimension.at("name").get_ref<const std::string&>());
    writer.message_field(tensor_shape::kDim, dim_writer);
  }
  if (shape.value("unknownRank", false)) writer.bool_field(tensor_shape::kUnknownRank, true);
  return writer;
}

ProtobufWriter encode_tensor(const TfTensor& tensor) {
  ProtobufWriter shape;
  for (std::int64_t size : tensor.shape) {
    ProtobufWriter dim_writer;
    dim_writer.varint_field(dim::kSize, size);
    shape.message_field(tensor_shape::kDim, dim_writer);
  }
  ProtobufWriter writer;
  writer.varint_field(tensor_proto::kDtype, static_cast<std::int64_t>(tensor.dtype));
  writer.message_field(tensor_proto::kShape, shape);
  // TensorFlow writes one-element tensors in the typed value fields, and
  // OpenCV's importer reads some scalars (ConcatV2's axis) only from there.
  if (tensor.dtype == TfDataType::Float && tensor.content.size() == sizeof(float)) {
    float value = 0;
    std::memcpy(&value, tensor.content.data(), sizeof value);
    writer.packed_float_field(tensor_proto::kFloatVal, std::span<const float>(&value, 1));
  } else if (tensor.dtype == TfDataType::Int32 && tensor.content.size() == sizeof(std::int32_t)) {
    std::int32_t value = 0;
    std::memcpy(&value, tensor.content.data(), sizeof value);
    const std::int64_t widened = value;
    writer.packed_varint_field(tensor_proto::kIntVal, std::span<const std::int64_t>(&widened, 1));
  } else if (tensor.dtype == TfDataType::Bool && tensor.content.size() == 1) {
    const std::int64_t value = tensor.content[0] != 0 ? 1 : 0;
    writer.packed_varint_field(tensor_proto::kBoolVal, std::span<const std::int64_t>(&value, 1));
  } else {
    writer.bytes_field(tensor_proto::kContent, tensor.content);
  }
  return writer;
}

// A tensor written inline in JSON (rare in tfjs models: their constants
// live in the weight shards).
ProtobufWriter encode_json_tensor(const json& tensor) {
  if (!tensor.is_object()) fail("a tensor is not an object: " + tensor.dump());
  ProtobufWriter writer;
  if (tensor.contains("dtype")) writer.varint_field(tensor_proto::kDtype, json_data_type(tensor.at("dtype")));
  if (tensor.contains("tensorShape"))
    writer.message_field(tensor_proto::kShape, encode_shape(tensor.at("tensorShape")));
  if (tensor.contains("tensorContent"))
    writer.bytes_field(tensor_proto::kContent, json_bytes(tensor.at("tensorContent")));
  std::vector<float> floats;
  for (const json& value : json_array(tensor, "floatVal")) floats.push_back(json_float(value));
  if (!floats.empty()) writer.packed_float_field(tensor_proto::kFloatVal, floats);
  std::vector<std::int64_t> ints;
  for (const json& value : json_array(tensor, "intVal")) ints.push_back(json_int64(value));
  if (!ints.empty()) writer.packed_varint_field(tensor_proto::kIntVal, ints);
  return writer;
}

ProtobufWriter encode_list(const json& list) {
  if (!list.is_object()) fail("a list is not an object: " + list.dump());
  ProtobufWriter writer;
  for (const json& value : json_array(list, "s")) writer.bytes_field(list_value::kS, json_bytes(value));
  std::vector<std::int64_t> ints;
  for (const json& value : json_array(list, "i")) ints.push_back(json_int64(value));
  if (!ints.empty()) writer.packed_varint_field(list_value::kI, ints);
  std::vector<float> floats;
  for (const json& value : json_array(list, "f")) floats.push_back(json_float(value));
  if (!floats.empty()) writer.packed_float_field(list_value::kF, floats);
  std::vector<std::int64_t> bools;
  for (const json& value : json_array(list, "b")) {
    if (!value.is_boolean()) fail("expected a boolean, found " + value.dump());
    bools.push_back(value.get<bool>() ? 1 : 0);
  }
  if (!bools.empty()) writer.packed_varint_field(list_value::kB, bools);
  std::vector<std::int64_t> types;
  for (const json& value : json_array(list, "type")) types.push_back(json_data_type(value));
  if (!types.empty()) writer.packed_varint_field(list_value::kType, types);
  for (const json& value : json_array(list, "shape")) writer.message_field(list_value::kShape, encode_shape(value));
  for (const json& value : json_array(list, "tensor"))
    writer.message_field(list_value::kTensor, encode_json_tensor(value));
  if (list.contains("func")) fail("function attrs are not supported");
  return writer;
}

ProtobufWriter encode_attr_value(const json& value) {
  if (!value.is_object()) fail("an attr value is not an object: " + value.dump());
  ProtobufWriter writer;
  if (value.contains("list"))
    writer.message_field(attr_value::kList, encode_list(value.at("list")));
  else if (value.contains("s"))
    writer.bytes_field(attr_value::kS, json_bytes(value.at("s")));
  else if (value.contains("i"))
    writer.varint_field(attr_value::kI, json_int64(value.at("i")));
  else if (value.contains("f"))
    writer.float_field(attr_value::kF, json_float(value.at("f")));
  else if (value.contains("b")) {
    if (!value.at("b").is_boolean()) fail("expected a boolean, found " + value.at("b").dump());
    writer.bool_field(attr_value::kB, value.at("b").get<bool>());
  } else if (value.contains("type"))
    writer.varint_field(attr_value::kType, json_data_type(value.at("type")));
  else if (value.contains("shape"))
    writer.message_field(attr_value::kShape, encode_shape(value.at("shape")));
  else if (value.contains("tensor"))
    writer.message_field(attr_value::kTensor, encode_json_tensor(value.at("tensor")));
  else if (value.contains("placeholder") && value.at("placeholder").is_string())
    writer.bytes_field(attr_value::kPlaceholder, value.at("placeholder").get_ref<const std::string&>());
  else if (value.contains("func"))
    fail("function attrs are not supported");
  else if (!value.empty())
    fail("unknown attr value " + value.dump());
  return writer;
}

void write_attr(ProtobufWriter& node, const std::string& name, const ProtobufWriter& value) {
  ProtobufWriter entry;
  entry.bytes_field(map_entry::kKey, name);
  entry.message_field(map_entry::kValue, value);
  node.message_field(node_def::kAttr, entry);
}

ProtobufWriter encode_node(const TfNode& node) {
  ProtobufWriter writer;
  writer.bytes_field(node_def::kName, node.name);
  writer.bytes_field(node_def::kOp, node.op);
  for (const std::string& input : node.inputs) writer.bytes_field(node_def::kInput, input);
  for (const auto& [name, value] : node.attrs.items()) {
    if (node.value && name == "value") continue;
    try {
      write_attr(writer, name, encode_attr_value(value));
    } catch (const ModelFormatError& error) {
      fail("attr '" + name + "': " + error.what());
    }
  }
  if (node.value) {
    ProtobufWriter tensor_attr;
    tensor_attr.message_field(attr_value::kTensor, encode_tensor(*node.value));
    write_attr(writer, "value", tensor_attr);
  }
  return writer;
}

}  // namespace

std::optional<TfDataType> tf_data_type_from_name(std::string_view name) {
  for (const auto& entry : kDataTypeNames) {
    if (entry.name == name) return entry.type;
  }
  return std::nullopt;
}

std::string producer_name(std::string_view input) {
  if (!input.empty() && input.front() == '^') input.remove_prefix(1);
  const auto colon = input.rfind(':');
  if (colon != std::string_view::npos) input = input.substr(0, colon);
  return std::string(input);
}

std::vector<TfNode> nodes_from_json(const json& graph, const std::string& source) {
  if (!graph.is_object() || !graph.contains("node") || !graph.at("node").is_array())
    throw ModelFormatError(source + ": the graph has no list of nodes (\"node\")");
  std::vector<TfNode> nodes;
  for (const json& entry : graph.at("node")) {
    const std::string where = source + ": node " + std::to_string(nodes.size());
    if (!entry.is_object()) throw ModelFormatError(where + " is not an object");
    TfNode node;
    if (!entry.contains("name") || !entry.at("name").is_string()) throw ModelFormatError(where + " has no name");
    node.name = entry.at("name").get<std::string>();
    if (!entry.contains("op") || !entry.at("op").is_string())
      throw ModelFormatError(source + ": node '" + node.name + "' has no op");
    node.op = entry.at("op").get<std::string>();
    if (entry.contains("input")) {
      if (!entry.at("input").is_array())
        throw ModelFormatError(source + ": node '" + node.name + "': input is not a list");
      for (const json& input : entry.at("input")) {
        if (!input.is_string()) throw ModelFormatError(source + ": node '" + node.name + "' has a non-string input");
        node.inputs.push_back(input.get<std::string>());
      }
    }
    if (entry.contains("attr")) {
      if (!entry.at("attr").is_object())
        throw ModelFormatError(source + ": node '" + node.name + "': attr is not an object");
      node.attrs = entry.at("attr");
    }
    nodes.push_back(std::move(node));
  }
  return nodes;
}

std::string encode_graph_def(const std::vector<TfNode>& nodes, const std::string& source) {
  ProtobufWriter graph;
  for (const TfNode& node : nodes) {
    try {
      graph.message_field(graph_def::kNode, encode_node(node));
    } catch (const std::exception& error) {
      const std::string origin = node.split_from.empty() ? "" : " (split from '" + node.split_from + "')";
      throw ModelFormatError(source + ": node '" + node.name + "'" + origin + ": " + error.what());
    }
  }
  return graph.bytes();
}

}  // namespace alplan::perception
