// A senior's face as the home reads it when it has no camera of its own
// (`alplan deliberate`, `serve --deliberate`, `home --live`): an image of
// the face, read anew by the pretrained emotion network at every look (what
// a camera would show), or an emotion the operator gives. Either way the
// reading is a real one, from a real image or from a person, never made up
// by a model of the senior.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "perception/goals/goal_generator.h"

namespace alplan::perception {
class PretrainedEmotionRecognizer;
}

namespace alplan::home {

class GivenFace {
 public:
  // `emotion` (a name: terrified, sad, bored, happy, ...) when given, else
  // `face` (an image file). Throws std::invalid_argument with neither or an
  // unknown emotion. Loads the network once, for a face.
  GivenFace(std::string face, std::string emotion);
  ~GivenFace();
  GivenFace(GivenFace&&) noexcept;

  // The most confident face's emotion, or nothing when the image shows no
  // face; `note` says what was read, for people. Throws
  // std::invalid_argument on an unreadable image.
  std::optional<perception::EmotionReading> look(std::string& note);
  bool given() const { return !emotion_.empty(); }

 private:
  std::string face_, emotion_;
  std::unique_ptr<perception::PretrainedEmotionRecognizer> faces_;
};

}  // namespace alplan::home
