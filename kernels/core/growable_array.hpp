// A growable array of trivially copyable values whose new elements are left uninitialized: for
// outputs that a kernel writes in whole batches, where std::vector would first zero every element
// (resize) or check its capacity for each one (push_back).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <memory>
#include <type_traits>

namespace edgewise::detail {

template <class T>
class GrowableArray {
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);

 public:
  GrowableArray() = default;
  explicit GrowableArray(std::size_t size) : GrowableArray() { extend(size); }

  T* data() { return values_.get(); }
  const T* data() const { return values_.get(); }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  T& operator[](std::size_t i) { return values_[i]; }
  const T& operator[](std::size_t i) const { return values_[i]; }

  // Room for `count` more elements, uninitialized; returns the first of them.
  T* extend(std::size_t count) {
    if (count > capacity_ - size_) grow(size_ + count);
    T* first = values_.get() + size_;
    size_ += count;
    return first;
  }
  void push_back(T value) { *extend(1) = value; }  // by value: extend() may move the array
  // Keeps the first `size` elements (at most size()).
  void truncate(std::size_t size) { size_ = std::min(size, size_); }
  void reserve(std::size_t capacity) {
    if (capacity > capacity_) grow(capacity);
  }

 private:
  void grow(std::size_t at_least) {
    capacity_ = std::max(at_least, 2 * capacity_);
    auto values = std::make_unique_for_overwrite<T[]>(capacity_);
    if (size_ != 0) std::memcpy(values.get(), values_.get(), size_ * sizeof(T));
    values_ = std::move(values);
  }

  std::unique_ptr<T[]> values_;
  std::size_t size_ = 0;
  std::size_t capacity_ = 0;
};

}  // namespace edgewise::detail
