// One second-order IIR section (a "biquad") in transposed direct form II,
// and the Butterworth low- and high-pass sections it is designed as.
//
// Design: the analogue prototype mapped by the bilinear transform with the
// cutoff pre-warped (K = tan(pi fc / fs)); the formulas are those of R.
// Bristow-Johnson's "Cookbook formulae for audio EQ biquad filter
// coefficients". A Butterworth filter of order 2N is N such sections with
// Q_k = 1 / (2 cos((2k - 1) pi / (4N))).
//
// Coefficients and state are double: at 500 Hz a 0.5 Hz high-pass puts the
// poles within 0.3 % of the unit circle, where float round-off in the state
// would be amplified by the pole gain into visible noise. The cost is a few
// soft-float operations per sample, small against the ESP32's budget.
#pragma once

namespace alplan::firmware {

struct BiquadCoefficients {
  double b0 = 1.0, b1 = 0.0, b2 = 0.0;  // numerator
  double a1 = 0.0, a2 = 0.0;            // denominator, a0 normalised to 1
};

// Preconditions: 0 < cutoff_hz < sample_rate_hz / 2, q > 0.
BiquadCoefficients butterworth_low_pass_section(double cutoff_hz, double sample_rate_hz, double q);
BiquadCoefficients butterworth_high_pass_section(double cutoff_hz, double sample_rate_hz, double q);

class Biquad {
 public:
  Biquad() = default;  // the identity filter
  explicit Biquad(const BiquadCoefficients& coefficients) : c_(coefficients) {}

  double process(double input) {
    const double output = c_.b0 * input + s1_;
    s1_ = c_.b1 * input - c_.a1 * output + s2_;
    s2_ = c_.b2 * input - c_.a2 * output;
    return output;
  }

  // Puts the section in the steady state it would reach after a constant
  // `input` forever, so a signal starting far from zero (a PPG's large DC
  // level) does not ring through the filter for seconds. Returns that steady
  // output.
  double settle(double input);

  // The gain at 0 Hz, (b0 + b1 + b2) / (1 + a1 + a2).
  double dc_gain() const;

 private:
  BiquadCoefficients c_{};
  double s1_ = 0.0;
  double s2_ = 0.0;
};

}  // namespace alplan::firmware
