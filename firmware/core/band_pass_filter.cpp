#include "band_pass_filter.h"

namespace alplan::firmware {

namespace {
// Q of the two sections of a fourth-order Butterworth filter,
// 1 / (2 cos(pi/8)) and 1 / (2 cos(3 pi/8)).
constexpr double kQ4th[2] = {0.54119610014619698, 1.3065629648763766};
}  // namespace

bool band_is_valid(const BandPassConfig& config) {
  return config.low_cut_hz > 0.0f && config.low_cut_hz < config.high_cut_hz &&
         config.high_cut_hz < 0.45f * config.sample_rate_hz;
}

BandPassFilter::BandPassFilter(const BandPassConfig& config) {
  if (!band_is_valid(config)) return;
  const auto fs = static_cast<double>(config.sample_rate_hz);
  const auto low = static_cast<double>(config.low_cut_hz);
  const auto high = static_cast<double>(config.high_cut_hz);
  sections_[0] = Biquad(butterworth_high_pass_section(low, fs, kQ4th[0]));
  sections_[1] = Biquad(butterworth_high_pass_section(low, fs, kQ4th[1]));
  sections_[2] = Biquad(butterworth_low_pass_section(high, fs, kQ4th[0]));
  sections_[3] = Biquad(butterworth_low_pass_section(high, fs, kQ4th[1]));
}

float BandPassFilter::process(float sample) {
  auto value = static_cast<double>(sample);
  if (!settled_) {
    settled_ = true;
    for (Biquad& section : sections_) value = section.settle(value);
    return static_cast<float>(value);
  }
  for (Biquad& section : sections_) value = section.process(value);
  return static_cast<float>(value);
}

}  // namespace alplan::firmware
