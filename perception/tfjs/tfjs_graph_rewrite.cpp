#include "perception/tfjs/tfjs_graph_rewrite.h"

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <string_view>

#include "perception/tfjs/base64.h"
#include "perception/tfjs/model_format_error.h"

namespace alplan::perception {

namespace {

using nlohmann::json;

struct FusedOp {
  std::string_view fused;
  std::string_view plain;
};
const std::array<FusedOp, 3> kFusedOps = {
    {{"_FusedConv2D", "Conv2D"}, {"FusedDepthwiseConv2dNative", "DepthwiseConv2dNative"}, {"_FusedMatMul", "MatMul"}}};

const std::array<std::string_view, 7> kActivations = {"Relu", "Relu6", "Elu", "Selu", "Sigmoid", "Tanh", "LeakyRelu"};

// Attrs that only describe the fusion; the plain op must not carry them.
const std::array<std::string_view, 4> kFusionAttrs = {"fused_ops", "num_args", "epsilon", "leakyrelu_alpha"};

std::vector<std::string> fused_op_names(const TfNode& node, const std::string& where) {
  std::vector<std::string> names;
  const json* list = nullptr;
  if (node.attrs.contains("fused_ops") && node.attrs.at("fused_ops").is_object() &&
      node.attrs.at("fused_ops").contains("list") && node.attrs.at("fused_ops").at("list").is_object())
    list = &node.attrs.at("fused_ops").at("list");
  if (list == nullptr || !list->contains("s")) return names;
  if (!list->at("s").is_array()) throw ModelFormatError(where + ": fused_ops is not a list of strings");
  for (const json& encoded : list->at("s")) {
    auto name = encoded.is_string() ? decode_base64(encoded.get<std::string>()) : std::nullopt;
    if (!name) throw ModelFormatError(where + ": fused_ops holds " + encoded.dump() + ", not base64 text");
    names.push_back(*name);
  }
  return names;
}

json attr_if_present(const json& attrs, const char* name) {
  json picked = json::object();
  if (attrs.contains(name)) picked[name] = attrs.at(name);
  return picked;
}

TfNode bias_add_node(const TfNode& fused, const std::string& name, const std::string& input, const std::string& bias) {
  TfNode node{name, "BiasAdd", {input, bias}, attr_if_present(fused.attrs, "T"), std::nullopt, fused.name};
  if (fused.attrs.contains("data_format")) node.attrs["data_format"] = fused.attrs.at("data_format");
  return node;
}

TfNode activation_node(const TfNode& fused, const std::string& activation, const std::string& input) {
  TfNode node{fused.name, activation, {input}, attr_if_present(fused.attrs, "T"), std::nullopt, fused.name};
  if (activation == "LeakyRelu" && fused.attrs.contains("leakyrelu_alpha"))
    node.attrs["alpha"] = fused.attrs.at("leakyrelu_alpha");
  return node;
}

void split_fused(const TfNode& fused, std::string_view plain_op, std::vector<TfNode>& out, const std::string& source) {
  const std::string where = source + ": node '" + fused.name + "' (" + fused.op + ")";
  const std::vector<std::string> ops = fused_op_names(fused, where);
  const bool bias_then_activation =
      ops.size() == 2 && std::find(kActivations.begin(), kActivations.end(), ops[1]) != kActivations.end();
  if (ops.empty() || ops[0] != "BiasAdd" || (ops.size() > 1 && !bias_then_activation)) {
    std::string listed;
    for (const std::string& op : ops) listed += (listed.empty() ? "" : ", ") + op;
    throw ModelFormatError(where + ": fused_ops [" + listed +
                           "] is not supported (only BiasAdd, optionally followed by one of Relu, Relu6, Elu, Selu, "
                           "Sigmoid, Tanh, LeakyRelu)");
  }
  std::vector<std::string> data_inputs;
  std::vector<std::string> control_inputs;
  for (const std::string& input : fused.inputs)
    (input.starts_with('^') ? control_inputs : data_inputs).push_back(input);
  if (data_inputs.size() != 3)
    throw ModelFormatError(where + ": expected 3 inputs (input, filter, bias), found " +
                           std::to_string(data_inputs.size()));

  TfNode plain{fused.name + "/" + std::string(plain_op),
               std::string(plain_op),
               {data_inputs[0], data_inputs[1]},
               fused.attrs,
               std::nullopt,
               fused.name};
  for (std::string_view attr : kFusionAttrs) plain.attrs.erase(std::string(attr));
  plain.inputs.insert(plain.inputs.end(), control_inputs.begin(), control_inputs.end());
  out.push_back(plain);
  if (!bias_then_activation) {
    out.push_back(bias_add_node(fused, fused.name, plain.name, data_inputs[2]));
    return;
  }
  const std::string bias_name = fused.name + "/BiasAdd";
  out.push_back(bias_add_node(fused, bias_name, plain.name, data_inputs[2]));
  out.push_back(activation_node(fused, ops[1], bias_name));
}

}  // namespace

std::vector<TfNode> unfuse_tfjs_ops(const std::vector<TfNode>& nodes, const std::string& source) {
  std::vector<TfNode> out;
  out.reserve(nodes.size());
  for (const TfNode& node : nodes) {
    const auto fused =
        std::find_if(kFusedOps.begin(), kFusedOps.end(), [&](const FusedOp& op) { return op.fused == node.op; });
    if (fused == kFusedOps.end()) {
      out.push_back(node);
    } else {
      split_fused(node, fused->plain, out, source);
    }
  }
  return out;
}

std::vector<TfNode> nodes_needed_for(const std::vector<TfNode>& nodes, const std::vector<std::string>& outputs,
                                     const std::string& source) {
  std::map<std::string, std::size_t> index_of;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (!index_of.emplace(nodes[i].name, i).second)
      throw ModelFormatError(source + ": two nodes are named '" + nodes[i].name + "'");
  }
  std::vector<bool> needed(nodes.size(), false);
  std::vector<std::size_t> pending;
  for (const std::string& output : outputs) {
    const auto found = index_of.find(producer_name(output));
    if (found == index_of.end()) throw ModelFormatError(source + ": the graph has no output node '" + output + "'");
    pending.push_back(found->second);
  }
  while (!pending.empty()) {
    const std::size_t index = pending.back();
    pending.pop_back();
    if (needed[index]) continue;
    needed[index] = true;
    for (const std::string& input : nodes[index].inputs) {
      const auto found = index_of.find(producer_name(input));
      if (found == index_of.end())
        throw ModelFormatError(source + ": node '" + nodes[index].name + "' reads '" + input +
                               "', which is not a node of the graph");
      pending.push_back(found->second);
    }
  }
  std::vector<TfNode> kept;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (needed[i]) kept.push_back(nodes[i]);
  }
  return kept;
}

}  // namespace alplan::perception
