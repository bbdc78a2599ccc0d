#pragma once
// A filter of record addresses (particles, by SpeciesStore::Particle::address) that may answer "maybe" for an
// address it was not given, never "no" for one it was: the particles of a thread's chunk in a concurrent
// collision round (schemes/concurrent_rounds.hpp), where a "maybe" only defers a candidate that could have
// run at once. A blocked Bloom filter: two bits per address in one 64-bit word of 16384 (128 KB, in the core's
// second-level cache), so an insert and a query read one word. With the 16384 particles of a leader's chunk of
// 4 x 2048 candidates about 1 query in 550 for an address not inserted answers "maybe", as for random bits
// (each word holds the bits of one address on average). The word and the two bits come from the top 26 bits
// of a multiplicative hash, its best mixed; bits 32-45 made "maybe" 1.5 times as frequent. Half the words, with
// those bits, deferred 2.4 times as many candidates in one replica of 10^7 particles on two threads, and the
// run took about 3 % longer (docs/developer-guide/scaling.md).
#include <cstdint>
#include <vector>

namespace granmc {

class AddressFilter {
 public:
  /// An address's key: its 16-byte slot modulo 2^32 (records are 16 or 32 bytes and aligned to their size; two
  /// records with the same key are a multiple of 64 GB apart, and only make a query answer "maybe").
  static std::uint32_t key(const void* a) noexcept {
    return static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(a) >> 4);
  }
  void insert(std::uint32_t k) noexcept {
    const std::uint64_t h = hash(k);
    words_[word(h)] |= bits(h);
  }
  [[nodiscard]] bool may_contain(const void* a) const noexcept {
    const std::uint64_t h = hash(key(a));
    return (words_[word(h)] & bits(h)) == bits(h);
  }
  void clear() noexcept { std::fill(words_.begin(), words_.end(), 0); }

 private:
  static constexpr int words_log2 = 14;
  static std::uint64_t hash(std::uint32_t k) noexcept { return k * 0x9E3779B97F4A7C15ull; }  // Fibonacci hashing
  static std::size_t word(std::uint64_t h) noexcept { return static_cast<std::size_t>(h >> (64 - words_log2)); }
  static std::uint64_t bits(std::uint64_t h) noexcept {  // bits 38-43 and 44-49, below the word's
    return (std::uint64_t{1} << ((h >> 38) & 63)) | (std::uint64_t{1} << ((h >> 44) & 63));
  }

  std::vector<std::uint64_t> words_ = std::vector<std::uint64_t>(std::size_t{1} << words_log2, 0);
};

}  // namespace granmc
