#include <catch2/catch.hpp>

#include <atomic>
#include <set>
#include <thread>
#include <vector>

#include "perception/service/stress_event_queue.h"

using namespace alplan::perception::service;
using namespace std::chrono_literals;

namespace {

StressEvent event_at(std::uint64_t t_ms) { return {"senior", "wb", true, t_ms, 1.0, 3}; }

}  // namespace

TEST_CASE("stress events: first in first out, when full the oldest goes and is counted") {
  StressEventQueue queue(3);
  CHECK_FALSE(queue.try_pop());
  for (std::uint64_t t = 1; t <= 5; ++t) CHECK(queue.push(event_at(t)));
  CHECK(queue.size() == 3);
  CHECK(queue.dropped() == 2);
  CHECK(queue.try_pop()->t_ms == 3);
  CHECK(queue.pop_wait(10ms)->t_ms == 4);
  CHECK(queue.try_pop()->t_ms == 5);
  CHECK_FALSE(queue.try_pop());
  CHECK_THROWS_AS(StressEventQueue(0), std::invalid_argument);
}

TEST_CASE("stress events: pop_wait times out when empty, and close wakes a waiter") {
  StressEventQueue queue(4);
  const auto start = std::chrono::steady_clock::now();
  CHECK_FALSE(queue.pop_wait(50ms));
  CHECK(std::chrono::steady_clock::now() - start >= 45ms);

  std::thread closer([&queue] {
    std::this_thread::sleep_for(50ms);
    queue.close();
  });
  const auto wait_start = std::chrono::steady_clock::now();
  CHECK_FALSE(queue.pop_wait(10s));
  CHECK(std::chrono::steady_clock::now() - wait_start < 5s);
  closer.join();
  CHECK(queue.closed());
  CHECK_FALSE(queue.push(event_at(1)));
}

TEST_CASE("stress events: what was queued before close can still be popped") {
  StressEventQueue queue(4);
  queue.push(event_at(7));
  queue.close();
  CHECK(queue.pop_wait(1s)->t_ms == 7);
  CHECK_FALSE(queue.pop_wait(1ms));
}

TEST_CASE("stress events: many producers and consumers lose nothing that fits") {
  StressEventQueue queue(100000);
  constexpr int kProducers = 4, kPerProducer = 5000;
  std::vector<std::thread> threads;
  for (int p = 0; p < kProducers; ++p) {
    threads.emplace_back([&queue, p] {
      for (int i = 0; i < kPerProducer; ++i) queue.push(event_at(static_cast<std::uint64_t>(p * kPerProducer + i)));
    });
  }
  std::mutex seen_mutex;
  std::set<std::uint64_t> seen;
  std::atomic<int> popped{0};
  for (int c = 0; c < 3; ++c) {
    threads.emplace_back([&] {
      while (popped.load() < kProducers * kPerProducer) {
        if (auto e = queue.pop_wait(5ms)) {
          const std::lock_guard lock(seen_mutex);
          seen.insert(e->t_ms);
          popped.fetch_add(1);
        }
      }
    });
  }
  for (std::thread& t : threads) t.join();
  CHECK(seen.size() == static_cast<std::size_t>(kProducers * kPerProducer));
  CHECK(queue.dropped() == 0);
}
