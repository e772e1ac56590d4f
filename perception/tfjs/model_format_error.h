// The error every model loader of perception raises when a model's files are
// missing, malformed, or use something the loader cannot represent. The
// message names the file and, where there is one, the node or weight, and
// says what is wrong.
#pragma once

#include <stdexcept>

namespace alplan::perception {

class ModelFormatError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace alplan::perception
