// What perception reports when the monitor asks what is around: new objects
// (not yet in the planning problem) with the type a classifier gave them.
// The world simulator implements it for experiments; the perception
// library's camera-based recognizer implements it on real images.
#pragma once

#include <string>
#include <vector>

#include "repair/world_state.h"

namespace alplan::repair {

struct RecognizedObject {
  std::string name;      // "mug_id01"
  std::string type;      // "mug": a type of the (augmented) domain
  std::string location;  // where it was seen
  double confidence = 1.0;
};

class ObjectRecognizer {
 public:
  virtual ~ObjectRecognizer() = default;
  // Objects visible from `location` that the planning problem does not know.
  virtual std::vector<RecognizedObject> recognize(const WorldState& observed, const std::string& location) = 0;
};

}  // namespace alplan::repair
