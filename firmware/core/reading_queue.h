// A bounded FIFO of encoded readings, for the time Wi-Fi or the service is
// down: it keeps the unsent readings and hands them out oldest first. When
// full, a new reading drops the oldest one (recent readings matter more to a
// stress monitor than old ones) and the drop is counted.
//
// Sending is two-phase so nothing is lost when a POST fails: write_batch()
// copies the oldest readings into a request body without removing them, and
// release_before() removes them once the service has acknowledged them. Every
// reading gets an id (the count of readings pushed before it); releasing by
// id stays correct even when readings were dropped and others pushed while
// the request was in flight.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "reading_encoder.h"
#include "ring_buffer.h"

namespace alplan::firmware {

struct QueuedBatch {
  size_t length = 0;    // of the JSON array written, without the '\0'
  size_t count = 0;     // readings in it
  uint64_t end_id = 0;  // release_before(end_id) removes exactly these (or what is left of them)
};

template <size_t Capacity, size_t MaxLength = kMaxReadingJsonLength>
class ReadingQueue {
  static_assert(MaxLength >= 2, "an entry needs room for a character and the terminator");

 public:
  static constexpr size_t capacity() { return Capacity; }
  size_t size() const { return entries_.size(); }
  bool empty() const { return entries_.empty(); }
  uint64_t dropped() const { return dropped_; }
  uint64_t next_id() const { return next_id_; }

  // Stores a copy of json[0..length). False, storing nothing, when it does not
  // fit an entry (length > MaxLength - 1).
  bool push(const char* json, size_t length) {
    if (length > MaxLength - 1) return false;
    Entry entry;
    for (size_t i = 0; i < length; ++i) entry.text[i] = json[i];
    entry.text[length] = '\0';
    entry.length = length;
    entry.id = next_id_++;
    if (entries_.push_back_overwrite(entry)) ++dropped_;
    return true;
  }

  // The oldest reading, '\0'-terminated. Precondition: !empty().
  const char* oldest() const { return entries_.front().text; }
  size_t oldest_length() const { return entries_.front().length; }
  uint64_t oldest_id() const { return entries_.front().id; }
  bool pop() { return entries_.pop_front(); }

  // As many of the oldest readings as fit in `capacity` (with the brackets,
  // commas and the terminator), at most max_readings, as a JSON array. With
  // no reading written (empty queue, or the oldest does not fit) the buffer
  // holds "" and count is 0.
  QueuedBatch write_batch(char* buffer, size_t capacity, size_t max_readings) const {
    QueuedBatch batch;
    size_t used = 1;  // '['
    for (size_t i = 0; i < entries_.size() && batch.count < max_readings; ++i) {
      const Entry& entry = entries_[i];
      const size_t needed = used + (batch.count > 0 ? 1 : 0) + entry.length + 2;  // ',' entry ']' '\0'
      if (needed > capacity) break;
      if (batch.count > 0) buffer[used++] = ',';
      for (size_t k = 0; k < entry.length; ++k) buffer[used + k] = entry.text[k];
      used += entry.length;
      ++batch.count;
      batch.end_id = entry.id + 1;
    }
    if (batch.count == 0) {
      if (capacity > 0) buffer[0] = '\0';
      return batch;
    }
    buffer[0] = '[';
    buffer[used++] = ']';
    buffer[used] = '\0';
    batch.length = used;
    return batch;
  }

  // Removes the readings whose id is below end_id.
  void release_before(uint64_t end_id) {
    while (!entries_.empty() && entries_.front().id < end_id) entries_.pop_front();
  }

 private:
  struct Entry {
    char text[MaxLength];
    size_t length;
    uint64_t id;
  };
  RingBuffer<Entry, Capacity> entries_;
  uint64_t next_id_ = 0;
  uint64_t dropped_ = 0;
};

}  // namespace alplan::firmware
