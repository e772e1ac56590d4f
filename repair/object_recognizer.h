// What perception reports when the monitor asks what is around: new objects
// (not yet in the planning problem) with the type a classifier gave them.
// The world simulator implements it for experiments; the perception
// library's camera-based recognizer implements it on real images.
#pragma once

#include <string>
#include <vector>

#include "repair/world_state.h"

namespace alplan::repair {

// A thing the robot's camera saw that the planning problem does not name:
// a picture to classify, not yet a type (observation.h keeps them).
struct Sighting {
  std::string object;    // the id the robot tracks it by
  std::string location;  // where it was seen
  double time = 0.0;     // when
};

struct RecognizedObject {
  std::string name;      // "mug_id01"
  std::string type;      // "mug": a type of the (augmented) domain
  std::string location;  // where it was seen
  double confidence = 1.0;
  double seen_at = -1.0;  // when the camera saw it, if earlier than now; -1: now
};

class ObjectRecognizer {
 public:
  virtual ~ObjectRecognizer() = default;
  // Objects visible from `location` that the planning problem does not know.
  virtual std::vector<RecognizedObject> recognize(const WorldState& observed, const std::string& location) = 0;
  // Classifies what the camera saw earlier, anywhere on the robot's route;
  // each object keeps the place it was seen at. A recognizer that can only
  // look now (a folder of images per place) recognises none.
  virtual std::vector<RecognizedObject> recognize_sightings(const std::vector<Sighting>& sightings) {
    (void)sightings;
    return {};
  }
};

}  // namespace alplan::repair
