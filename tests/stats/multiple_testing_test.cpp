#include "stats/multiple_testing.h"

#include <catch2/catch.hpp>

using namespace alplan::stats;

TEST_CASE("Holm's step-down adjustment") {
  // {0.01, 0.04, 0.03, 0.005}, m = 4, sorted 0.005, 0.01, 0.03, 0.04:
  // 4 * 0.005 = 0.02; 3 * 0.01 = 0.03; 2 * 0.03 = 0.06; 1 * 0.04 = 0.04,
  // raised to 0.06 to stay monotone. In the given order: 0.03, 0.06, 0.06, 0.02.
  const std::vector<double> adjusted = holm_adjust({0.01, 0.04, 0.03, 0.005});
  REQUIRE(adjusted.size() == 4);
  CHECK(adjusted[0] == Approx(0.03));
  CHECK(adjusted[1] == Approx(0.06));
  CHECK(adjusted[2] == Approx(0.06));
  CHECK(adjusted[3] == Approx(0.02));
  // Capped at 1: 2 * 0.5 = 1; 0.6 raised to 1.
  CHECK(holm_adjust({0.5, 0.6}) == std::vector<double>{1.0, 1.0});
  CHECK(holm_adjust({0.2}) == std::vector<double>{0.2});
  CHECK(holm_adjust({}).empty());
}

TEST_CASE("Benjamini-Hochberg's step-up adjustment") {
  // {0.01, 0.04, 0.03, 0.005}, m = 4, sorted 0.005, 0.01, 0.03, 0.04 at
  // ranks 1-4: m p / rank = 0.02, 0.02, 0.04, 0.04; the minimum from the
  // top down leaves them so. In the given order: 0.02, 0.04, 0.04, 0.02.
  const std::vector<double> adjusted = benjamini_hochberg_adjust({0.01, 0.04, 0.03, 0.005});
  REQUIRE(adjusted.size() == 4);
  CHECK(adjusted[0] == Approx(0.02));
  CHECK(adjusted[1] == Approx(0.04));
  CHECK(adjusted[2] == Approx(0.04));
  CHECK(adjusted[3] == Approx(0.02));
  // {0.01, 0.2, 0.03}, m = 3, sorted 0.01, 0.03, 0.2: 0.03, 0.045, 0.2.
  // {0.04, 0.05}: 2 * 0.04 / 1 = 0.08 lowered to 0.05, the next rank's.
  const std::vector<double> three = benjamini_hochberg_adjust({0.01, 0.2, 0.03});
  REQUIRE(three.size() == 3);
  CHECK(three[0] == Approx(0.03));
  CHECK(three[1] == Approx(0.2));
  CHECK(three[2] == Approx(0.045));
  const std::vector<double> lowered = benjamini_hochberg_adjust({0.04, 0.05});
  CHECK(lowered[0] == Approx(0.05));
  CHECK(lowered[1] == Approx(0.05));
  // Capped at 1, and never above Holm's.
  CHECK(benjamini_hochberg_adjust({0.6, 0.9}) == std::vector<double>{0.9, 0.9});
  const std::vector<double> p{0.001, 0.02, 0.03, 0.2, 0.5};
  const std::vector<double> holm = holm_adjust(p), bh = benjamini_hochberg_adjust(p);
  for (std::size_t i = 0; i < p.size(); ++i) CHECK(bh[i] <= holm[i]);
  CHECK(benjamini_hochberg_adjust({}).empty());
}
