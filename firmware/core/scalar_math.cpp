#include "scalar_math.h"

#include <float.h>

namespace alplan::firmware {

bool is_finite(float value) { return value == value && value <= FLT_MAX && value >= -FLT_MAX; }

bool is_finite(double value) { return value == value && value <= DBL_MAX && value >= -DBL_MAX; }

double square_root(double value) {
  if (!(value > 0.0)) return value == value ? 0.0 : value;
  if (value > DBL_MAX) return value;
  // Scale into [0.25, 1) by powers of four so that Newton's iteration starts
  // within 10 % of the root; six iterations then reach full precision.
  double mantissa = value;
  double scale = 1.0;
  while (mantissa >= 1.0) {
    mantissa *= 0.25;
    scale *= 2.0;
  }
  while (mantissa < 0.25) {
    mantissa *= 4.0;
    scale *= 0.5;
  }
  double root = 0.5 + 0.5 * mantissa;
  for (int iteration = 0; iteration < 6; ++iteration) root = 0.5 * (root + mantissa / root);
  return root * scale;
}

namespace {

// Taylor series about 0; on |x| <= pi/2 the first omitted terms are below
// 1e-15, which is why the series stop where they do.
double sine(double x) {
  const double x2 = x * x;
  double term = x;
  double sum = x;
  for (int k = 1; k <= 10; ++k) {
    term *= -x2 / static_cast<double>((2 * k) * (2 * k + 1));
    sum += term;
  }
  return sum;
}

double cosine(double x) {
  const double x2 = x * x;
  double term = 1.0;
  double sum = 1.0;
  for (int k = 1; k <= 10; ++k) {
    term *= -x2 / static_cast<double>((2 * k - 1) * (2 * k));
    sum += term;
  }
  return sum;
}

}  // namespace

double tangent(double angle) { return sine(angle) / cosine(angle); }

}  // namespace alplan::firmware
