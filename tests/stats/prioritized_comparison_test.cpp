#include "stats/prioritized_comparison.h"

#include <catch2/catch.hpp>

using namespace alplan::stats;

TEST_CASE("prioritized score: success first, then the value, lower better") {
  const PrioritizedOutcome fail{false, 0.0};
  CHECK(prioritized_score(fail, fail) == 0);
  CHECK(prioritized_score({true, 5.0}, fail) == -1);
  CHECK(prioritized_score(fail, {true, 9.0}) == 1);  // any success beats a failure, however long
  CHECK(prioritized_score({true, 5.0}, {true, 3.0}) == 1);
  CHECK(prioritized_score({true, 5.0}, {true, 5.0}) == 0);
  CHECK(prioritized_score({true, 5.0}, {true, 7.0}) == -1);
  CHECK(prioritized_score({true, 100.0}, {true, 100.0 + 1e-5}) == 0);  // within the relative tolerance
  // A failure's value is never read.
  CHECK(prioritized_score({false, 1.0}, {false, 99.0}) == 0);
}

TEST_CASE("net benefit counts every pair, failures included, computed by hand") {
  const std::vector<PrioritizedOutcome> reference{{true, 5}, {true, 5}, {false, 0}, {true, 4}, {true, 2}};
  const std::vector<PrioritizedOutcome> other{{true, 3}, {false, 0}, {true, 9}, {true, 4}, {true, 6}};
  // Scores +1, -1, +1, 0, -1: two wins, two losses, a tie, net 0.
  const NetBenefit n = net_benefit(reference, other);
  CHECK(n.wins == 2);
  CHECK(n.losses == 2);
  CHECK(n.ties == 1);
  CHECK(n.scores.pairs == 5);
  CHECK(n.scores.mean_difference == Approx(0.0));
  CHECK_THROWS(net_benefit(reference, {{true, 1}}));
}

TEST_CASE("a strategy that fails on the hard cases is not made to look better by leaving them out") {
  // The reference repairs all five at distance 10; the other repairs the
  // three easy ones at 8 and fails the two hard ones. On the common set the
  // other is 2 closer in every pair; counted whole, it wins three and loses
  // two: net benefit 1/5, not a clean sweep.
  const std::vector<PrioritizedOutcome> reference(5, PrioritizedOutcome{true, 10.0});
  const std::vector<PrioritizedOutcome> other{{true, 8}, {true, 8}, {true, 8}, {false, 0}, {false, 0}};
  const NetBenefit n = net_benefit(reference, other);
  CHECK(n.wins == 3);
  CHECK(n.losses == 2);
  CHECK(n.scores.mean_difference == Approx(0.2));
  const PairedComparison common = compare_paired({10, 10, 10}, {8, 8, 8});
  CHECK(common.mean_difference == Approx(-2.0));
  CHECK(common.nonzero == 3);
}
