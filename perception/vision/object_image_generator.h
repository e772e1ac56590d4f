// A procedurally generated image set of the paper's object classes, for
// training and testing the object classifier where the paper's 200 web
// images per class cannot be had. Every image: a cluttered background (a
// colour gradient, a table edge, low-contrast shapes), one object of the
// class drawn by object_drawings.h at a random size, position, rotation and
// colour, then blur and sensor noise. Deterministic for a seed.
//
// What a classifier learns from these is the drawings' shapes, not real
// photographs: the README says which classes rest only on generated images.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "perception/vision/image_dataset.h"

namespace alplan::perception {

struct ObjectImageOptions {
  std::size_t per_class = 200;  // the paper's count
  int size = 64;                // square, pixels
  unsigned seed = 1;
  std::vector<std::string> classes;  // empty: all 18 of the paper's Table 4
};

// Throws std::invalid_argument for a class without a drawing.
ImageDataset generate_object_images(const ObjectImageOptions& options);

// The classes there are drawings for.
std::vector<std::string> drawable_object_classes();

}  // namespace alplan::perception
