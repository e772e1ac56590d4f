#include "perception/vision/cnn_classifier.h"

#include <torch/torch.h>

#include <algorithm>
#include <chrono>
#include <limits>
#include <numeric>
#include <random>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>

namespace alplan::perception {
namespace {

// The network: conv blocks, then the dense funnel, then the class logits.
struct PaperCnnImpl : torch::nn::Module {
  PaperCnnImpl(const CnnArchitecture& a, std::size_t classes) {
    int in = a.channels;
    int side = a.input_size;
    for (std::size_t i = 0; i < a.conv_filters.size(); ++i) {
      convs.push_back(register_module(
          "conv" + std::to_string(i),
          torch::nn::Conv2d(torch::nn::Conv2dOptions(in, a.conv_filters[i], a.kernel).padding(a.kernel / 2))));
      in = a.conv_filters[i];
      side /= 2;
    }
    std::int64_t features = static_cast<std::int64_t>(in) * side * side;
    for (std::size_t i = 0; i < a.hidden.size(); ++i) {
      dense.push_back(register_module("dense" + std::to_string(i), torch::nn::Linear(features, a.hidden[i])));
      features = a.hidden[i];
    }
    output = register_module("output", torch::nn::Linear(features, static_cast<std::int64_t>(classes)));
    dropout = register_module("dropout", torch::nn::Dropout(a.dropout));
    dropout_every_hidden = a.dropout_every_hidden_layer;
    // He initialisation (He et al., ICCV 2015) for the ReLU layers: torch's
    // default draws weights a third as large in variance, and through five
    // narrow dense layers the signal then fades and training crawls.
    for (auto& conv : convs) init_for_relu(conv->weight, conv->bias);
    for (auto& layer : dense) init_for_relu(layer->weight, layer->bias);
  }

  static void init_for_relu(torch::Tensor& weight, torch::Tensor& bias) {
    torch::NoGradGuard no_grad;
    torch::nn::init::kaiming_normal_(weight, 0.0, torch::kFanIn, torch::kReLU);
    torch::nn::init::zeros_(bias);
  }

  torch::Tensor forward(torch::Tensor x) {
    for (auto& conv : convs) x = torch::max_pool2d(torch::relu(conv->forward(x)), 2);
    x = dropout->forward(x.flatten(1));
    for (auto& layer : dense) {
      x = torch::relu(layer->forward(x));
      if (dropout_every_hidden) x = dropout->forward(x);
    }
    return output->forward(x);
  }

  // Keras' kernel_regularizer: the squared weights (not biases).
  torch::Tensor weight_penalty() {
    torch::Tensor sum = torch::zeros({1});
    for (const auto& p : named_parameters()) {
      if (p.key().find("weight") != std::string::npos) sum = sum + p.value().pow(2).sum();
    }
    return sum;
  }

  std::vector<torch::nn::Conv2d> convs;
  std::vector<torch::nn::Linear> dense;
  torch::nn::Linear output{nullptr};
  torch::nn::Dropout dropout{nullptr};
  bool dropout_every_hidden = false;
};
TORCH_MODULE(PaperCnn);

nlohmann::json architecture_json(const CnnArchitecture& a) {
  return {{"input_size", a.input_size}, {"channels", a.channels}, {"conv_filters", a.conv_filters},
          {"kernel", a.kernel},         {"hidden", a.hidden},     {"dropout", a.dropout},
          {"dropout_every_hidden_layer", a.dropout_every_hidden_layer}};
}

CnnArchitecture architecture_from_json(const nlohmann::json& j) {
  CnnArchitecture a;
  a.input_size = j.at("input_size").get<int>();
  a.channels = j.at("channels").get<int>();
  a.conv_filters = j.at("conv_filters").get<std::vector<int>>();
  a.kernel = j.at("kernel").get<int>();
  a.hidden = j.at("hidden").get<std::vector<int>>();
  a.dropout = j.at("dropout").get<double>();
  a.dropout_every_hidden_layer = j.value("dropout_every_hidden_layer", false);
  return a;
}

void check_architecture(const CnnArchitecture& a, std::size_t classes) {
  const auto fail = [](const std::string& what) { throw std::invalid_argument("CNN architecture: " + what); };
  if (classes < 2) fail("needs at least two classes");
  if (a.channels != 1 && a.channels != 3) fail("channels must be 1 (grey) or 3 (colour)");
  if (a.kernel < 1 || a.kernel % 2 == 0) fail("the kernel size must be odd");
  if (a.conv_filters.empty()) fail("needs at least one convolutional layer");
  if ((a.input_size >> a.conv_filters.size()) < 1) fail("the input is too small for that many pooling layers");
  for (int f : a.conv_filters) if (f < 1) fail("filter counts must be positive");
  for (int h : a.hidden) if (h < 1) fail("hidden layer sizes must be positive");
  if (a.dropout < 0 || a.dropout >= 1) fail("dropout must be in [0, 1)");
}

}  // namespace

struct CnnClassifier::Impl {
  std::vector<std::string> classes;
  CnnArchitecture architecture;
  PaperCnn net{nullptr};

