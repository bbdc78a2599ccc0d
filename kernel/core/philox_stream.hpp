#pragma once
// Counter-based random numbers: Philox4x32-10 from Random123 (Salmon et al., SC'11).
//
// A RandomStream is keyed by (seed, replica). Philox4x32 has a 64-bit key, so the 128 bits of
// (seed, replica) are compressed to 64 by one Philox4x32 encryption under a fixed key: distinct pairs
// share a key with probability 2^-64. A block of four 32-bit words is addressed by the counter
// (index, step, purpose, sub): what it is for, never who draws it. Words: (index low 32 bits,
// step low 32 bits, step high 16 | index high 16 << 16, purpose | sub << 16), so step and index each
// range over 2^48 values.
#include <array>
#include <cstddef>
#include <cstdint>

#include <Random123/philox.h>

#include "kernel/core/rng_ids.hpp"

namespace granmc {

using RandomBlock = std::array<std::uint32_t, 4>;

/// N blocks as four arrays of words: word[w][k] is word w of block k.
template <std::size_t N>
struct RandomBlocks {
  std::array<std::array<std::uint32_t, N>, 4> word;
};

class RandomStream {
 public:
  RandomStream(std::uint64_t seed, std::uint64_t replica) noexcept {
    const r123::Philox4x32::ctr_type c = {{lo(seed), hi(seed), lo(replica), hi(replica)}};
    const r123::Philox4x32::key_type k = {{0x9E3779B9u, 0x7F4A7C15u}};  // fixed: golden-ratio words
    const auto h = r123::Philox4x32{}(c, k);
    key_ = {{h[0] ^ h[2], h[1] ^ h[3]}};
  }

  /// The block at (purpose, sub, step, index).
  static constexpr std::uint64_t counter_limit = std::uint64_t{1} << 48;  // for step and index

  /// The block at (purpose, sub, step, index); step and index below counter_limit.
  [[nodiscard]] RandomBlock block(RngPurpose purpose, std::uint16_t sub, std::uint64_t step,
                                  std::uint64_t index) const noexcept {
    const r123::Philox4x32::ctr_type c = {{lo(index), lo(step), (hi(step) & 0xFFFFu) | (hi(index) << 16),
                                           static_cast<std::uint32_t>(purpose) | (std::uint32_t{sub} << 16)}};
    const auto r = r123::Philox4x32{}(c, key_);
    return {r[0], r[1], r[2], r[3]};
  }

  /// Block k at (purpose, sub, step[k], index[k]) for k < N: the same values as block(), with the ten
  /// Philox rounds run over the N counters as arrays, which the compiler vectorizes (Random123's round
  /// function, Salmon et al. SC'11, written lane-wise; tests/test_philox.cpp checks every word).
  template <std::size_t N>
  [[nodiscard]] RandomBlocks<N> blocks(RngPurpose purpose, std::uint16_t sub, const std::array<std::uint64_t, N>& step,
                                       const std::array<std::uint64_t, N>& index) const noexcept {
    RandomBlocks<N> c;
    const std::uint32_t last = static_cast<std::uint32_t>(purpose) | (std::uint32_t{sub} << 16);
    for (std::size_t k = 0; k < N; ++k) {
      c.word[0][k] = lo(index[k]);
      c.word[1][k] = lo(step[k]);
      c.word[2][k] = (hi(step[k]) & 0xFFFFu) | (hi(index[k]) << 16);
      c.word[3][k] = last;
    }
    std::uint32_t k0 = key_[0], k1 = key_[1];
    for (int round = 0; round < 10; ++round) {
      if (round > 0) {  // bump the key (Weyl sequence)
        k0 += 0x9E3779B9u;
        k1 += 0xBB67AE85u;
      }
      for (std::size_t k = 0; k < N; ++k) {
        const std::uint64_t p0 = std::uint64_t{0xD2511F53u} * c.word[0][k];
        const std::uint64_t p1 = std::uint64_t{0xCD9E8D57u} * c.word[2][k];
        const std::uint32_t w0 = static_cast<std::uint32_t>(p1 >> 32) ^ c.word[1][k] ^ k0;
        const std::uint32_t w2 = static_cast<std::uint32_t>(p0 >> 32) ^ c.word[3][k] ^ k1;
        c.word[1][k] = static_cast<std::uint32_t>(p1);
        c.word[3][k] = static_cast<std::uint32_t>(p0);
        c.word[0][k] = w0;
        c.word[2][k] = w2;
      }
    }
    return c;
  }

 private:
  static constexpr std::uint32_t lo(std::uint64_t x) noexcept { return static_cast<std::uint32_t>(x); }
  static constexpr std::uint32_t hi(std::uint64_t x) noexcept { return static_cast<std::uint32_t>(x >> 32); }
  r123::Philox4x32::key_type key_;
};

}  // namespace granmc
