#include "stats/paired_comparison.h"
#include "stats/rank_tests.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace alplan::stats;

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

TEST_CASE("Wilcoxon signed-rank with ties, exact: the permutation distribution of the averaged ranks") {
  // d = {1, -2, 2, 3}: |d| = 1, 2, 2, 3 -> ranks 1, 2.5, 2.5, 4 (one pair
  // tied: tie term 2^3 - 2 = 6). W+ = 1 + 2.5 + 4 = 7.5, W- = 2.5.
  // Doubled ranks {2, 5, 5, 8}, total 20; the 16 sign assignments give the
  // positive sums 0, 2, 5, 5, 7, 7, 8, 10, 10, 12, 13, 13, 15, 15, 18, 20.
  // 2 W+ = 15, the smaller tail is 2 W- = 5: sums <= 5 are {0, 2, 5, 5},
  // 4 of 16, so p = 2 * 4/16 = 0.5.
  const SignedRank t = signed_rank_test({1, -2, 2, 3});
  CHECK(t.n == 4);
  CHECK(t.w_plus == 7.5);
  CHECK(t.w_minus == 2.5);
  CHECK(t.tie_term == 6.0);
  CHECK(t.exact);
  CHECK(t.p == Approx(0.5));
  // d = {-1, 2, 2, 3, 4}: ranks 1, 2.5, 2.5, 4, 5; W- = 1. Doubled {2, 5, 5,
  // 8, 10}: sums <= 2 are {0, 2}, 2 of 32, p = 2 * 2/32 = 0.125.
  CHECK(wilcoxon_signed_rank_p({-1, 2, 2, 3, 4}) == Approx(0.125));
}

TEST_CASE("Wilcoxon signed-rank with ties, normal approximation from 20 differences") {
  // 15 of +1, 5 of -1: all 20 tied at rank 10.5. W+ = 15 * 10.5 = 157.5,
  // mean n(n+1)/4 = 105, variance n(n+1)(2n+1)/24 - (t^3 - t)/48
  // = 717.5 - (8000 - 20)/48 = 717.5 - 166.25 = 551.25.
  // z = (|157.5 - 105| - 0.5) / sqrt(551.25) = 52 / 23.4787 = 2.21477,
  // p = erfc(z / sqrt 2) = 0.026776.
  std::vector<double> d(15, 1.0);
  d.insert(d.end(), 5, -1.0);
  const SignedRank t = signed_rank_test(d);
  CHECK_FALSE(t.exact);
  CHECK(t.w_plus == 157.5);
  CHECK(t.tie_term == 7980.0);
  CHECK(t.p == Approx(0.0267757).epsilon(1e-5));
}

TEST_CASE("ranks tie within a tolerance, grouped against each group's first value") {
  // Means of the same values summed in another order: not equal as
  // doubles, the same difference all the same.
  REQUIRE(-484.999 != -484.99899999999997);
  const std::vector<double> seven{-484.999, -484.99899999999997, -484.999, -484.99899999999997,
                                  -484.999, -484.999,            -484.99899999999997};
  // One seven-way tie: every rank (1 + 7) / 2 = 4.
  CHECK(absolute_ranks(seven, 1e-9) == std::vector<double>(7, 4.0));
  CHECK(signed_rank_test(seven).tie_term == 7.0 * 7.0 * 7.0 - 7.0);
  // Exact equality (tolerance 0) breaks it into 4 and 3: ranks 1-3 and 4-7.
  CHECK(absolute_ranks(seven, 0.0) == std::vector<double>{5.5, 2.0, 5.5, 2.0, 5.5, 5.5, 2.0});
  // Below magnitude 1 the tolerance is absolute: 1e-9.
  CHECK(absolute_ranks({0.5, 0.5 + 0.5e-9, 0.7}, 1e-9) == std::vector<double>{1.5, 1.5, 3.0});
  // 1, 1 + 0.6e-9, 1 + 1.2e-9: the second is within 1e-9 of the first, the
  // third is not (though within 1e-9 of the second): ranks 1.5, 1.5, 3.
  CHECK(absolute_ranks({1.0 + 1.2e-9, 1.0, -(1.0 + 0.6e-9)}, 1e-9) == std::vector<double>{3.0, 1.5, 1.5});
  // A difference within the tolerance of zero is a zero, and dropped.
  CHECK(signed_rank_test({1e-12, 1.0, 2.0}).n == 2);
}

