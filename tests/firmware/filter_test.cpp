#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "firmware/core/band_pass_filter.h"
#include "firmware/core/biquad.h"
#include "firmware/core/scalar_math.h"

using namespace alplan::firmware;

namespace {

// The steady-state gain of a fresh filter for a sine of `frequency_hz`:
// the output's peak over the last 25 s of 60 s (more than a period of the
// slowest sine, after the start-up transient), over the input's.
double gain(float sample_rate_hz, double frequency_hz) {
  BandPassFilter filter({sample_rate_hz, 0.5f, 5.0f});
  const double fs = sample_rate_hz;
  const auto samples = static_cast<int>(60.0 * fs);
  double peak = 0.0;
  for (int i = 0; i < samples; ++i) {
    const double x = std::sin(2.0 * std::numbers::pi * frequency_hz * i / fs);
    const double y = filter.process(static_cast<float>(x));
    if (i >= samples - static_cast<int>(25.0 * fs)) peak = std::max(peak, std::abs(y));
  }
  return peak;
}

double decibels(double ratio) { return 20.0 * std::log10(ratio); }

}  // namespace

TEST_CASE("the band-pass passes the pulse band and attenuates outside it, at any sample rate") {
  for (float fs : {25.0f, 50.0f, 100.0f, 250.0f, 500.0f}) {
    INFO("sample rate " << fs << " Hz");
    for (double f : {1.0, 1.5, 2.0, 3.0}) {
      INFO("pass band " << f << " Hz");
      CHECK(std::abs(decibels(gain(fs, f))) < 1.0);
    }
    CHECK(std::abs(decibels(gain(fs, 0.5)) + 3.0) < 0.5);  // Butterworth: -3 dB at the cutoffs
    CHECK(std::abs(decibels(gain(fs, 5.0)) + 3.0) < 0.5);
    CHECK(decibels(gain(fs, 0.25)) < -20.0);  // breathing's baseline wander
    CHECK(decibels(gain(fs, 0.05)) < -60.0);  // slow drift
    CHECK(decibels(gain(fs, 10.0)) < -20.0);
    if (fs >= 50.0f) CHECK(decibels(gain(fs, 20.0)) < -40.0);
  }
}

TEST_CASE("the filter settles on its first sample, so a large DC level does not ring") {
  BandPassFilter filter({100.0f, 0.5f, 5.0f});
  double worst = 0.0;
  for (int i = 0; i < 1000; ++i) worst = std::max(worst, std::abs(static_cast<double>(filter.process(2000.0f))));
  CHECK(worst < 1e-6);
}

TEST_CASE("a band outside what the sample rate allows is refused") {
  CHECK(band_is_valid({100.0f, 0.5f, 5.0f}));
  CHECK_FALSE(band_is_valid({10.0f, 0.5f, 5.0f}));  // 5 Hz is at Nyquist
  CHECK_FALSE(band_is_valid({100.0f, 5.0f, 0.5f}));
  CHECK_FALSE(band_is_valid({100.0f, 0.0f, 5.0f}));
}

TEST_CASE("Butterworth sections have unit gain in their pass band and the Butterworth Q") {
  const Biquad low(butterworth_low_pass_section(5.0, 100.0, std::sqrt(0.5)));
  CHECK(low.dc_gain() == Approx(1.0).epsilon(1e-12));
  const Biquad high(butterworth_high_pass_section(0.5, 100.0, std::sqrt(0.5)));
  CHECK(std::abs(high.dc_gain()) < 1e-12);
}

TEST_CASE("the core's own square root and tangent agree with <cmath>") {
  for (double x : {0.0, 1e-300, 1e-9, 0.25, 0.5, 1.0, 2.0, 3.0, 1234.5678, 1e9, 1e300}) {
    INFO(x);
    CHECK(square_root(x) == Approx(std::sqrt(x)).epsilon(1e-15));
  }
  CHECK(square_root(-4.0) == 0.0);
  CHECK(std::isnan(square_root(std::numeric_limits<double>::quiet_NaN())));
  CHECK(square_root(std::numeric_limits<double>::infinity()) == std::numeric_limits<double>::infinity());
  for (double x = -1.5; x <= 1.5; x += 0.01) {
    INFO(x);
    CHECK(tangent(x) == Approx(std::tan(x)).epsilon(1e-12).margin(1e-15));
  }
  CHECK(is_finite(1.0f));
  CHECK_FALSE(is_finite(std::numeric_limits<float>::infinity()));
  CHECK_FALSE(is_finite(std::numeric_limits<float>::quiet_NaN()));
  CHECK_FALSE(is_finite(-std::numeric_limits<double>::infinity()));
}
