#include "benchmarks/harness/paired_statistics.h"

#include <catch2/catch.hpp>

using namespace alplan::bench;

TEST_CASE("the sign test is the exact binomial, two-sided") {
  CHECK(sign_test_p(0, 0) == 1.0);
  CHECK(sign_test_p(5, 5) == Approx(2.0 / 32.0));
  CHECK(sign_test_p(8, 10) == Approx(2.0 * (1.0 + 10.0 + 45.0) / 1024.0));
  CHECK(sign_test_p(5, 10) == 1.0);
}

TEST_CASE("Wilcoxon signed-rank: exact for small samples, normal approximation with ties") {
  // All five differences positive: W+ = 15, P = 2/32 exactly.
  CHECK(wilcoxon_signed_rank_p({1, 2, 3, 4, 5}) == Approx(0.0625));
  // Zeros are dropped; symmetric differences give p = 1.
  CHECK(wilcoxon_signed_rank_p({0, 0, 1, -1, 2, -2}) == Approx(1.0));
  CHECK(wilcoxon_signed_rank_p({}) == 1.0);
  // 30 equal positive differences (all tied): z large, p tiny.
  CHECK(wilcoxon_signed_rank_p(std::vector<double>(30, 15.0)) < 1e-5);
  // A textbook case (n = 10, no ties; W- = 5 -> exact two-sided p = 0.0195).
  CHECK(wilcoxon_signed_rank_p({1.1, 2.2, 3.3, 4.4, -5.5, 6.6, 7.7, 8.8, 9.9, 10.0}) == Approx(0.0195).margin(0.001));
}

TEST_CASE("paired comparison: a shifted sample has an interval that excludes zero, identical samples tie") {
  std::vector<double> a, b;
  for (int i = 0; i < 40; ++i) {
    a.push_back(100.0 + (i % 7));
    b.push_back(85.0 + (i % 5));
  }
  const PairedComparison shifted = compare_paired(a, b);
  CHECK(shifted.pairs == 40);
  CHECK(shifted.mean_difference < -10.0);
  CHECK(shifted.ci_high < 0.0);
  CHECK(shifted.ci_low <= shifted.mean_difference);
  CHECK(shifted.significant());
  const PairedComparison same = compare_paired(a, a);
  CHECK(same.nonzero == 0);
  CHECK(same.ci_low == 0.0);
  CHECK(same.ci_high == 0.0);
  CHECK_FALSE(same.significant());
  // Rounding in the last digits is no difference.
  const PairedComparison rounding = compare_paired({100.0, 200.0, 300.0}, {100.0 + 1e-9, 200.0 - 1e-8, 300.0});
  CHECK(rounding.nonzero == 0);
  CHECK(rounding.wilcoxon_p == 1.0);
  // Pairs with a missing side (NaN) are left out.
  const PairedComparison partial = compare_paired({1.0, std::nan(""), 3.0}, {2.0, 5.0, 4.0});
  CHECK(partial.pairs == 2);
  CHECK_THROWS(compare_paired({1.0}, {1.0, 2.0}));
}
