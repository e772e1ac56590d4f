// Labelled image sets in the layouts the paper's learners were trained on,
// read into memory as 8-bit images:
//  - KDEF (Lundqvist et al. 1998): files such as AF01AFS.JPG, whose letters
//    4-5 encode the emotion (AF afraid, AN angry, DI disgusted, HA happy,
//    NE neutral, SA sad, SU surprised); any folder depth.
//  - folder per class: DIR/<class>/<image>, the layout of the paper's
//    object set (200 web images per class) and of UMB-DB's "bored" faces
//    added to KDEF's seven emotions;
//  - IDX (LeCun's MNIST format, optionally gzipped), as Debian's
//    dataset-fashion-mnist ships Fashion-MNIST.
// Errors name the file and say what is wrong (ImageDatasetError).
#pragma once

#include <cstddef>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace alplan::perception {

class ImageDatasetError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct LabelledImage {
  cv::Mat image;  // CV_8UC1 or CV_8UC3 (BGR)
  int label = 0;  // index into ImageDataset::classes
  std::string source;  // file (and index for IDX)
};

struct ImageDataset {
  std::vector<std::string> classes;
  std::vector<LabelledImage> samples;

  std::vector<std::size_t> class_counts() const;
};

struct ReadOptions {
  bool grey = true;      // read as one channel, else BGR
  std::size_t limit = 0;  // at most this many samples (0: all); IDX reads the first ones
};

// KDEF: the paper's seven emotion classes (terrified for KDEF's "afraid").
ImageDataset read_kdef(const std::filesystem::path& dir, const ReadOptions& options = {});
// DIR/<class>/*.{png,jpg,jpeg,bmp,pgm,ppm,tif,tiff}; classes sorted by name.
ImageDataset read_class_folders(const std::filesystem::path& dir, const ReadOptions& options = {});
// IDX images (u8, 3 dims) and labels (u8, 1 dim), plain or .gz.
ImageDataset read_idx(const std::filesystem::path& images, const std::filesystem::path& labels,
                      const std::vector<std::string>& class_names, const ReadOptions& options = {});
// Fashion-MNIST's train or test split where Debian installs it
// (/usr/share/datasets/fashion-mnist), with its ten class names.
ImageDataset read_fashion_mnist(bool train, const ReadOptions& options = {},
                                const std::filesystem::path& dir = "/usr/share/datasets/fashion-mnist");

// The KDEF emotion code of a file name ("AF01AFS.JPG" -> "AF"), or "".
std::string kdef_emotion_code(const std::string& file_name);

// A stratified split: about `test_fraction` of every class goes to the test
// set, chosen by a seeded shuffle (the paper: 80% train, 20% test).
struct DatasetSplit {
  ImageDataset train, test;
};
DatasetSplit split_dataset(const ImageDataset& data, double test_fraction, unsigned seed);

// Writes DIR/<class>/<n>.png for every sample (for generated sets).
void write_class_folders(const ImageDataset& data, const std::filesystem::path& dir);

}  // namespace alplan::perception
