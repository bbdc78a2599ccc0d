#pragma once
// Fixed-size, cache-line-aligned buffer of trivially copyable values. Large buffers are aligned to
// 2 MiB and advised for transparent huge pages: random pair access over 10^7 particles is bound by
// TLB and cache misses (docs/developer-guide/performance.md).
#include <sys/mman.h>

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <new>
#include <span>
#include <type_traits>
#include <utility>

namespace granmc {

namespace detail {

/// One freed huge-page block per thread, kept for the thread's next allocation of the same size. A run
/// allocates each replica's particle store anew on the thread that runs it; a fresh block makes the kernel
/// zero every page on first touch, a third of the set-up of a 10^7-particle replica
/// (docs/developer-guide/performance.md).
class SpareHugeBlock {
 public:
  SpareHugeBlock() = default;
  SpareHugeBlock(const SpareHugeBlock&) = delete;
  SpareHugeBlock& operator=(const SpareHugeBlock&) = delete;
  ~SpareHugeBlock() { std::free(data_); }

  /// The kept block if it has `bytes` bytes (then no longer kept), else nullptr.
  void* take(std::size_t bytes) noexcept {
    if (data_ == nullptr || bytes_ != bytes) return nullptr;
    return std::exchange(data_, nullptr);
  }
  /// Keeps the block if none is kept, else frees it.
  void give(void* data, std::size_t bytes) noexcept {
    if (data_ != nullptr) {
      std::free(data);
      return;
    }
    data_ = data;
    bytes_ = bytes;
  }

 private:
  void* data_ = nullptr;
  std::size_t bytes_ = 0;
};

inline thread_local SpareHugeBlock spare_huge_block;

}  // namespace detail

template <class T>
class AlignedBuffer {
  static_assert(std::is_trivially_copyable_v<T>, "AlignedBuffer holds plain values");

 public:
  static constexpr std::size_t cache_line = 64;
  static constexpr std::size_t huge_page = std::size_t{2} << 20;

  AlignedBuffer() = default;
  /// n zeros, written by `threads` threads, each a contiguous part: the first touch of a fresh block makes the
  /// kernel clear its pages, which then happens on all of them.
  explicit AlignedBuffer(std::size_t n, int threads = 1) : size_(n) {
    if (n == 0) return;
    const std::size_t bytes = n * sizeof(T);
    const std::size_t align = bytes >= huge_page ? huge_page : cache_line;
    const std::size_t rounded = (bytes + align - 1) / align * align;
    if (align == huge_page) data_ = static_cast<T*>(detail::spare_huge_block.take(rounded));
    if (data_ == nullptr) {
      data_ = static_cast<T*>(std::aligned_alloc(align, rounded));
      if (data_ == nullptr) throw std::bad_alloc();
      if (align == huge_page) madvise(data_, rounded, MADV_HUGEPAGE);  // advice only; failure is harmless
    }
    const std::size_t parts = static_cast<std::size_t>(std::max(threads, 1));
    const std::size_t part = (rounded / align + parts - 1) / parts * align;
    char* const bytes_at = reinterpret_cast<char*>(data_);
#pragma omp parallel for num_threads(threads) schedule(static) if (threads > 1)
    for (std::size_t k = 0; k < parts; ++k)
      if (k * part < rounded) std::memset(bytes_at + k * part, 0, std::min(part, rounded - k * part));
  }
  AlignedBuffer(const AlignedBuffer& o) : AlignedBuffer(o.size_) {
    if (size_ != 0) std::memcpy(static_cast<void*>(data_), o.data_, size_ * sizeof(T));
  }
  AlignedBuffer(AlignedBuffer&& o) noexcept
      : data_(std::exchange(o.data_, nullptr)), size_(std::exchange(o.size_, 0)) {}
  AlignedBuffer& operator=(AlignedBuffer o) noexcept {
    std::swap(data_, o.data_);
    std::swap(size_, o.size_);
    return *this;
  }
  ~AlignedBuffer() {
    if (data_ == nullptr) return;
    const std::size_t bytes = size_ * sizeof(T);
    if (bytes >= huge_page)
      detail::spare_huge_block.give(data_, (bytes + huge_page - 1) / huge_page * huge_page);
    else
      std::free(data_);
  }

  [[nodiscard]] std::size_t size() const noexcept { return size_; }
  T& operator[](std::size_t i) noexcept { return data_[i]; }
  const T& operator[](std::size_t i) const noexcept { return data_[i]; }
  T* data() noexcept { return data_; }
  const T* data() const noexcept { return data_; }
  std::span<T> span() noexcept { return {data_, size_}; }
  std::span<const T> span() const noexcept { return {data_, size_}; }

 private:
  T* data_ = nullptr;
  std::size_t size_ = 0;
};

}  // namespace granmc
