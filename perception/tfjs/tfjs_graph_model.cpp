#include "perception/tfjs/tfjs_graph_model.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>

#include "perception/tfjs/tensorflow_graph.h"
#include "perception/tfjs/tfjs_graph_rewrite.h"
#include "perception/tfjs/tfjs_weights.h"

namespace alplan::perception {

namespace {

using nlohmann::json;

json read_model_json(const std::filesystem::path& model_json) {
  std::ifstream in(model_json, std::ios::binary);
  if (!in) throw ModelFormatError(model_json.string() + ": cannot open the model file");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  json model;
  try {
    model = json::parse(text);
  } catch (const json::parse_error& error) {
    throw ModelFormatError(model_json.string() + ": not valid JSON: " + error.what());
  }
  if (!model.is_object() || !model.contains("modelTopology") || !model.at("modelTopology").is_object() ||
      !model.at("modelTopology").contains("node"))
    throw ModelFormatError(model_json.string() +
                           ": not a TensorFlow.js graph model (no modelTopology holding a GraphDef)");
  if (!model.contains("weightsManifest")) throw ModelFormatError(model_json.string() + ": no weightsManifest");
  return model;
}

// The shape a Const node declares for its value, if it declares one.
std::optional<std::vector<std::int64_t>> declared_shape(const TfNode& node) {
  const json& attrs = node.attrs;
  if (!attrs.contains("value") || !attrs.at("value").is_object() || !attrs.at("value").contains("tensor")) return {};
  const json& tensor = attrs.at("value").at("tensor");
  if (!tensor.is_object() || !tensor.contains("tensorShape") || !tensor.at("tensorShape").is_object()) return {};
  std::vector<std::int64_t> shape;
  const json& shape_json = tensor.at("tensorShape");
  if (!shape_json.contains("dim")) return shape;
  if (!shape_json.at("dim").is_array()) return {};
  for (const json& dim : shape_json.at("dim")) {
    const json size = dim.is_object() ? dim.value("size", json("0")) : json();
    if (size.is_string())
      shape.push_back(std::stoll(size.get<std::string>()));
    else if (size.is_number_integer())
      shape.push_back(size.get<std::int64_t>());
    else
      return {};
  }
  return shape;
}

std::string shape_text(const std::vector<std::int64_t>& shape) {
  std::string text = "[";
  for (std::size_t i = 0; i < shape.size(); ++i) text += (i ? "," : "") + std::to_string(shape[i]);
  return text + "]";
}

void attach_weights(std::vector<TfNode>& nodes, std::map<std::string, TfTensor>& weights, const std::string& source) {
  for (TfNode& node : nodes) {
    if (node.op != "Const") continue;
    const auto weight = weights.find(node.name);
    if (weight == weights.end()) {
      const bool inline_content = node.attrs.contains("value") && node.attrs.at("value").is_object() &&
                                  node.attrs.at("value").contains("tensor") &&
                                  node.attrs.at("value").at("tensor").is_object() &&
                                  (node.attrs.at("value").at("tensor").contains("tensorContent") ||
                                   node.attrs.at("value").at("tensor").contains("floatVal") ||
                                   node.attrs.at("value").at("tensor").contains("intVal"));
      if (inline_content) continue;
      throw ModelFormatError(source + ": Const node '" + node.name + "' has no weight in the weightsManifest");
    }
    std::optional<std::vector<std::int64_t>> shape;
    try {
      shape = declared_shape(node);
    } catch (const std::exception&) {
      throw ModelFormatError(source + ": Const node '" + node.name + "' declares a malformed shape");
    }
    if (shape && *shape != weight->second.shape)
      throw ModelFormatError(source + ": Const node '" + node.name + "' declares shape " + shape_text(*shape) +
                             " but its weight has shape " + shape_text(weight->second.shape));
    node.value = std::move(weight->second);
    node.attrs["dtype"] = json{{"type", static_cast<int>(node.value->dtype)}};
    weights.erase(weight);
  }
}

// The OpenCV layer computing `output`. OpenCV's importer maps an Identity to
// the layer it copies, and folds a BiasAdd into the convolution or matrix
// product before it, whose name the merged layer keeps.
std::string layer_computing(const std::vector<TfNode>& nodes, const std::string& requested) {
  std::string output = requested;
  const auto node_named = [&](const std::string& name) {
    return std::find_if(nodes.begin(), nodes.end(), [&](const TfNode& n) { return n.name == name; });
  };
  for (std::size_t hops = 0; hops <= nodes.size(); ++hops) {
    const auto node = node_named(output);
    if (node == nodes.end() || node->inputs.empty()) return output;
    const std::string input = producer_name(node->inputs.front());
    const auto producer = node_named(input);
    const bool folded_bias =
        node->op == "BiasAdd" && producer != nodes.end() &&
        (producer->op == "Conv2D" || producer->op == "DepthwiseConv2dNative" || producer->op == "MatMul");
    if (node->op != "Identity" && !folded_bias) return output;
    output = input;
  }
  return output;
}

// OpenCV's importer reads some axes as `int_val(0)` of a Const without
// checking that it exists (Concat, ConcatV2, ExpandDims); a file giving
// anything else must be refused here rather than crash there.
void check_constant_axes(const std::vector<TfNode>& nodes, const std::string& source) {
  for (const TfNode& node : nodes) {
    std::optional<std::size_t> axis_input;
    if (node.op == "ConcatV2" && !node.inputs.empty()) axis_input = node.inputs.size() - 1;
    if (node.op == "Concat" && !node.inputs.empty()) axis_input = 0;
    if (node.op == "ExpandDims" && node.inputs.size() > 1) axis_input = 1;
    if (!axis_input) continue;
    const std::string axis = producer_name(node.inputs[*axis_input]);
    const auto producer = std::find_if(nodes.begin(), nodes.end(), [&](const TfNode& n) { return n.name == axis; });
    const bool scalar = producer != nodes.end() && producer->op == "Const" && producer->value &&
                        producer->value->dtype == TfDataType::Int32 &&
                        producer->value->content.size() == sizeof(std::int32_t);
    if (!scalar)
      throw ModelFormatError(source + ": node '" + node.name + "' (" + node.op + "): its axis '" + axis +
                             "' is not a one-element int32 constant");
  }
}

std::vector<TfNode> importable_nodes(const std::filesystem::path& model_json, const std::vector<std::string>& outputs) {
  const std::string source = model_json.string();
  const json model = read_model_json(model_json);
  std::vector<TfNode> nodes = nodes_from_json(model.at("modelTopology"), source);
  auto weights = read_tfjs_weights(model.at("weightsManifest"), model_json);
  attach_weights(nodes, weights, source);
  // Pruning first keeps errors about dangling inputs on the model's own names.
  std::vector<TfNode> needed = unfuse_tfjs_ops(nodes_needed_for(nodes, outputs, source), source);
  check_constant_axes(needed, source);
  return needed;
}

}  // namespace

std::string tfjs_model_to_graph_def(const std::filesystem::path& model_json, const std::vector<std::string>& outputs) {
  return encode_graph_def(importable_nodes(model_json, outputs), model_json.string());
}

TfjsGraphModel load_tfjs_graph_model(const std::filesystem::path& model_json, const std::vector<std::string>& outputs) {
  const std::vector<TfNode> nodes = importable_nodes(model_json, outputs);
  const std::string graph_def = encode_graph_def(nodes, model_json.string());
  TfjsGraphModel model;
  try {
    model.net = cv::dnn::readNetFromTensorflow(graph_def.data(), graph_def.size());
  } catch (const cv::Exception& error) {
    throw ModelFormatError(model_json.string() + ": OpenCV cannot import the graph: " + error.what());
  }
  // OpenCV creates layers lazily; an op it lacks would otherwise surface
  // only at the first forward pass.
  for (const std::string& layer : model.net.getLayerNames()) {
    try {
      model.net.getLayer(layer);
    } catch (const cv::Exception& error) {
      throw ModelFormatError(model_json.string() + ": node '" + layer +
                             "': OpenCV has no layer for it: " + error.what());
    }
  }
  for (const std::string& output : outputs) model.output_layers.push_back(layer_computing(nodes, output));
  return model;
}

}  // namespace alplan::perception
