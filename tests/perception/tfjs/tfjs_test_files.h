// Writing small TensorFlow.js models for the loader's tests: a scratch
// folder, weight bytes, and the first message of a ModelFormatError.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace alplan::test {

// A fresh folder under the system's temp folder, removed with the object;
// the process id keeps concurrent test runs apart.
class ScratchFolder {
 public:
  explicit ScratchFolder(const std::string& purpose);
  ~ScratchFolder();
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

void write_file(const std::filesystem::path& path, std::string_view bytes);
void write_json(const std::filesystem::path& path, const nlohmann::json& value);

// Little-endian element bytes, as tfjs weight shards hold them.
std::string float32_bytes(const std::vector<float>& values);
std::string int32_bytes(const std::vector<std::int32_t>& values);
std::string uint16_bytes(const std::vector<std::uint16_t>& values);
std::string uint8_bytes(const std::vector<std::uint8_t>& values);

// The message of the ModelFormatError `action` throws, or "no error".
// Other exceptions propagate, so the test fails on them.
std::string model_format_error_of(const std::function<void()>& action);

// A JSON TensorShapeProto of `sizes` as tfjs writes it.
nlohmann::json tensor_shape_json(const std::vector<std::int64_t>& sizes);

}  // namespace alplan::test
