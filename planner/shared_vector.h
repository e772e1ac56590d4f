// A vector that copies share until one of them changes it. The tasks a
// grounding cache derives for each repair (grounding_cache.h) differ from
// their reference only in the initial state and the timed literals; with
// their ground actions shared, deriving one costs a few pointer copies, not
// a copy of every action. Readers see a const vector; writers call mutate(),
// which takes a private copy first when the data is shared.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

namespace alplan {

template <typename T>
class SharedVector {
 public:
  using value_type = T;
  using const_iterator = typename std::vector<T>::const_iterator;

  SharedVector() : data_(std::make_shared<std::vector<T>>()) {}

  std::size_t size() const { return data_->size(); }
  bool empty() const { return data_->empty(); }
  const T& operator[](std::size_t i) const { return (*data_)[i]; }
  const T& front() const { return data_->front(); }
  const T& back() const { return data_->back(); }
  const_iterator begin() const { return data_->cbegin(); }
  const_iterator end() const { return data_->cend(); }
  const std::vector<T>& vector() const { return *data_; }
  // Whether the two hold the very same data (not just equal data).
  bool shares_with(const SharedVector& other) const { return data_ == other.data_; }

  // Only the owner of a task under construction writes, so a count of one
  // cannot grow meanwhile; a stale higher count only costs a needless copy.
  std::vector<T>& mutate() {
    if (data_.use_count() > 1) data_ = std::make_shared<std::vector<T>>(*data_);
    return *data_;
  }
  void push_back(T value) { mutate().push_back(std::move(value)); }

 private:
  std::shared_ptr<std::vector<T>> data_;
};

}  // namespace alplan
