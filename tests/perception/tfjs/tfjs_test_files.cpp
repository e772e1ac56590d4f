#include "tests/perception/tfjs/tfjs_test_files.h"

#include <unistd.h>

#include <cstring>
#include <fstream>
#include <stdexcept>

#include "perception/tfjs/model_format_error.h"

namespace alplan::test {

namespace {

template <typename Value>
std::string element_bytes(const std::vector<Value>& values) {
  std::string out;
  for (Value value : values) {
    char raw[sizeof(Value)];
    std::memcpy(raw, &value, sizeof(Value));
    out.append(raw, sizeof(Value));
  }
  return out;
}

}  // namespace

ScratchFolder::ScratchFolder(const std::string& purpose)
    : path_(std::filesystem::temp_directory_path() / ("alplan-" + purpose + "-" + std::to_string(::getpid()))) {
  std::filesystem::remove_all(path_);
  std::filesystem::create_directories(path_);
}

ScratchFolder::~ScratchFolder() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

void write_file(const std::filesystem::path& path, std::string_view bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

void write_json(const std::filesystem::path& path, const nlohmann::json& value) { write_file(path, value.dump(1)); }

std::string float32_bytes(const std::vector<float>& values) { return element_bytes(values); }
std::string int32_bytes(const std::vector<std::int32_t>& values) { return element_bytes(values); }
std::string uint16_bytes(const std::vector<std::uint16_t>& values) { return element_bytes(values); }
std::string uint8_bytes(const std::vector<std::uint8_t>& values) { return element_bytes(values); }

std::string model_format_error_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const perception::ModelFormatError& error) {
    return error.what();
  }
  return "no error";
}

nlohmann::json tensor_shape_json(const std::vector<std::int64_t>& sizes) {
  nlohmann::json dims = nlohmann::json::array();
  for (std::int64_t size : sizes) dims.push_back({{"size", std::to_string(size)}});
  return {{"dim", dims}};
}

}  // namespace alplan::test
