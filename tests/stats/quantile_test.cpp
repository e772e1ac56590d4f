#include "stats/quantile.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>
#include <vector>

using namespace alplan::stats;

TEST_CASE("nearest rank: the value at rank ceil(q n), computed by hand") {
  // 20..1: the p95 is rank ceil(0.95 * 20) = 19, value 19 (the rule the
  // home used before, index round(q (n - 1)), gave 19 too; it parts from
  // nearest rank below).
  std::vector<double> twenty;
  for (int i = 20; i >= 1; --i) twenty.push_back(i);
  CHECK(nearest_rank(twenty, 0.95) == 19.0);
  CHECK(nearest_rank(twenty, 0.5) == 10.0);  // rank 10: the lower middle, not 10.5
  CHECK(nearest_rank(twenty, 1.0) == 20.0);
  CHECK(nearest_rank(twenty, 0.0) == 1.0);
  CHECK(nearest_rank(twenty, 0.01) == 1.0);  // rank ceil(0.2) = 1
  CHECK(nearest_rank(twenty, 0.96) == 20.0);  // rank ceil(19.2) = 20
  // 30 calls, 28 fast and 2 slow: p95 is rank ceil(28.5) = 29, a slow call.
  std::vector<double> calls(28, 0.01);
  calls.push_back(0.6);
  calls.push_back(0.7);
  CHECK(nearest_rank(calls, 0.95) == 0.6);
  // 12 values, 1 slow: rank ceil(11.4) = 12, the slow one, where the old
  // rule's index round(0.95 * 11) = round(10.45) = 10 is a fast one: it hid
  // the slow call.
  std::vector<double> twelve(11, 0.05);
  twelve.push_back(0.9);
  CHECK(nearest_rank(twelve, 0.95) == 0.9);
  // Ties and unsorted input.
  CHECK(nearest_rank({3.0, 1.0, 2.0, 2.0}, 0.5) == 2.0);   // rank 2
  CHECK(nearest_rank({3.0, 1.0, 2.0, 2.0}, 0.75) == 2.0);  // rank 3
  CHECK(nearest_rank({3.0, 1.0, 2.0, 2.0}, 0.76) == 3.0);  // rank ceil(3.04) = 4
  CHECK(nearest_rank({7.0}, 0.95) == 7.0);
}

TEST_CASE("nearest rank: a share that is a whole rank up to rounding is that rank") {
  // Products of a share and a count that land just above a whole number in
  // doubles: their ceiling would be one rank too far.
  volatile double q07 = 0.07, q28 = 0.28, q55 = 0.55;  // computed at run time, as a caller's would be
  REQUIRE(q07 * 100 > 7.0);
  REQUIRE(q28 * 25 > 7.0);
  REQUIRE(q55 * 100 > 55.0);
  std::vector<double> hundred, twenty_five;
  for (int i = 1; i <= 100; ++i) hundred.push_back(i);
  for (int i = 1; i <= 25; ++i) twenty_five.push_back(i);
  CHECK(nearest_rank(hundred, 0.07) == 7.0);
  CHECK(nearest_rank(twenty_five, 0.28) == 7.0);
  CHECK(nearest_rank(hundred, 0.55) == 55.0);
  CHECK(nearest_rank(hundred, 0.29) == 29.0);  // 28.999999999999996 goes up anyway
  CHECK(nearest_rank(hundred, 0.291) == 30.0);
}

TEST_CASE("linear quantile: between order statistics, at 1 + q (n - 1)") {
  // {1, 2, 3, 4}: the median at position 1 + 1.5 = 2.5, between 2 and 3.
  CHECK(linear_quantile({4.0, 1.0, 3.0, 2.0}, 0.5) == Approx(2.5));
  // p95 of 1..20: position 1 + 0.95 * 19 = 19.05: 19 + 0.05 * (20 - 19).
  std::vector<double> twenty;
  for (int i = 1; i <= 20; ++i) twenty.push_back(i);
  CHECK(linear_quantile(twenty, 0.95) == Approx(19.05));
  CHECK(linear_quantile(twenty, 0.0) == 1.0);
  CHECK(linear_quantile(twenty, 1.0) == 20.0);
  // {10, 20}: p25 at position 1.25: 12.5.
  CHECK(linear_quantile({20.0, 10.0}, 0.25) == Approx(12.5));
}

TEST_CASE("quantiles of nothing are NaN, a share outside [0, 1] is refused") {
  CHECK(std::isnan(nearest_rank({}, 0.5)));
  CHECK(std::isnan(linear_quantile({}, 0.5)));
  CHECK_THROWS_AS(nearest_rank({1.0}, 1.5), std::invalid_argument);
  CHECK_THROWS_AS(linear_quantile({1.0}, -0.1), std::invalid_argument);
  CHECK_THROWS_AS(nearest_rank({1.0}, std::nan("")), std::invalid_argument);
}
