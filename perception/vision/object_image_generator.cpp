#include "perception/vision/object_image_generator.h"

#include <random>
#include <stdexcept>

#include <opencv2/imgproc.hpp>

#include "perception/vision/object_drawings.h"

namespace alplan::perception {
namespace {

float uniform(std::mt19937& rng, float low, float high) { return std::uniform_real_distribution<float>(low, high)(rng); }

cv::Mat background(int size, std::mt19937& rng) {
  std::uniform_int_distribution<int> level(60, 230);
  const cv::Vec3f top(static_cast<float>(level(rng)), static_cast<float>(level(rng)), static_cast<float>(level(rng)));
  const cv::Vec3f bottom = top * uniform(rng, 0.6f, 1.1f);
  cv::Mat image(size, size, CV_8UC3);
  for (int y = 0; y < size; ++y) {
    const float t = static_cast<float>(y) / static_cast<float>(size - 1);
    const cv::Vec3f c = top * (1 - t) + bottom * t;
    image.row(y).setTo(cv::Scalar(c[0], c[1], c[2]));
  }
  if (rng() % 2 == 0) {  // a table edge
    const int edge = static_cast<int>(uniform(rng, 0.55f, 0.9f) * static_cast<float>(size));
    image.rowRange(edge, size).setTo(cv::Scalar(level(rng) / 2, level(rng) / 2, level(rng) / 2));
  }
  for (int k = static_cast<int>(rng() % 4); k > 0; --k) {  // low-contrast clutter
    const cv::Point p(static_cast<int>(rng() % static_cast<unsigned>(size)), static_cast<int>(rng() % static_cast<unsigned>(size)));
    const cv::Scalar c = cv::mean(image(cv::Rect(0, 0, size, size))) * uniform(rng, 0.75f, 1.25f);
    cv::circle(image, p, static_cast<int>(uniform(rng, 0.05f, 0.25f) * static_cast<float>(size)), c, cv::FILLED, cv::LINE_AA);
  }
  return image;
}

cv::Mat draw_one(const ObjectDrawing& draw, int size, std::mt19937& rng, cv::RNG& noise_rng) {
  // Drawn at twice the size, then scaled down: smoother edges.
  const int big = 2 * size;
  cv::Mat canvas = background(big, rng);
  cv::Mat layer(big, big, CV_8UC3, cv::Scalar::all(0)), mask(big, big, CV_8UC1, cv::Scalar(0));
  const float object_size = uniform(rng, 0.55f, 0.85f) * static_cast<float>(big);
  const cv::Point2f centre(static_cast<float>(big) / 2 + uniform(rng, -0.12f, 0.12f) * static_cast<float>(big),
                           static_cast<float>(big) / 2 + uniform(rng, -0.12f, 0.12f) * static_cast<float>(big));
  draw(layer, mask, centre, object_size, rng);
  const cv::Mat turn = cv::getRotationMatrix2D(centre, uniform(rng, -25.0f, 25.0f), 1.0);
  cv::warpAffine(layer, layer, turn, layer.size(), cv::INTER_LINEAR);
  cv::warpAffine(mask, mask, turn, mask.size(), cv::INTER_LINEAR);
  layer.copyTo(canvas, mask);
  cv::Mat image;
  cv::resize(canvas, image, {size, size}, 0, 0, cv::INTER_AREA);
  if (rng() % 2 == 0) cv::GaussianBlur(image, image, {3, 3}, uniform(rng, 0.3f, 1.0f));
  cv::Mat noise(image.size(), CV_16SC3);
  noise_rng.fill(noise, cv::RNG::NORMAL, 0, uniform(rng, 2.0f, 8.0f));
  cv::Mat noisy;
  image.convertTo(noisy, CV_16SC3);
  noisy += noise;
  noisy.convertTo(image, CV_8UC3);
  return image;
}

}  // namespace

std::vector<std::string> drawable_object_classes() {
  std::vector<std::string> names;
  for (const ObjectClassDrawing& d : object_class_drawings()) names.push_back(d.name);
  return names;
}

ImageDataset generate_object_images(const ObjectImageOptions& options) {
  if (options.size < 16) throw std::invalid_argument("generated object images must be at least 16 pixels");
  ImageDataset data;
  data.classes = options.classes.empty() ? drawable_object_classes() : options.classes;
  std::mt19937 rng(options.seed);
  cv::RNG noise_rng(options.seed);
  for (std::size_t c = 0; c < data.classes.size(); ++c) {
    const ObjectDrawing* draw = nullptr;
    for (const ObjectClassDrawing& d : object_class_drawings()) {
      if (d.name == data.classes[c]) draw = &d.draw;
    }
    if (!draw) throw std::invalid_argument("no drawing for object class '" + data.classes[c] + "'");
    for (std::size_t i = 0; i < options.per_class; ++i) {
      data.samples.push_back({draw_one(*draw, options.size, rng, noise_rng), static_cast<int>(c),
                              "generated:" + data.classes[c] + "#" + std::to_string(i)});
    }
  }
  return data;
}

}  // namespace alplan::perception