  // Images as a float tensor N x C x S x S in [-1, 1].
  torch::Tensor to_tensor(const std::vector<cv::Mat>& images) const {
    const int s = architecture.input_size, c = architecture.channels;
    torch::Tensor batch = torch::empty({static_cast<std::int64_t>(images.size()), c, s, s});
    auto out = batch.accessor<float, 4>();
    for (std::size_t n = 0; n < images.size(); ++n) {
      cv::Mat image = images[n];
      if (image.empty()) throw std::invalid_argument("cannot classify an empty image");
      if (c == 1 && image.channels() == 3) cv::cvtColor(image, image, cv::COLOR_BGR2GRAY);
      if (c == 1 && image.channels() == 4) cv::cvtColor(image, image, cv::COLOR_BGRA2GRAY);
      if (c == 3 && image.channels() == 1) cv::cvtColor(image, image, cv::COLOR_GRAY2BGR);
      if (c == 3 && image.channels() == 4) cv::cvtColor(image, image, cv::COLOR_BGRA2BGR);
      if (image.rows != s || image.cols != s) cv::resize(image, image, {s, s}, 0, 0, cv::INTER_AREA);
      image.convertTo(image, CV_32F, 2.0 / 255.0, -1.0);
      for (int y = 0; y < s; ++y) {
        const float* row = image.ptr<float>(y);
        for (int x = 0; x < s; ++x) {
          for (int k = 0; k < c; ++k) out[static_cast<std::int64_t>(n)][k][y][x] = row[x * c + k];
        }
      }
    }
    return batch;
  }
};

CnnClassifier::CnnClassifier(std::vector<std::string> classes, const CnnArchitecture& architecture, unsigned seed)
    : impl_(std::make_unique<Impl>()) {
  check_architecture(architecture, classes.size());
  impl_->classes = std::move(classes);
  impl_->architecture = architecture;
  torch::manual_seed(seed);
  impl_->net = PaperCnn(architecture, impl_->classes.size());
}

CnnClassifier::~CnnClassifier() = default;
CnnClassifier::CnnClassifier(CnnClassifier&&) noexcept = default;
CnnClassifier& CnnClassifier::operator=(CnnClassifier&&) noexcept = default;

const std::vector<std::string>& CnnClassifier::classes() const { return impl_->classes; }
const CnnArchitecture& CnnClassifier::architecture() const { return impl_->architecture; }

std::size_t CnnClassifier::parameter_count() const {
  std::size_t n = 0;
  for (const auto& p : impl_->net->parameters()) n += static_cast<std::size_t>(p.numel());
  return n;
}

TrainingReport CnnClassifier::train(const ImageDataset& data, const TrainingOptions& options) {
  if (data.classes != impl_->classes) throw std::invalid_argument("training data has other classes than the model");
  if (data.samples.size() < 2) throw std::invalid_argument("training needs at least two samples");
  torch::set_num_threads(options.threads > 0 ? options.threads
                                             : static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
  torch::manual_seed(options.seed);
  const DatasetSplit split = split_dataset(data, options.validation_fraction, options.seed);
  const auto tensors = [&](const ImageDataset& d) {
    std::vector<cv::Mat> images;
    std::vector<std::int64_t> labels;
    for (const LabelledImage& s : d.samples) images.push_back(s.image), labels.push_back(s.label);
    return std::make_pair(impl_->to_tensor(images), torch::tensor(labels, torch::kLong));
  };
  const auto [train_x, train_y] = tensors(split.train);
  const auto [val_x, val_y] = tensors(split.test.samples.empty() ? split.train : split.test);

  const bool decoupled = options.l2_mode == L2Mode::DecoupledWeightDecay;
  torch::optim::AdamW optimiser(impl_->net->parameters(),
                                torch::optim::AdamWOptions(options.learning_rate).weight_decay(decoupled ? options.l2 : 0.0));
  TrainingReport report;
  double best_loss = std::numeric_limits<double>::infinity();
  std::stringstream best_weights;
  std::mt19937 rng(options.seed);
  std::vector<std::int64_t> order(static_cast<std::size_t>(train_x.size(0)));
  std::iota(order.begin(), order.end(), 0);
  int since_best = 0;
  for (int epoch = 1; epoch <= options.epochs; ++epoch) {
    const auto start = std::chrono::steady_clock::now();
    impl_->net->train();
    std::shuffle(order.begin(), order.end(), rng);
    double loss_sum = 0;
    std::int64_t batches = 0;
    for (std::size_t b = 0; b < order.size(); b += static_cast<std::size_t>(options.batch_size)) {
      const std::size_t e = std::min(order.size(), b + static_cast<std::size_t>(options.batch_size));
      const torch::Tensor index = torch::tensor(std::vector<std::int64_t>(order.begin() + static_cast<long>(b),
                                                                          order.begin() + static_cast<long>(e)));
      optimiser.zero_grad();
      torch::Tensor loss = torch::cross_entropy_loss(impl_->net->forward(train_x.index_select(0, index)),
                                                     train_y.index_select(0, index));
      if (!decoupled && options.l2 > 0) loss = loss + options.l2 * impl_->net->weight_penalty();
      loss.backward();
      optimiser.step();
      loss_sum += loss.item<double>();
      ++batches;
    }
    EpochReport r;
    r.epoch = epoch;
    r.train_loss = loss_sum / static_cast<double>(std::max<std::int64_t>(1, batches));
    {
      torch::NoGradGuard no_grad;
      impl_->net->eval();
      const torch::Tensor logits = impl_->net->forward(val_x);
      r.validation_loss = torch::cross_entropy_loss(logits, val_y).item<double>();
      r.validation_accuracy = logits.argmax(1).eq(val_y).to(torch::kDouble).mean().item<double>();
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    report.epochs.push_back(r);
    if (options.on_epoch) options.on_epoch(r);
    if (r.validation_loss < best_loss - options.min_delta) {
      best_loss = r.validation_loss;
      report.best_epoch = epoch;
      best_weights.str("");
      torch::save(impl_->net, best_weights);
      since_best = 0;
    } else if (++since_best >= options.patience) {
      report.stopped_early = epoch < options.epochs;
      break;
    }
  }
  if (report.best_epoch > 0) torch::load(impl_->net, best_weights);
  impl_->net->eval();
  return report;
}

std::vector<std::vector<float>> CnnClassifier::scores(const std::vector<cv::Mat>& images) const {
  torch::NoGradGuard no_grad;
  impl_->net->eval();
  std::vector<std::vector<float>> out;
  constexpr std::size_t kBatch = 256;
  for (std::size_t b = 0; b < images.size(); b += kBatch) {
    const std::vector<cv::Mat> part(images.begin() + static_cast<long>(b),
                                    images.begin() + static_cast<long>(std::min(images.size(), b + kBatch)));
    const torch::Tensor probabilities = torch::softmax(impl_->net->forward(impl_->to_tensor(part)), 1).contiguous();
    const float* p = probabilities.data_ptr<float>();
    const std::size_t k = impl_->classes.size();
    for (std::size_t n = 0; n < part.size(); ++n) out.emplace_back(p + n * k, p + (n + 1) * k);
  }
  return out;
}

std::vector<float> CnnClassifier::scores(const cv::Mat& image) const { return scores(std::vector<cv::Mat>{image}).front(); }

std::size_t CnnClassifier::predict(const cv::Mat& image) const {
  const std::vector<float> s = scores(image);
  return static_cast<std::size_t>(std::max_element(s.begin(), s.end()) - s.begin());
}

ConfusionMatrix CnnClassifier::evaluate(const ImageDataset& test) const {
  if (test.classes != impl_->classes) throw std::invalid_argument("test data has other classes than the model");
  ConfusionMatrix matrix(impl_->classes);
  std::vector<cv::Mat> images;
  for (const LabelledImage& s : test.samples) images.push_back(s.image);
  const std::vector<std::vector<float>> all = scores(images);
  for (std::size_t i = 0; i < all.size(); ++i) {
    const auto predicted = static_cast<std::size_t>(std::max_element(all[i].begin(), all[i].end()) - all[i].begin());
    matrix.add(static_cast<std::size_t>(test.samples[i].label), predicted);
  }
  return matrix;
}

void CnnClassifier::save(const std::filesystem::path& file) const {
  torch::serialize::OutputArchive archive;
  impl_->net->save(archive);
  const nlohmann::json meta = {{"format", "alplan-cnn-1"},
                               {"classes", impl_->classes},
                               {"architecture", architecture_json(impl_->architecture)}};
  archive.write("alplan_meta", c10::IValue(meta.dump()));
  try {
    archive.save_to(file.string());
  } catch (const c10::Error& e) {
    throw ModelFileError(file.string() + ": cannot write the model");
  }
}

CnnClassifier CnnClassifier::load(const std::filesystem::path& file) {
  torch::serialize::InputArchive archive;
  nlohmann::json meta;
  try {
    archive.load_from(file.string());
    c10::IValue text;
    if (!archive.try_read("alplan_meta", text) || !text.isString()) {
      throw ModelFileError(file.string() + ": a torch archive, but not an alplan CNN (no alplan_meta)");
    }
    meta = nlohmann::json::parse(text.toStringRef());
  } catch (const c10::Error&) {
    throw ModelFileError(file.string() + ": not a model file saved by alplan (torch cannot read it)");
  } catch (const nlohmann::json::exception& e) {
    throw ModelFileError(file.string() + ": corrupt model metadata: " + e.what());
  }
  try {
    CnnClassifier model(meta.at("classes").get<std::vector<std::string>>(),
                        architecture_from_json(meta.at("architecture")));
    model.impl_->net->load(archive);
    model.impl_->net->eval();
    return model;
  } catch (const nlohmann::json::exception& e) {
    throw ModelFileError(file.string() + ": corrupt model metadata: " + e.what());
  } catch (const c10::Error&) {
    throw ModelFileError(file.string() + ": the weights do not fit the architecture the file describes");
  }
}

}  // namespace alplan::perception