TEST_CASE("effect sizes: matched-pairs rank-biserial (Kerby 2014) and d_z") {
  // {1, -2, 2, 3}: W+ = 7.5, W- = 2.5 (above): r = (7.5 - 2.5) / 10 = 0.5.
  CHECK(rank_biserial(signed_rank_test({1, -2, 2, 3})) == Approx(0.5));
  CHECK(rank_biserial(signed_rank_test({-1, -2, -3})) == Approx(-1.0));
  CHECK(rank_biserial(signed_rank_test({0, 0})) == 0.0);
  // {1, -2, 2, 3}: mean 1, squared deviations 0 + 9 + 1 + 4 = 14, sd
  // sqrt(14 / 3) = 2.16025: d_z = 0.46291.
  CHECK(standardized_mean_difference({1, -2, 2, 3}) == Approx(0.46291).epsilon(1e-4));
  CHECK(standardized_mean_difference({0, 0, 0}) == 0.0);
  CHECK(std::isnan(standardized_mean_difference({2, 2, 2})));  // no spread: no scale
  CHECK(std::isnan(standardized_mean_difference({5})));
}

TEST_CASE("paired comparison: a shifted sample has an interval that excludes zero, identical samples tie") {
  std::vector<double> a, b;
  for (int i = 0; i < 40; ++i) {
    a.push_back(100.0 + (i % 7));
    b.push_back(85.0 + (i % 5));
  }
  const PairedComparison shifted = compare_paired(a, b);
  CHECK(shifted.pairs == 40);
  CHECK(shifted.clusters == 40);  // no cluster ids: each pair its own
  CHECK(shifted.mean_difference < -10.0);
  CHECK(shifted.ci_high < 0.0);
  CHECK(shifted.ci_low <= shifted.mean_difference);
  CHECK(shifted.wilcoxon_p_adjusted == shifted.wilcoxon_p);
  CHECK(shifted.rank_biserial == -1.0);
  CHECK(shifted.significant());
  const PairedComparison same = compare_paired(a, a);
  CHECK(same.nonzero == 0);
  CHECK(same.ci_low == 0.0);
  CHECK(same.ci_high == 0.0);
  CHECK(same.d_z == 0.0);
  CHECK_FALSE(same.significant());
  // Rounding in the last digits is no difference.
  const PairedComparison rounding = compare_paired({100.0, 200.0, 300.0}, {100.0 + 1e-9, 200.0 - 1e-8, 300.0});
  CHECK(rounding.nonzero == 0);
  CHECK(rounding.wilcoxon_p == 1.0);
  // Pairs with a missing side (NaN) are left out.
  const PairedComparison partial = compare_paired({1.0, std::nan(""), 3.0}, {2.0, 5.0, 4.0});
  CHECK(partial.pairs == 2);
  CHECK_THROWS(compare_paired({1.0}, {1.0, 2.0}));
  CHECK_THROWS(compare_paired({1.0, 2.0}, {1.0, 2.0}, {"a"}));
}

