// The few scalar functions the core needs, written out here because the
// embedded toolchain the core is checked with (Debian's xtensa-lx106-elf-g++)
// ships no C library: there is no <math.h>, let alone <cmath>. Writing them
// out keeps one code path on host and device, tested on the host against
// <cmath>. None of them is on a per-sample path except `absolute` and
// `is_finite`; square roots are taken once per reading and tangents once at
// construction.
#pragma once

namespace alplan::firmware {

inline constexpr double kPi = 3.14159265358979323846;

// True for numbers other than NaN and the infinities.
bool is_finite(float value);
bool is_finite(double value);

inline float absolute(float value) { return value < 0.0f ? -value : value; }
inline double absolute(double value) { return value < 0.0 ? -value : value; }

// sqrt(value) to full double precision for finite value >= 0; 0 for
// value <= 0; NaN and +infinity are returned unchanged.
double square_root(double value);

// tan(angle) for |angle| < pi/2, accurate to about 1e-13 relative; outside
// that range the result is meaningless (the filters never ask for it).
double tangent(double angle);

}  // namespace alplan::firmware
