// Graph rewrites that turn a TensorFlow.js graph into one a plain TensorFlow
// importer (OpenCV's) can read.
//
// TensorFlow's grappler and the tfjs converter fuse a convolution with its
// bias and activation into ops only tfjs executes; their definitions are in
// tfjs-converter's src/operations/op_list (convolution.json, matrices.json):
//   _FusedConv2D(x, filter, bias) {fused_ops: [BiasAdd, Relu]}
//     -> Relu(BiasAdd(Conv2D(x, filter), bias))
// and likewise FusedDepthwiseConv2dNative -> DepthwiseConv2dNative and
// _FusedMatMul -> MatMul. The bias is the fused node's third input.
#pragma once

#include <string>
#include <vector>

#include "perception/tfjs/tensorflow_graph.h"

namespace alplan::perception {

// Every fused op split into its plain ops; the last of them keeps the fused
// node's name, so consumers are unchanged. Activations after BiasAdd: Relu,
// Relu6, Elu, Selu, Sigmoid, Tanh, LeakyRelu. Throws ModelFormatError naming
// `source` and the node for other fusions (Prelu, FusedBatchNorm) or a
// fused node without its bias input.
std::vector<TfNode> unfuse_tfjs_ops(const std::vector<TfNode>& nodes, const std::string& source);

// The nodes `outputs` depend on (through data and control inputs), in their
// original order; `outputs` are node names. Throws ModelFormatError naming
// `source` when an output or an input is not a node of the graph, or a
// name is used twice.
std::vector<TfNode> nodes_needed_for(const std::vector<TfNode>& nodes, const std::vector<std::string>& outputs,
                                     const std::string& source);

}  // namespace alplan::perception