TEST_CASE("clustered pairs: the homes' means drive the tests, duplicated runs do not inflate n") {
  // Home A: 5 identical runs, each -10; home B: one run, -20; home C: one
  // run, +5. Mean over the 7 runs: (-50 - 20 + 5) / 7 = -9.2857.
  const std::vector<double> reference(7, 100.0);
  const std::vector<double> other{90, 90, 90, 90, 90, 80, 105};
  const std::vector<std::string> homes{"A", "A", "A", "A", "A", "B", "C"};
  const PairedComparison clustered = compare_paired(reference, other, homes);
  CHECK(clustered.pairs == 7);
  CHECK(clustered.clusters == 3);
  CHECK(clustered.nonzero_clusters == 3);
  CHECK(clustered.positive_clusters == 1);
  CHECK(clustered.mean_difference == Approx(-65.0 / 7.0));
  // Home means -10, -20, +5: ranks 2, 3, 1; W+ = 1, W- = 5. Exact, n = 3:
  // sums of subsets of {1, 2, 3} <= 1 are {0, 1}, 2 of 8: p = 2 * 2/8 = 0.5.
  CHECK(clustered.wilcoxon_p == Approx(0.5));
  // Sign test on the homes: 1 positive of 3, p = 2 * (1 + 3)/8 = 1.
  CHECK(clustered.sign_p == Approx(1.0));
  // r = (1 - 5) / 6 = -2/3. d_z: mean -25/3, sd sqrt(316.667 / 2) = 12.583,
  // d_z = -0.66227.
  CHECK(clustered.rank_biserial == Approx(-2.0 / 3.0));
  CHECK(clustered.d_z == Approx(-0.66227).epsilon(1e-4));
  CHECK_FALSE(clustered.significant());
  // The same runs taken as independent: ranks 1 (the +5), 4 (the five
  // -10s, tied over 2..6), 7 (the -20); W+ = 1. Doubled ranks {2, 8, 8, 8,
  // 8, 8, 14}: sums <= 2 are {0, 2}, 2 of 128: p = 4/128 = 0.03125, a
  // "significant" result made of one home's copies.
  const PairedComparison runs = compare_paired(reference, other);
  CHECK(runs.clusters == 7);
  CHECK(runs.wilcoxon_p == Approx(0.03125));
  CHECK(runs.sign_p == Approx(2.0 * (1.0 + 7.0) / 128.0));
}

TEST_CASE("clustered pairs: a home whose runs cancel has mean zero") {
  // Home A: (1.3 - 1) + (1.6 - 1) + (0.1 - 1) is 1.1e-16 in doubles, not 0;
  // within the zero tolerance it is 0.
  const PairedComparison c = compare_paired({1.0, 1.0, 1.0, 1.0}, {1.3, 1.6, 0.1, 3.0}, {"A", "A", "A", "B"});
  CHECK(c.clusters == 2);
  CHECK(c.nonzero_clusters == 1);
  CHECK(c.positive_clusters == 1);
}

TEST_CASE("the cluster bootstrap is wider than the run bootstrap on clustered data, and seeded") {
  // 6 homes of 5 identical runs: 30 runs but 6 independent values, so the
  // run bootstrap's interval is about sqrt(5) too narrow.
  const std::vector<double> home_differences{-10, -4, -1, 2, 3, 6};
  std::vector<double> reference, other;
  std::vector<std::string> homes;
  for (std::size_t h = 0; h < home_differences.size(); ++h) {
    for (int r = 0; r < 5; ++r) {
      reference.push_back(50.0);
      other.push_back(50.0 + home_differences[h]);
      homes.push_back("home-" + std::to_string(h));
    }
  }
  const PairedComparison clustered = compare_paired(reference, other, homes);
  const PairedComparison runs = compare_paired(reference, other);
  CHECK(clustered.mean_difference == Approx(runs.mean_difference));
  CHECK(clustered.ci_low < clustered.mean_difference);
  CHECK(clustered.ci_high > clustered.mean_difference);
  CHECK(clustered.ci_high - clustered.ci_low > 1.8 * (runs.ci_high - runs.ci_low));
  // Deterministic for a seed, another seed draws other homes.
  const PairedComparison again = compare_paired(reference, other, homes);
  CHECK(again.ci_low == clustered.ci_low);
  CHECK(again.ci_high == clustered.ci_high);
  BootstrapOptions seed2;
  seed2.seed = 2;
  const PairedComparison other_seed = compare_paired(reference, other, homes, seed2);
  CHECK((other_seed.ci_low != clustered.ci_low || other_seed.ci_high != clustered.ci_high));
}
