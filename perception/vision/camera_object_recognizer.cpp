#include "perception/vision/camera_object_recognizer.h"

#include <algorithm>
#include <filesystem>
#include <set>

#include <opencv2/imgcodecs.hpp>

namespace alplan::perception {
namespace fs = std::filesystem;

std::vector<CameraView> FolderCamera::look(const std::string& location) {
  const fs::path dir = fs::path(dir_) / location;
  std::vector<CameraView> views;
  if (!fs::is_directory(dir)) return views;
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.is_regular_file()) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  for (const fs::path& f : files) {
    cv::Mat image = cv::imread(f.string(), cv::IMREAD_COLOR);
    if (!image.empty()) views.push_back({f.string(), image});  // other files are not views
  }
  return views;
}

std::string CameraObjectRecognizer::fresh_name(const std::string& type, const repair::WorldState& observed) {
  std::set<std::string> taken;
  for (const repair::AtomKey& atom : observed.atoms) taken.insert(atom.begin() + 1, atom.end());
  for (const auto& [key, object] : seen_) taken.insert(object.name);
  for (int n = 1;; ++n) {
    const std::string name = type + "_id" + (n < 10 ? "0" : "") + std::to_string(n);
    if (!taken.count(name)) return name;
  }
}

std::vector<repair::RecognizedObject> CameraObjectRecognizer::recognize(const repair::WorldState& observed,
                                                                        const std::string& location) {
  std::vector<repair::RecognizedObject> out;
  for (const CameraView& view : camera_->look(location)) {
    const std::vector<ImageObject> objects = recognizer_->recognize(view.image);
    for (std::size_t i = 0; i < objects.size(); ++i) {
      const std::string key = view.id + "#" + std::to_string(i) + ":" + objects[i].type;
      auto it = seen_.find(key);
      if (it == seen_.end()) {
        repair::RecognizedObject o{fresh_name(objects[i].type, observed), objects[i].type, location, objects[i].score};
        it = seen_.emplace(key, o).first;
      }
      out.push_back(it->second);
    }
  }
  return out;
}

}  // namespace alplan::perception
