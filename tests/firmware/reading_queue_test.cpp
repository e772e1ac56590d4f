#include <catch2/catch.hpp>

#include <cstring>
#include <string>

#include "firmware/core/reading_queue.h"

using alplan::firmware::QueuedBatch;
using alplan::firmware::ReadingQueue;

namespace {
template <std::size_t N, std::size_t L>
bool push(ReadingQueue<N, L>& queue, const std::string& json) {
  return queue.push(json.data(), json.size());
}
}  // namespace

TEST_CASE("the queue hands readings out oldest first") {
  ReadingQueue<4, 32> queue;
  CHECK(push(queue, "{\"seq\":0}"));
  CHECK(push(queue, "{\"seq\":1}"));
  REQUIRE(queue.size() == 2);
  CHECK(std::string(queue.oldest()) == "{\"seq\":0}");
  CHECK(queue.oldest_length() == 9);
  CHECK(queue.pop());
  CHECK(std::string(queue.oldest()) == "{\"seq\":1}");
  CHECK(queue.pop());
  CHECK_FALSE(queue.pop());
  CHECK(queue.dropped() == 0);
}

TEST_CASE("a full queue drops its oldest reading and counts the drop") {
  ReadingQueue<3, 32> queue;
  for (int i = 0; i < 5; ++i) CHECK(push(queue, "{\"seq\":" + std::to_string(i) + "}"));
  CHECK(queue.size() == 3);
  CHECK(queue.dropped() == 2);
  CHECK(std::string(queue.oldest()) == "{\"seq\":2}");
  CHECK(queue.oldest_id() == 2);
  CHECK(queue.next_id() == 5);
}

TEST_CASE("a reading longer than an entry is refused, not truncated") {
  ReadingQueue<2, 8> queue;
  CHECK(push(queue, "1234567"));
  CHECK_FALSE(push(queue, "12345678"));
  CHECK(queue.size() == 1);
  CHECK(queue.dropped() == 0);
}

TEST_CASE("a batch is a JSON array of the oldest readings that fit, released only on request") {
  ReadingQueue<8, 32> queue;
  for (int i = 0; i < 4; ++i) push(queue, "{\"seq\":" + std::to_string(i) + "}");
  char body[64];

  QueuedBatch batch = queue.write_batch(body, sizeof body, 3);
  CHECK(std::string(body) == "[{\"seq\":0},{\"seq\":1},{\"seq\":2}]");
  CHECK(batch.count == 3);
  CHECK(batch.length == std::strlen(body));
  CHECK(queue.size() == 4);  // nothing removed until the service has them

  queue.release_before(batch.end_id);
  REQUIRE(queue.size() == 1);
  CHECK(std::string(queue.oldest()) == "{\"seq\":3}");

  // Room for one reading only: "[" + 9 + "]" + NUL = 12.
  push(queue, "{\"seq\":4}");
  char small[12];
  batch = queue.write_batch(small, sizeof small, 10);
  CHECK(batch.count == 1);
  CHECK(std::string(small) == "[{\"seq\":3}]");

  char tiny[11];
  batch = queue.write_batch(tiny, sizeof tiny, 10);
  CHECK(batch.count == 0);
  CHECK(batch.length == 0);
  CHECK(std::string(tiny).empty());
}

TEST_CASE("releasing a batch stays correct when readings were dropped while it was in flight") {
  ReadingQueue<3, 32> queue;
  for (int i = 0; i < 3; ++i) push(queue, "{\"seq\":" + std::to_string(i) + "}");
  char body[64];
  const QueuedBatch batch = queue.write_batch(body, sizeof body, 2);  // seq 0 and 1
  CHECK(batch.end_id == 2);
  // Two more readings arrive during the POST and push out seq 0 and 1.
  push(queue, "{\"seq\":3}");
  push(queue, "{\"seq\":4}");
  queue.release_before(batch.end_id);
  REQUIRE(queue.size() == 3);  // seq 2, 3, 4 are all still unsent
  CHECK(std::string(queue.oldest()) == "{\"seq\":2}");
  CHECK(queue.dropped() == 2);
}
