#include "cli/perception_module.h"

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "cli/commands.h"

namespace alplan::cli {
namespace {

std::filesystem::path module_path() {
  if (const char* set = std::getenv("ALPLAN_PERCEPTION_MODULE")) return set;
  char self[4096];
  const ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
  const std::filesystem::path dir = n > 0 ? std::filesystem::path(std::string(self, static_cast<std::size_t>(n))).parent_path()
                                          : std::filesystem::current_path();
  return dir / ALPLAN_PERCEPTION_MODULE_FILE;
}

}  // namespace

bool load_drawing_camera(const std::string& types_ttl, ObjectCamera& make, nlohmann::json& info, std::string& error) {
  const std::filesystem::path path = module_path();
  // Kept open for the process: the recognizers' code lives in the module.
  void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!module) {
    error = "cannot load the perception module " + path.string() + ": " + dlerror();
    return false;
  }
  auto entry = reinterpret_cast<DrawingCameraEntry>(dlsym(module, kDrawingCameraEntryPoint));
  if (!entry) {
    error = path.string() + " has no " + kDrawingCameraEntryPoint;
    return false;
  }
  return entry(types_ttl.c_str(), &make, &info, &error);
}

bool runs_in_perception_module(int argc, char** argv) {
  if (argc < 2) return false;
  const std::string first = argv[1];
  for (const ModuleCommand& c : kPerceptionCommands) {
    if (first == c.name) return true;
  }
  if (first != "bench" || argc < 3) return false;
  const std::string second = argv[2];
  return second == "service" || second == "soak" || second == "home";
}

int run_perception_command(int argc, char** argv) {
  const std::filesystem::path path = module_path();
  // The handle stays open until the process ends: the command's objects
  // and atexit handlers live in the module.
  void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!module) {
    std::cerr << "error: cannot load the perception module " << path.string() << ": " << dlerror()
              << "\n(build it with the alplan target, or set ALPLAN_PERCEPTION_MODULE to its path)\n";
    return kExitInputError;
  }
  auto entry = reinterpret_cast<PerceptionMain>(dlsym(module, kPerceptionEntryPoint));
  if (!entry) {
    std::cerr << "error: " << path.string() << " is not alplan's perception module (no " << kPerceptionEntryPoint
              << ")\n";
    return kExitInputError;
  }
  return entry(argc, argv);
}

}  // namespace alplan::cli
