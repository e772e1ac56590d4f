// A fixed-capacity FIFO ring buffer: the storage lives inside the object, so
// it never allocates. Index 0 is the oldest element.
//
// Contract: front(), back() and operator[] with an index >= size() are
// precondition violations; they stay memory-safe (the index wraps inside the
// storage) but return an unspecified element. Nothing throws.
#pragma once

#include <stddef.h>

namespace alplan::firmware {

template <typename T, size_t Capacity>
class RingBuffer {
  static_assert(Capacity > 0, "a ring buffer needs room for one element");

 public:
  static constexpr size_t capacity() { return Capacity; }
  size_t size() const { return count_; }
  bool empty() const { return count_ == 0; }
  bool full() const { return count_ == Capacity; }

  // Appends `value`; when full, stores nothing and returns false.
  bool push_back(const T& value) {
    if (full()) return false;
    items_[slot(count_)] = value;
    ++count_;
    return true;
  }

  // Appends `value`, dropping the oldest element when full; returns true
  // when an element was dropped.
  bool push_back_overwrite(const T& value) {
    if (!full()) {
      push_back(value);
      return false;
    }
    items_[head_] = value;
    head_ = (head_ + 1) % Capacity;
    return true;
  }

  // Removes the oldest element; false when there was none.
  bool pop_front() {
    if (empty()) return false;
    head_ = (head_ + 1) % Capacity;
    --count_;
    return true;
  }

  void clear() {
    head_ = 0;
    count_ = 0;
  }

  const T& front() const { return items_[head_]; }
  T& front() { return items_[head_]; }
  const T& back() const { return items_[slot(count_ == 0 ? 0 : count_ - 1)]; }
  T& back() { return items_[slot(count_ == 0 ? 0 : count_ - 1)]; }
  const T& operator[](size_t index) const { return items_[slot(index)]; }
  T& operator[](size_t index) { return items_[slot(index)]; }

 private:
  size_t slot(size_t index) const { return (head_ + index % Capacity) % Capacity; }

  T items_[Capacity]{};
  size_t head_ = 0;
  size_t count_ = 0;
};

}  // namespace alplan::firmware
