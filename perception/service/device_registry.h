// The wristbands the service accepts readings from, each with its bearer
// token and the senior who wears it. A device proves who it is with
// "Authorization: Bearer <token>"; a stranger on the network without a token
// cannot add readings, and a device cannot post readings in another's name.
//
// The tokens file, one device a line, fields separated by spaces or tabs:
//
//   # device   token                              senior
//   wb-01      4f1c0c6e2b0d4a7f9e3d8b5a1c2e7f60    alice
//
// Blank lines and lines starting with '#' are skipped. The device id follows
// the firmware's rule (1-32 of [A-Za-z0-9._-]); the token is 16-128 of the
// RFC 6750 token characters [A-Za-z0-9._~+/=-]; the senior 1-64 of
// [A-Za-z0-9._-]. Device ids and tokens are unique. Errors name the file and
// line: "tokens.txt:3: error: token too short (need at least 16 characters)".
#pragma once

#include <cstddef>
#include <filesystem>
#include <iosfwd>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace alplan::perception::service {

struct Device {
  std::string id;
  std::string token;
  std::string senior;
};

inline constexpr std::size_t kMaxTokenLength = 128;

class DeviceRegistryError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Equal length and bytes, in time that depends only on the lengths, so the
// time a comparison takes does not tell an attacker how much of a guess was
// right.
bool tokens_equal(std::string_view a, std::string_view b);

class DeviceRegistry {
 public:
  DeviceRegistry() = default;
  // Throws DeviceRegistryError on an invalid or repeated device or token.
  explicit DeviceRegistry(std::vector<Device> devices);

  // The device this token belongs to, or null. Compares the token with every
  // device's in constant time and does not stop at a match. A token over
  // kMaxTokenLength is refused before any comparison, since the comparison's
  // cost grows with the presented token's length.
  const Device* authenticate(std::string_view token) const;
  const Device* find(std::string_view device_id) const;

  const std::vector<Device>& devices() const { return devices_; }
  std::size_t size() const { return devices_.size(); }

 private:
  std::vector<Device> devices_;
};

// `source` names the input in messages. Throws DeviceRegistryError.
DeviceRegistry read_device_registry(std::istream& in, const std::string& source);
DeviceRegistry read_device_registry_file(const std::filesystem::path& path);
void write_device_registry(std::ostream& out, const DeviceRegistry& registry);

}  // namespace alplan::perception::service
