#include "perception/vision/image_dataset.h"

#include <zlib.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <map>
#include <memory>
#include <numeric>
#include <random>
#include <set>

#include <opencv2/imgcodecs.hpp>

#include "perception/common/emotion.h"

namespace alplan::perception {
namespace fs = std::filesystem;
namespace {

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

bool is_image_file(const fs::path& path) {
  static const std::set<std::string> kExtensions = {".png", ".jpg", ".jpeg", ".bmp", ".pgm", ".ppm", ".tif", ".tiff"};
  return kExtensions.count(lower(path.extension().string())) != 0;
}

cv::Mat read_image(const fs::path& path, bool grey) {
  cv::Mat image = cv::imread(path.string(), grey ? cv::IMREAD_GRAYSCALE : cv::IMREAD_COLOR);
  if (image.empty()) throw ImageDatasetError(path.string() + ": not an image OpenCV can read");
  return image;
}

std::vector<fs::path> sorted_files_below(const fs::path& dir) {
  if (!fs::is_directory(dir)) throw ImageDatasetError(dir.string() + ": not a folder");
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (entry.is_regular_file() && is_image_file(entry.path())) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// A whole file, gunzipped when it is gzip (zlib reads plain files as they are).
std::vector<unsigned char> read_maybe_gzipped(const fs::path& path) {
  std::unique_ptr<gzFile_s, decltype(&gzclose)> in(gzopen(path.string().c_str(), "rb"), gzclose);
  if (!in) throw ImageDatasetError(path.string() + ": cannot open");
  std::vector<unsigned char> bytes;
  std::array<unsigned char, 1 << 16> buffer{};
  for (;;) {
    const int n = gzread(in.get(), buffer.data(), static_cast<unsigned>(buffer.size()));
    if (n < 0) throw ImageDatasetError(path.string() + ": corrupt gzip data");
    if (n == 0) break;
    bytes.insert(bytes.end(), buffer.begin(), buffer.begin() + n);
  }
  return bytes;
}

std::uint32_t big_endian_u32(const std::vector<unsigned char>& bytes, std::size_t at) {
  return (std::uint32_t{bytes[at]} << 24) | (std::uint32_t{bytes[at + 1]} << 16) | (std::uint32_t{bytes[at + 2]} << 8) |
         std::uint32_t{bytes[at + 3]};
}

// Checks an IDX header (magic 0x0000 0x08 = unsigned byte, then the number
// of dimensions) and returns the dimensions.
std::vector<std::uint32_t> idx_dimensions(const std::vector<unsigned char>& bytes, std::size_t expected_rank,
                                          const fs::path& path) {
  if (bytes.size() < 4 || bytes[0] != 0 || bytes[1] != 0 || bytes[2] != 0x08) {
    throw ImageDatasetError(path.string() + ": not an IDX file of unsigned bytes (bad magic number)");
  }
  const std::size_t rank = bytes[3];
  if (rank != expected_rank) {
    throw ImageDatasetError(path.string() + ": expected " + std::to_string(expected_rank) + " dimensions, found " +
                            std::to_string(rank));
  }
  if (bytes.size() < 4 + 4 * rank) throw ImageDatasetError(path.string() + ": truncated header");
  std::vector<std::uint32_t> dims;
  std::size_t total = 1;
  for (std::size_t d = 0; d < rank; ++d) {
    dims.push_back(big_endian_u32(bytes, 4 + 4 * d));
    total *= dims.back();
    if (total > bytes.size()) break;
  }
  if (bytes.size() != 4 + 4 * rank + total) {
    throw ImageDatasetError(path.string() + ": the header announces " + std::to_string(total) +
                            " bytes of data, the file has " + std::to_string(bytes.size() - 4 - 4 * rank));
  }
  return dims;
}

}  // namespace

std::vector<std::size_t> ImageDataset::class_counts() const {
  std::vector<std::size_t> counts(classes.size(), 0);
  for (const LabelledImage& s : samples) counts.at(static_cast<std::size_t>(s.label)) += 1;
  return counts;
}

std::string kdef_emotion_code(const std::string& file_name) {
  // [A|B][F|M][two digits][emotion code][angle].ext, e.g. AF01AFS.JPG.
  const std::string stem = fs::path(file_name).stem().string();
  if (stem.size() < 7) return "";
  const std::string upper = [&] {
    std::string u = stem;
    std::transform(u.begin(), u.end(), u.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    return u;
  }();
  if ((upper[0] != 'A' && upper[0] != 'B') || (upper[1] != 'F' && upper[1] != 'M')) return "";
  if (!std::isdigit(static_cast<unsigned char>(upper[2])) || !std::isdigit(static_cast<unsigned char>(upper[3]))) {
    return "";
  }
  return upper.substr(4, 2);
}

ImageDataset read_kdef(const fs::path& dir, const ReadOptions& options) {
  static const std::map<std::string, Emotion> kCodes = {
      {"AF", Emotion::Terrified}, {"AN", Emotion::Angry}, {"DI", Emotion::Disgusted}, {"HA", Emotion::Happy},
      {"NE", Emotion::Neutral},   {"SA", Emotion::Sad},   {"SU", Emotion::Surprised}};
  ImageDataset data;
  for (const auto& [code, emotion] : kCodes) data.classes.emplace_back(emotion_name(emotion));
  std::sort(data.classes.begin(), data.classes.end());
  for (const fs::path& file : sorted_files_below(dir)) {
    const auto code = kCodes.find(kdef_emotion_code(file.filename().string()));
    if (code == kCodes.end()) continue;  // KDEF folders hold other files too
    const std::string name(emotion_name(code->second));
    const auto label = std::find(data.classes.begin(), data.classes.end(), name) - data.classes.begin();
    data.samples.push_back({read_image(file, options.grey), static_cast<int>(label), file.string()});
    if (options.limit && data.samples.size() >= options.limit) break;
  }
  if (data.samples.empty()) {
    throw ImageDatasetError(dir.string() + ": no KDEF images (names like AF01AFS.JPG) below this folder");
  }
  return data;
}

ImageDataset read_class_folders(const fs::path& dir, const ReadOptions& options) {
  if (!fs::is_directory(dir)) throw ImageDatasetError(dir.string() + ": not a folder");
  ImageDataset data;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.is_directory()) data.classes.push_back(entry.path().filename().string());
  }
  std::sort(data.classes.begin(), data.classes.end());
  for (std::size_t c = 0; c < data.classes.size(); ++c) {
    for (const fs::path& file : sorted_files_below(dir / data.classes[c])) {
      data.samples.push_back({read_image(file, options.grey), static_cast<int>(c), file.string()});
    }
  }
  if (data.classes.empty() || data.samples.empty()) {
    throw ImageDatasetError(dir.string() + ": expected one folder of images per class, found none");
  }
  if (options.limit && data.samples.size() > options.limit) data.samples.resize(options.limit);
  return data;
}

ImageDataset read_idx(const fs::path& images, const fs::path& labels, const std::vector<std::string>& class_names,
                      const ReadOptions& options) {
  const std::vector<unsigned char> image_bytes = read_maybe_gzipped(images);
  const std::vector<unsigned char> label_bytes = read_maybe_gzipped(labels);
  const std::vector<std::uint32_t> dims = idx_dimensions(image_bytes, 3, images);
  const std::vector<std::uint32_t> label_dims = idx_dimensions(label_bytes, 1, labels);
  if (dims[0] != label_dims[0]) {
    throw ImageDatasetError(labels.string() + ": " + std::to_string(label_dims[0]) + " labels for " +
                            std::to_string(dims[0]) + " images");
  }
  ImageDataset data;
  data.classes = class_names;
  const std::size_t count = options.limit ? std::min<std::size_t>(options.limit, dims[0]) : dims[0];
  const std::size_t rows = dims[1], cols = dims[2];
  for (std::size_t i = 0; i < count; ++i) {
    const int label = label_bytes[8 + i];
    if (static_cast<std::size_t>(label) >= class_names.size()) {
      throw ImageDatasetError(labels.string() + ": label " + std::to_string(label) + " of item " + std::to_string(i) +
                              " is not one of the " + std::to_string(class_names.size()) + " classes");
    }
    cv::Mat grey(static_cast<int>(rows), static_cast<int>(cols), CV_8UC1,
                 const_cast<unsigned char*>(image_bytes.data() + 16 + i * rows * cols));
    cv::Mat image;
    if (options.grey) {
      image = grey.clone();
    } else {
      cv::merge(std::vector<cv::Mat>{grey, grey, grey}, image);
    }
    data.samples.push_back({image, label, images.filename().string() + "#" + std::to_string(i)});
  }
  return data;
}

ImageDataset read_fashion_mnist(bool train, const ReadOptions& options, const fs::path& dir) {
  const std::string prefix = train ? "train" : "t10k";
  return read_idx(dir / (prefix + "-images-idx3-ubyte.gz"), dir / (prefix + "-labels-idx1-ubyte.gz"),
                  {"t-shirt", "trouser", "pullover", "dress", "coat", "sandal", "shirt", "sneaker", "bag", "ankle-boot"},
                  options);
}

DatasetSplit split_dataset(const ImageDataset& data, double test_fraction, unsigned seed) {
  DatasetSplit split;
  split.train.classes = split.test.classes = data.classes;
  std::mt19937 rng(seed);
  for (std::size_t c = 0; c < data.classes.size(); ++c) {
    std::vector<std::size_t> members;
    for (std::size_t i = 0; i < data.samples.size(); ++i) {
      if (data.samples[i].label == static_cast<int>(c)) members.push_back(i);
    }
    std::shuffle(members.begin(), members.end(), rng);
    const auto test_count = static_cast<std::size_t>(test_fraction * static_cast<double>(members.size()) + 0.5);
    for (std::size_t k = 0; k < members.size(); ++k) {
      (k < test_count ? split.test : split.train).samples.push_back(data.samples[members[k]]);
    }
  }
  return split;
}

void write_class_folders(const ImageDataset& data, const fs::path& dir) {
  std::vector<std::size_t> written(data.classes.size(), 0);
  for (const std::string& c : data.classes) fs::create_directories(dir / c);
  for (const LabelledImage& s : data.samples) {
    const auto label = static_cast<std::size_t>(s.label);
    const fs::path file = dir / data.classes.at(label) / (std::to_string(written[label]++) + ".png");
    if (!cv::imwrite(file.string(), s.image)) throw ImageDatasetError(file.string() + ": cannot write");
  }
}

}  // namespace alplan::perception
