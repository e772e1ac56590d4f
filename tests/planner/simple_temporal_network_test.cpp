#include "planner/simple_temporal_network.h"

#include <catch2/catch.hpp>

using namespace alplan;

TEST_CASE("the network keeps the earliest time of every node") {
  SimpleTemporalNetwork stn;
  REQUIRE(stn.add_node({{0, 1, 2.0}}));            // t1 >= 2
  REQUIRE(stn.add_node({{1, 2, 3.0}}));            // t2 >= t1 + 3
  CHECK(stn.earliest(1) == Approx(2.0));
  CHECK(stn.earliest(2) == Approx(5.0));
  // A later constraint that pushes an earlier node propagates forward.
  REQUIRE(stn.add_node({{0, 3, 10.0}, {3, 1, 0.5}}));  // t3 >= 10, t1 >= t3 + 0.5
  CHECK(stn.earliest(1) == Approx(10.5));
  CHECK(stn.earliest(2) == Approx(13.5));
}

TEST_CASE("an upper bound that cannot hold is refused and leaves the network unchanged") {
  SimpleTemporalNetwork stn;
  REQUIRE(stn.add_node({{0, 1, 0.0}}));
  REQUIRE(stn.add_node({{1, 2, 5.0}, {2, 1, -7.0}}));  // t2 in [t1+5, t1+7]
  const auto before = stn.earliest_times();
  const auto edges = stn.edges().size();
  // t3 >= t2 + 1 and t3 <= t1 + 5: inconsistent with t2 >= t1 + 5.
  CHECK_FALSE(stn.add_node({{2, 3, 1.0}, {3, 1, -5.0}}));
  CHECK(stn.earliest_times() == before);
  CHECK(stn.edges().size() == edges);
  // A deadline: t2 <= 4 from the origin, while t2 >= 5.
  CHECK_FALSE(stn.add_edges({{2, 0, -4.0}}));
  CHECK(stn.earliest_times() == before);
  // A deadline that holds is kept.
  CHECK(stn.add_edges({{2, 0, -6.0}}));
  CHECK(stn.earliest(2) == Approx(5.0));
}

TEST_CASE("several nodes can be added at once with constraints among them") {
  SimpleTemporalNetwork stn;
  REQUIRE(stn.add_nodes(2, {{0, 1, 1.0}, {1, 2, 4.0}, {2, 1, -6.0}}));
  CHECK(stn.size() == 3);
  CHECK(stn.earliest(2) == Approx(5.0));
  CHECK_FALSE(stn.add_nodes(2, {{0, 3, 1.0}, {3, 4, 4.0}, {4, 3, -3.0}}));
  CHECK(stn.size() == 3);
}

TEST_CASE("copies of a network are independent, as search states need") {
  SimpleTemporalNetwork a;
  REQUIRE(a.add_node({{0, 1, 1.0}}));
  SimpleTemporalNetwork b = a;
  REQUIRE(b.add_node({{1, 2, 1.0}, {0, 1, 3.0}}));
  CHECK(a.size() == 2);
  CHECK(a.earliest(1) == Approx(1.0));
  CHECK(b.earliest(1) == Approx(3.0));
}
