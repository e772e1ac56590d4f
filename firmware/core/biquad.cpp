#include "biquad.h"

#include "scalar_math.h"

namespace alplan::firmware {

namespace {

struct Prewarped {
  double k2;    // K^2
  double norm;  // 1 / (1 + K/Q + K^2)
  double a1;
  double a2;
};

Prewarped prewarp(double cutoff_hz, double sample_rate_hz, double q) {
  const double k = tangent(kPi * cutoff_hz / sample_rate_hz);
  const double k2 = k * k;
  const double norm = 1.0 / (1.0 + k / q + k2);
  return {k2, norm, 2.0 * (k2 - 1.0) * norm, (1.0 - k / q + k2) * norm};
}

}  // namespace

BiquadCoefficients butterworth_low_pass_section(double cutoff_hz, double sample_rate_hz, double q) {
  const Prewarped p = prewarp(cutoff_hz, sample_rate_hz, q);
  const double b0 = p.k2 * p.norm;
  return {b0, 2.0 * b0, b0, p.a1, p.a2};
}

BiquadCoefficients butterworth_high_pass_section(double cutoff_hz, double sample_rate_hz, double q) {
  const Prewarped p = prewarp(cutoff_hz, sample_rate_hz, q);
  return {p.norm, -2.0 * p.norm, p.norm, p.a1, p.a2};
}

double Biquad::dc_gain() const { return (c_.b0 + c_.b1 + c_.b2) / (1.0 + c_.a1 + c_.a2); }

double Biquad::settle(double input) {
  const double output = dc_gain() * input;
  s2_ = c_.b2 * input - c_.a2 * output;
  s1_ = c_.b1 * input - c_.a1 * output + s2_;
  return output;
}

}  // namespace alplan::firmware
