#include "perception/tfjs/tfjs_weights.h"

#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <optional>
#include <span>
#include <vector>

#include "perception/tfjs/model_format_error.h"

namespace alplan::perception {

namespace {

using nlohmann::json;

// Weights are copied as raw little-endian bytes.
static_assert(std::endian::native == std::endian::little, "the tfjs weight reader assumes a little-endian host");

struct Quantization {
  std::string dtype;  // uint8, uint16 or float16
  double min = 0;
  double scale = 1;
};

struct WeightSpec {
  std::string name;
  std::vector<std::int64_t> shape;
  std::string dtype;  // float32, int32 or bool
  std::optional<Quantization> quantization;
};

std::size_t stored_element_size(const WeightSpec& spec) {
  if (spec.quantization) return spec.quantization->dtype == "uint8" ? 1 : 2;
  return spec.dtype == "bool" ? 1 : 4;
}

Quantization parse_quantization(const json& entry, const std::string& dtype, const std::string& where) {
  if (!entry.is_object() || !entry.contains("dtype") || !entry.at("dtype").is_string())
    throw ModelFormatError(where + ": quantization has no dtype");
  Quantization quantization;
  quantization.dtype = entry.at("dtype").get<std::string>();
  if (quantization.dtype == "uint8" || quantization.dtype == "uint16") {
    if (!entry.contains("min") || !entry.at("min").is_number() || !entry.contains("scale") ||
        !entry.at("scale").is_number())
      throw ModelFormatError(where + ": " + quantization.dtype + " quantization needs numeric min and scale");
    quantization.min = entry.at("min").get<double>();
    quantization.scale = entry.at("scale").get<double>();
    if (dtype != "float32" && dtype != "int32")
      throw ModelFormatError(where + ": " + quantization.dtype + " quantization of a " + dtype + " weight");
  } else if (quantization.dtype == "float16") {
    if (dtype != "float32") throw ModelFormatError(where + ": float16 quantization of a " + dtype + " weight");
  } else {
    throw ModelFormatError(where + ": unsupported quantization dtype '" + quantization.dtype + "'");
  }
  return quantization;
}

WeightSpec parse_spec(const json& entry, const std::string& source) {
  if (!entry.is_object() || !entry.contains("name") || !entry.at("name").is_string())
    throw ModelFormatError(source + ": a weight of the manifest has no name");
  WeightSpec spec;
  spec.name = entry.at("name").get<std::string>();
  const std::string where = source + ": weight '" + spec.name + "'";
  if (!entry.contains("shape") || !entry.at("shape").is_array()) throw ModelFormatError(where + " has no shape");
  for (const json& size : entry.at("shape")) {
    if (!size.is_number_integer() || size.get<std::int64_t>() < 0)
      throw ModelFormatError(where + ": shape " + entry.at("shape").dump() + " is not a list of sizes >= 0");
    spec.shape.push_back(size.get<std::int64_t>());
  }
  if (!entry.contains("dtype") || !entry.at("dtype").is_string()) throw ModelFormatError(where + " has no dtype");
  spec.dtype = entry.at("dtype").get<std::string>();
  if (spec.dtype != "float32" && spec.dtype != "int32" && spec.dtype != "bool")
    throw ModelFormatError(where + ": unsupported dtype '" + spec.dtype + "'");
  if (entry.contains("quantization"))
    spec.quantization = parse_quantization(entry.at("quantization"), spec.dtype, where);
  return spec;
}

// The bytes of a group's shards, concatenated in order.
std::string read_shards(const json& group, const std::filesystem::path& model_json) {
  const std::string source = model_json.string();
  if (!group.is_object() || !group.contains("paths") || !group.at("paths").is_array())
    throw ModelFormatError(source + ": a weights group has no list of shard paths");
  std::string bytes;
  for (const json& path : group.at("paths")) {
    if (!path.is_string()) throw ModelFormatError(source + ": a shard path is not a string");
    const std::filesystem::path shard = model_json.parent_path() / path.get<std::string>();
    std::ifstream in(shard, std::ios::binary);
    if (!in) throw ModelFormatError(source + ": cannot read weight shard " + shard.string());
    bytes.append(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    if (in.bad()) throw ModelFormatError(source + ": error reading weight shard " + shard.string());
  }
  return bytes;
}

// Elements in `shape`; nothing if the count overflows 64 bits.
std::optional<std::uint64_t> element_count(const std::vector<std::int64_t>& shape) {
  std::uint64_t count = 1;
  for (std::int64_t size : shape) {
    if (__builtin_mul_overflow(count, static_cast<std::uint64_t>(size), &count)) return std::nullopt;
  }
  return count;
}

template <typename Stored>
std::vector<Stored> stored_values(std::string_view bytes) {
  std::vector<Stored> values(bytes.size() / sizeof(Stored));
  std::memcpy(values.data(), bytes.data(), values.size() * sizeof(Stored));
  return values;
}

template <typename Value>
std::string as_bytes(const std::vector<Value>& values) {
  return std::string(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(Value));
}

template <typename Stored>
std::string dequantize_affine(std::string_view bytes, const WeightSpec& spec) {
  const auto stored = stored_values<Stored>(bytes);
  const Quantization& q = *spec.quantization;
  if (spec.dtype == "int32") {
    std::vector<std::int32_t> values;
    for (Stored v : stored) values.push_back(static_cast<std::int32_t>(std::lround(v * q.scale + q.min)));
    return as_bytes(values);
  }
  std::vector<float> values;
  for (Stored v : stored) values.push_back(static_cast<float>(v * q.scale + q.min));
  return as_bytes(values);
}

TfTensor decode_weight(const WeightSpec& spec, std::string_view bytes) {
  TfTensor tensor;
  tensor.shape = spec.shape;
  tensor.dtype = spec.dtype == "int32"  ? TfDataType::Int32
                 : spec.dtype == "bool" ? TfDataType::Bool
                                        : TfDataType::Float;
  if (!spec.quantization) {
    tensor.content = std::string(bytes);
  } else if (spec.quantization->dtype == "uint8") {
    tensor.content = dequantize_affine<std::uint8_t>(bytes, spec);
  } else if (spec.quantization->dtype == "uint16") {
    tensor.content = dequantize_affine<std::uint16_t>(bytes, spec);
  } else {
    std::vector<float> values;
    for (std::uint16_t half : stored_values<std::uint16_t>(bytes)) values.push_back(half_to_float(half));
    tensor.content = as_bytes(values);
  }
  return tensor;
}

}  // namespace

float half_to_float(std::uint16_t half) {
  const std::uint32_t sign = static_cast<std::uint32_t>(half & 0x8000U) << 16U;
  const std::uint32_t exponent = (half >> 10U) & 0x1FU;
  const std::uint32_t mantissa = half & 0x3FFU;
  if (exponent == 0) {
    // Zero or subnormal: mantissa * 2^-24.
    const float magnitude = std::ldexp(static_cast<float>(mantissa), -24);
    return sign ? -magnitude : magnitude;
  }
  if (exponent == 0x1F) return std::bit_cast<float>(sign | 0x7F800000U | (mantissa << 13U));
  return std::bit_cast<float>(sign | ((exponent + 112U) << 23U) | (mantissa << 13U));
}

std::map<std::string, TfTensor> read_tfjs_weights(const json& manifest, const std::filesystem::path& model_json) {
  const std::string source = model_json.string();
  if (!manifest.is_array()) throw ModelFormatError(source + ": weightsManifest is not a list");
  std::map<std::string, TfTensor> weights;
  for (const json& group : manifest) {
    const std::string bytes = read_shards(group, model_json);
    if (!group.contains("weights") || !group.at("weights").is_array())
      throw ModelFormatError(source + ": a weights group has no list of weights");
    std::size_t offset = 0;
    for (const json& entry : group.at("weights")) {
      const WeightSpec spec = parse_spec(entry, source);
      const std::string where = source + ": weight '" + spec.name + "'";
      const auto count = element_count(spec.shape);
      const std::uint64_t available = (bytes.size() - offset) / stored_element_size(spec);
      if (!count || *count > available)
        throw ModelFormatError(where + " of shape " + entry.at("shape").dump() +
                               " needs more bytes than the shards hold (" + std::to_string(bytes.size() - offset) +
                               " left at offset " + std::to_string(offset) + "): truncated shard or wrong shape");
      const std::size_t size = *count * stored_element_size(spec);
      if (!weights.emplace(spec.name, decode_weight(spec, std::string_view(bytes).substr(offset, size))).second)
        throw ModelFormatError(where + " is listed twice");
      offset += size;
    }
    if (offset != bytes.size())
      throw ModelFormatError(source + ": the shards of a weights group hold " + std::to_string(bytes.size() - offset) +
                             " bytes more than its weights need");
  }
  return weights;
}

}  // namespace alplan::perception
