#include "perception/service/device_registry.h"

#include <fstream>
#include <ostream>
#include <set>
#include <sstream>

namespace alplan::perception::service {
namespace {

bool is_id_character(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '_' ||
         c == '-';
}

bool is_token_character(char c) { return is_id_character(c) || c == '~' || c == '+' || c == '/' || c == '='; }

template <typename Predicate>
bool all_of(std::string_view text, Predicate predicate) {
  for (const char c : text) {
    if (!predicate(c)) return false;
  }
  return true;
}

// Empty when the device is valid, otherwise what is wrong with it.
std::string device_problem(const Device& d) {
  if (d.id.empty() || d.id.size() > 32 || !all_of(d.id, is_id_character)) {
    return "device id '" + d.id + "' must be 1-32 of [A-Za-z0-9._-]";
  }
  if (d.token.size() < 16) return "token too short (need at least 16 characters)";
  if (d.token.size() > kMaxTokenLength) {
    return "token too long (at most " + std::to_string(kMaxTokenLength) + " characters)";
  }
  if (!all_of(d.token, is_token_character)) return "token may hold only [A-Za-z0-9._~+/=-]";
  if (d.senior.empty() || d.senior.size() > 64 || !all_of(d.senior, is_id_character)) {
    return "senior '" + d.senior + "' must be 1-64 of [A-Za-z0-9._-]";
  }
  return {};
}

}  // namespace

bool tokens_equal(std::string_view a, std::string_view b) {
  // Walk the longer one whole so unequal lengths take as long as equal ones.
  const std::size_t n = a.size() > b.size() ? a.size() : b.size();
  unsigned difference = a.size() == b.size() ? 0U : 1U;
  for (std::size_t i = 0; i < n; ++i) {
    const unsigned char x = i < a.size() ? static_cast<unsigned char>(a[i]) : 0;
    const unsigned char y = i < b.size() ? static_cast<unsigned char>(b[i]) : 0;
    difference |= static_cast<unsigned>(x ^ y);
  }
  // Read through a volatile so the compiler cannot turn the loop into an early exit.
  volatile unsigned result = difference;
  return result == 0;
}

DeviceRegistry::DeviceRegistry(std::vector<Device> devices) : devices_(std::move(devices)) {
  std::set<std::string> ids, tokens;
  for (const Device& d : devices_) {
    if (const std::string problem = device_problem(d); !problem.empty()) throw DeviceRegistryError(problem);
    if (!ids.insert(d.id).second) throw DeviceRegistryError("device '" + d.id + "' is listed twice");
    if (!tokens.insert(d.token).second) throw DeviceRegistryError("device '" + d.id + "' reuses another's token");
  }
}

const Device* DeviceRegistry::authenticate(std::string_view token) const {
  if (token.size() > kMaxTokenLength) return nullptr;
  const Device* match = nullptr;
  for (const Device& d : devices_) {
    if (tokens_equal(d.token, token)) match = &d;
  }
  return match;
}

const Device* DeviceRegistry::find(std::string_view device_id) const {
  for (const Device& d : devices_) {
    if (d.id == device_id) return &d;
  }
  return nullptr;
}

DeviceRegistry read_device_registry(std::istream& in, const std::string& source) {
  std::vector<Device> devices;
  std::set<std::string> ids, tokens;
  std::string line;
  for (std::size_t number = 1; std::getline(in, line); ++number) {
    const std::string where = source + ":" + std::to_string(number) + ": error: ";
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream fields(line);
    Device d;
    if (!(fields >> d.id) || d.id.front() == '#') continue;
    std::string extra;
    if (!(fields >> d.token >> d.senior)) throw DeviceRegistryError(where + "expected: device token senior");
    if (fields >> extra) throw DeviceRegistryError(where + "unexpected fourth field '" + extra + "'");
    if (const std::string problem = device_problem(d); !problem.empty()) throw DeviceRegistryError(where + problem);
    if (!ids.insert(d.id).second) throw DeviceRegistryError(where + "device '" + d.id + "' is listed twice");
    if (!tokens.insert(d.token).second) throw DeviceRegistryError(where + "this token is already another device's");
    devices.push_back(std::move(d));
  }
  if (in.bad()) throw DeviceRegistryError(source + ": error: cannot read the file");
  return DeviceRegistry(std::move(devices));
}

DeviceRegistry read_device_registry_file(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw DeviceRegistryError(path.string() + ": error: cannot open the file");
  return read_device_registry(in, path.string());
}

void write_device_registry(std::ostream& out, const DeviceRegistry& registry) {
  out << "# device token senior\n";
  for (const Device& d : registry.devices()) out << d.id << ' ' << d.token << ' ' << d.senior << '\n';
}

}  // namespace alplan::perception::service
