#include <catch2/catch.hpp>

#include "firmware/core/order_statistics.h"
#include "firmware/core/ring_buffer.h"

using alplan::firmware::RingBuffer;

TEST_CASE("a ring buffer keeps elements oldest first and refuses a push when full") {
  RingBuffer<int, 3> ring;
  CHECK(ring.empty());
  CHECK(ring.push_back(1));
  CHECK(ring.push_back(2));
  CHECK(ring.push_back(3));
  CHECK(ring.full());
  CHECK_FALSE(ring.push_back(4));
  REQUIRE(ring.size() == 3);
  CHECK(ring[0] == 1);
  CHECK(ring[2] == 3);
  CHECK(ring.front() == 1);
  CHECK(ring.back() == 3);
}

TEST_CASE("a ring buffer wraps around its storage as elements come and go") {
  RingBuffer<int, 3> ring;
  for (int i = 0; i < 10; ++i) {
    ring.push_back(i);
    if (ring.size() == 3) CHECK(ring.pop_front());
  }
  REQUIRE(ring.size() == 2);
  CHECK(ring[0] == 8);
  CHECK(ring[1] == 9);
  CHECK(ring.pop_front());
  CHECK(ring.pop_front());
  CHECK_FALSE(ring.pop_front());
  CHECK(ring.empty());
}

TEST_CASE("overwriting push drops the oldest element and says so") {
  RingBuffer<int, 2> ring;
  CHECK_FALSE(ring.push_back_overwrite(1));
  CHECK_FALSE(ring.push_back_overwrite(2));
  CHECK(ring.push_back_overwrite(3));
  REQUIRE(ring.size() == 2);
  CHECK(ring[0] == 2);
  CHECK(ring[1] == 3);
  ring.clear();
  CHECK(ring.empty());
  CHECK_FALSE(ring.push_back_overwrite(7));
  CHECK(ring.front() == 7);
}

TEST_CASE("medians of small arrays") {
  using alplan::firmware::median_in_place;
  float odd[] = {5.0f, 1.0f, 3.0f};
  CHECK(median_in_place(odd, 3) == 3.0f);
  float even[] = {4.0f, 1.0f, 3.0f, 2.0f};
  CHECK(median_in_place(even, 4) == 2.5f);
  CHECK(even[0] == 1.0f);  // sorted in place
  CHECK(median_in_place(even, 0) == 0.0f);
}
