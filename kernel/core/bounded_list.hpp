#pragma once
// A list whose length has a known bound: storage for the bound allocated once (reset), then appends that
// neither check a capacity nor reallocate. A concurrent collision round keeps its collisions' terms and the
// velocities they overwrote in such lists (schemes/concurrent_rounds.hpp), at most one or two per candidate of
// its chunk.
#include <cstddef>
#include <span>
#include <vector>

namespace granmc {

template <class T>
class BoundedList {
 public:
  /// Empties the list and makes room for `bound` items.
  void reset(std::size_t bound) {
    if (items_.size() < bound) items_.resize(bound);
    size_ = 0;
  }
  void push_back(const T& item) noexcept { items_[size_++] = item; }
  [[nodiscard]] std::size_t size() const noexcept { return size_; }
  T& operator[](std::size_t i) noexcept { return items_[i]; }
  [[nodiscard]] std::span<const T> items() const noexcept { return std::span(items_).first(size_); }

 private:
  std::vector<T> items_;
  std::size_t size_ = 0;
};

}  // namespace granmc
