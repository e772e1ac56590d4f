// Trained models kept between runs: the paper's CNN that `bench repair`
// trains on drawings, the stress classifier that `home`, `serve` and
// `deliberate` train on simulated recordings. Training is deterministic in
// its settings and seed, so a model is keyed by them (and by a version the
// trainer bumps when its code changes what it learns) and kept in the XDG
// cache directory ($XDG_CACHE_HOME/alplan, else ~/.cache/alplan), as
// the XDG Base Directory specification puts data that can be made again.
//
// A cache that cannot be read or written is no error: the model is trained,
// as without a cache. ALPLAN_MODEL_CACHE=off turns it off (a run that must
// measure training, or a read-only home).
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>

namespace alplan::perception {

// The cache's folder, or none when it is off or no folder can be named.
std::optional<std::filesystem::path> model_cache_dir();

// A file name for a model of `kind` ("drawing-cnn") whose settings read
// `key`: the kind, then a stable 64-bit hash of the key (FNV-1a), then
// `extension`.
std::string model_cache_name(const std::string& kind, const std::string& key, const std::string& extension);

// Loads the model from the cache when it is there and `load` reads it;
// else trains it, and saves it for the next run (written to a temporary
// file, then renamed: a run that stops midway leaves no half model).
// `from_cache` tells which happened.
template <typename Model>
Model cached_model(const std::string& file_name, const std::function<Model()>& train,
                   const std::function<Model(const std::filesystem::path&)>& load,
                   const std::function<void(const Model&, const std::filesystem::path&)>& save,
                   bool* from_cache = nullptr);

// Implementation detail of cached_model, without the model's type.
bool read_cached(const std::string& file_name, const std::function<void(const std::filesystem::path&)>& read);
void write_cached(const std::string& file_name, const std::function<void(const std::filesystem::path&)>& write);

template <typename Model>
Model cached_model(const std::string& file_name, const std::function<Model()>& train,
                   const std::function<Model(const std::filesystem::path&)>& load,
                   const std::function<void(const Model&, const std::filesystem::path&)>& save, bool* from_cache) {
  std::optional<Model> model;
  const bool hit = read_cached(file_name, [&](const std::filesystem::path& file) { model.emplace(load(file)); });
  if (from_cache) *from_cache = hit;
  if (hit) return std::move(*model);
  Model trained = train();
  write_cached(file_name, [&](const std::filesystem::path& file) { save(trained, file); });
  return trained;
}

}  // namespace alplan::perception
