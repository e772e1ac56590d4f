#include "perception/stress/stress_baseline.h"

#include <algorithm>
#include <stdexcept>

namespace alplan::perception {
namespace {

bool is_variability(const std::string& feature) { return feature == "sdnn_ms" || feature == "rmssd_ms"; }

}  // namespace

StressBaseline::StressBaseline(StressFeatureSet set, std::size_t readings)
    : set_(set), wanted_(readings), mean_(feature_names(set).size(), 0.0) {}

bool StressBaseline::add(const std::vector<float>& features) {
  if (complete()) return true;
  if (features.size() != mean_.size()) throw std::invalid_argument("stress baseline: a reading of the wrong width");
  seen_ += 1;
  for (std::size_t i = 0; i < mean_.size(); ++i) mean_[i] += (features[i] - mean_[i]) / static_cast<double>(seen_);
  return complete();
}

void StressBaseline::follow(const std::vector<float>& features, std::size_t readings) {
  if (!complete()) throw std::logic_error("stress baseline: not complete yet");
  if (features.size() != mean_.size()) throw std::invalid_argument("stress baseline: a reading of the wrong width");
  if (readings == 0) return;
  for (std::size_t i = 0; i < mean_.size(); ++i) mean_[i] += (features[i] - mean_[i]) / static_cast<double>(readings);
}

std::vector<float> StressBaseline::relative(const std::vector<float>& features,
                                            const std::vector<float>& calm_centre) const {
  if (!complete()) throw std::logic_error("stress baseline: not complete yet");
  if (features.size() != mean_.size() || calm_centre.size() != mean_.size()) {
    throw std::invalid_argument("stress baseline: features, baseline and calm centre differ in width");
  }
  const std::vector<std::string> names = feature_names(set_);
  std::vector<float> out(features.size());
  for (std::size_t i = 0; i < features.size(); ++i) {
    const double own = mean_[i];
    if (is_variability(names[i])) {
      // A baseline of (almost) no variability cannot be scaled from.
      out[i] = static_cast<float>(features[i] * calm_centre[i] / std::max(own, 1.0));
    } else {
      out[i] = static_cast<float>(features[i] - own + calm_centre[i]);
    }
  }
  return out;
}

}  // namespace alplan::perception
