#include "perception/common/model_cache.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <system_error>

#include <unistd.h>

namespace alplan::perception {

std::optional<std::filesystem::path> model_cache_dir() {
  if (const char* off = std::getenv("ALPLAN_MODEL_CACHE"); off && std::string(off) == "off") return std::nullopt;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg == '/') return std::filesystem::path(xdg) / "alplan";
  if (const char* home = std::getenv("HOME"); home && *home == '/') {
    return std::filesystem::path(home) / ".cache" / "alplan";
  }
  return std::nullopt;
}

std::string model_cache_name(const std::string& kind, const std::string& key, const std::string& extension) {
  std::uint64_t hash = 14695981039346656037ULL;  // FNV-1a: the same on every machine, unlike std::hash
  for (unsigned char c : key) {
    hash ^= c;
    hash *= 1099511628211ULL;
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
  return kind + "-" + hex + extension;
}

bool read_cached(const std::string& file_name, const std::function<void(const std::filesystem::path&)>& read) {
  const std::optional<std::filesystem::path> dir = model_cache_dir();
  if (!dir) return false;
  const std::filesystem::path file = *dir / file_name;
  std::error_code error;
  if (!std::filesystem::is_regular_file(file, error)) return false;
  try {
    read(file);
    return true;
  } catch (const std::exception&) {
    return false;  // damaged or foreign: trained again, and written over
  }
}

void write_cached(const std::string& file_name, const std::function<void(const std::filesystem::path&)>& write) {
  const std::optional<std::filesystem::path> dir = model_cache_dir();
  if (!dir) return;
  std::error_code error;
  std::filesystem::create_directories(*dir, error);
  if (error) return;
  // The process id keeps two runs training at once from writing one file;
  // the name keeps its extension, which some writers read the format from.
  const std::filesystem::path partial = *dir / ("partial-" + std::to_string(::getpid()) + "-" + file_name);
  try {
    write(partial);
    std::filesystem::rename(partial, *dir / file_name, error);
  } catch (const std::exception&) {
    error = std::make_error_code(std::errc::io_error);
  }
  if (error) std::filesystem::remove(partial, error);
}

}  // namespace alplan::perception
