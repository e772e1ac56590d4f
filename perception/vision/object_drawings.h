// Procedural drawings of the object classes of the paper's own dataset (its
// Table 4: 200 web images per class, which cannot be downloaded here). Each
// function draws one object of its class, in a colour and proportions drawn
// from `rng`, centred on `centre`, `size` pixels tall, on a BGR canvas and
// into a mask of the pixels it covered (for compositing). The shapes are
// what tells the classes apart: a cup has a saucer and a small handle, a mug
// is straight with a big handle, a jar has a lid and no handle, a journal a
// strap, a newspaper columns, a sudoku a 9x9 grid, and so on.
#pragma once

#include <functional>
#include <random>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace alplan::perception {

using ObjectDrawing = std::function<void(cv::Mat& canvas, cv::Mat& mask, cv::Point2f centre, float size, std::mt19937& rng)>;

struct ObjectClassDrawing {
  std::string name;  // the PDDL type (the domain's and Fig. 5's names)
  ObjectDrawing draw;
};

// The 18 classes of Table 4, in its order, named as the domain's types
// ("yoyo" for the paper's "yo-yo").
const std::vector<ObjectClassDrawing>& object_class_drawings();

}  // namespace alplan::perception
