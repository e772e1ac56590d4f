// The model cache (perception/common/model_cache.h): a model trained once is
// read by the next run; a damaged file is trained again and written over;
// the cache can be turned off.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "perception/common/model_cache.h"

using namespace alplan::perception;
namespace fs = std::filesystem;

namespace {

// A "model" is a string, saved as a text file; training counts its calls.
struct Counting {
  int trained = 0;
  std::string train() {
    ++trained;
    return "weights-" + std::to_string(trained);
  }
};

std::string load(const fs::path& file) {
  std::ifstream in(file);
  std::string text;
  if (!(in >> text) || text.rfind("weights-", 0) != 0) throw std::runtime_error("foreign file");
  return text;
}

void save(const std::string& model, const fs::path& file) { std::ofstream(file) << model << "\n"; }

std::string cached(Counting& counter, const std::string& name, bool* hit) {
  return cached_model<std::string>(name, [&] { return counter.train(); }, load, save, hit);
}

}  // namespace

TEST_CASE("a trained model is read back by the next run, keyed by its settings") {
  const fs::path home = fs::temp_directory_path() / ("alplan-model-cache-" + std::to_string(::getpid()));
  fs::remove_all(home);
  ::setenv("XDG_CACHE_HOME", home.c_str(), 1);
  ::unsetenv("ALPLAN_MODEL_CACHE");
  REQUIRE(model_cache_dir() == home / "alplan");
  const std::string name = model_cache_name("toy", "epochs 10 seed 1", ".txt");
  CHECK(name == model_cache_name("toy", "epochs 10 seed 1", ".txt"));
  CHECK(name != model_cache_name("toy", "epochs 10 seed 2", ".txt"));
  CHECK(name.rfind("toy-", 0) == 0);
  Counting counter;
  bool hit = true;
  CHECK(cached(counter, name, &hit) == "weights-1");
  CHECK_FALSE(hit);
  CHECK(cached(counter, name, &hit) == "weights-1");  // read, not trained
  CHECK(hit);
  CHECK(counter.trained == 1);
  // No partial file is left behind.
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator(home / "alplan")) files += entry.is_regular_file();
  CHECK(files == 1);
  // A damaged file is trained again and written over.
  std::ofstream(home / "alplan" / name) << "garbage\n";
  CHECK(cached(counter, name, &hit) == "weights-2");
  CHECK_FALSE(hit);
  CHECK(cached(counter, name, &hit) == "weights-2");
  CHECK(hit);
  // Off: always trained, nothing read.
  ::setenv("ALPLAN_MODEL_CACHE", "off", 1);
  CHECK_FALSE(model_cache_dir());
  CHECK(cached(counter, name, &hit) == "weights-3");
  CHECK_FALSE(hit);
  ::unsetenv("ALPLAN_MODEL_CACHE");
  fs::remove_all(home);
}
