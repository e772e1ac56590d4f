// The perception side of the `substitute` repair (the paper's Scenarios 1
// and 2): when the monitor asks what is around a location, the robot's
// camera looks, the image recogniser names the objects by the domain's
// types, and each new object becomes a repair::RecognizedObject -- an object
// id such as mug_id01, its type and location -- which the repair integrates
// into the planning problem as (object, type, (be o loc), (available o)).
#pragma once

#include <map>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "perception/vision/object_recognition.h"
#include "repair/object_recognizer.h"

namespace alplan::perception {

struct CameraView {
  std::string id;  // stable for the same view (a file name), so a look repeated sees the same objects
  cv::Mat image;
};

class Camera {
 public:
  virtual ~Camera() = default;
  virtual std::vector<CameraView> look(const std::string& location) = 0;
};

// Images in DIR/<location>/ (png, jpg, ...): what the camera sees there.
class FolderCamera : public Camera {
 public:
  explicit FolderCamera(std::string dir) : dir_(std::move(dir)) {}
  std::vector<CameraView> look(const std::string& location) override;

 private:
  std::string dir_;
};

class CameraObjectRecognizer : public repair::ObjectRecognizer {
 public:
  // Both must outlive this object.
  CameraObjectRecognizer(Camera& camera, ImageObjectRecognizer& recognizer) : camera_(&camera), recognizer_(&recognizer) {}

  std::vector<repair::RecognizedObject> recognize(const repair::WorldState& observed, const std::string& location) override;

 private:
  std::string fresh_name(const std::string& type, const repair::WorldState& observed);

  Camera* camera_;
  ImageObjectRecognizer* recognizer_;
  std::map<std::string, repair::RecognizedObject> seen_;  // by view id and object index
};

}  // namespace alplan::perception
