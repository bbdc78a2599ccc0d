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
#include <type_traits>

#include <Random123/philox.h>

#include "kernel/core/rng_ids.hpp"
#include "kernel/core/simd.hpp"

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

// (The intrinsics below are inlined from GCC 12's AVX-512 headers, which warn as core/simd.hpp says.)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
  /// Block k at (purpose, sub, step[k], index[k]) for k < N: the same values as block(), with the ten
  /// Philox rounds (Random123's round function, Salmon et al. SC'11) run over the N counters in SIMD
  /// registers, one 32-bit word per 64-bit lane so that each product is one unsigned 32 x 32 -> 64 multiply
  /// (tests/test_philox.cpp checks every word). Written with xsimd rather than left to the vectorizer,
  /// which vectorized the same loop or not depending on where it was inlined (3x apart for N = 16).
  template <std::size_t N>
  [[nodiscard]] RandomBlocks<N> blocks(RngPurpose purpose, std::uint16_t sub, const std::array<std::uint64_t, N>& step,
                                       const std::array<std::uint64_t, N>& index) const noexcept {
    constexpr std::size_t width = Lanes::size, group = 4;
    constexpr std::size_t grouped = N - N % (group * width), whole = N - N % width;
    RandomBlocks<N> c;
    // Four registers of counters go through the rounds together (16 of the 32 AVX-512 registers), so that
    // the multiplies of independent registers overlap; then the registers left one by one; then the last
    // counters, fewer than a register, one block at a time.
    for (std::size_t first = 0; first < grouped; first += group * width)
      simd_blocks<group>(purpose, sub, step.data() + first, index.data() + first, c, first);
    for (std::size_t first = grouped; first < whole; first += width)
      simd_blocks<1>(purpose, sub, step.data() + first, index.data() + first, c, first);
    for (std::size_t k = whole; k < N; ++k) {
      const RandomBlock r = block(purpose, sub, step[k], index[k]);
      for (std::size_t w = 0; w < 4; ++w) c.word[w][k] = r[w];
    }
    return c;
  }

 private:
  using Lanes = xsimd::batch<std::uint64_t>;

  /// Blocks out[first .. first + G width) of the counters step[0 .. G width), index[0 .. G width).
  template <std::size_t G, std::size_t N>
  void simd_blocks(RngPurpose purpose, std::uint16_t sub, const std::uint64_t* step, const std::uint64_t* index,
                   RandomBlocks<N>& out, std::size_t first) const noexcept {
    constexpr std::size_t width = Lanes::size;
    const std::uint64_t last = static_cast<std::uint32_t>(purpose) | (std::uint32_t{sub} << 16);
    const Lanes low(0xFFFFFFFFu), m0(0xD2511F53u), m1(0xCD9E8D57u);
    std::array<Lanes, G> w0, w1, w2, w3;
    for (std::size_t r = 0; r < G; ++r) {
      const Lanes i = Lanes::load_unaligned(index + r * width), s = Lanes::load_unaligned(step + r * width);
      w0[r] = i & low;
      w1[r] = s & low;
      w2[r] = ((s >> 32) & Lanes(0xFFFFu)) | ((i >> 32) << 16);
      w3[r] = Lanes(last);
    }
    std::uint32_t k0 = key_[0], k1 = key_[1];
    for (int round = 0; round < 10; ++round) {
      if (round > 0) {  // bump the key (Weyl sequence)
        k0 += 0x9E3779B9u;
        k1 += 0xBB67AE85u;
      }
      for (std::size_t r = 0; r < G; ++r) {
        const Lanes p0 = product_32(m0, w0[r]), p1 = product_32(m1, w2[r]);
        w0[r] = (p1 >> 32) ^ w1[r] ^ Lanes(k0);
        w2[r] = (p0 >> 32) ^ w3[r] ^ Lanes(k1);
        w1[r] = p1 & low;
        w3[r] = p0 & low;
      }
    }
    for (std::size_t r = 0; r < G; ++r) {
      const std::size_t g = first + r * width;
      store_words(w0[r], &out.word[0][g]);
      store_words(w1[r], &out.word[1][g]);
      store_words(w2[r], &out.word[2][g]);
      store_words(w3[r], &out.word[3][g]);
    }
  }

  /// a b for lanes holding 32-bit values: the unsigned 32 x 32 -> 64 multiply of the instruction set
  /// (pmuludq), or the 64-bit multiply where xsimd knows no cheaper one (exact, as a b < 2^64).
  template <class Arch>
  static xsimd::batch<std::uint64_t, Arch> product_32(const xsimd::batch<std::uint64_t, Arch>& a,
                                                      const xsimd::batch<std::uint64_t, Arch>& b) noexcept {
    // An if-constexpr chain across #if branches, which clang-format would misindent:
    // clang-format off
#if XSIMD_WITH_AVX512F
    if constexpr (std::is_base_of_v<xsimd::avx512f, Arch>) return _mm512_mul_epu32(a, b);
    else
#endif
#if XSIMD_WITH_AVX2
    if constexpr (std::is_base_of_v<xsimd::avx2, Arch>) return _mm256_mul_epu32(a, b);
    else
#endif
#if XSIMD_WITH_SSE2
    if constexpr (std::is_base_of_v<xsimd::sse2, Arch>) return _mm_mul_epu32(a, b);
    else
#endif
      return a * b;
    // clang-format on
  }

  /// The 32-bit values of the lanes, stored to out[0 .. size).
  template <class Arch>
  static void store_words(const xsimd::batch<std::uint64_t, Arch>& x, std::uint32_t* out) noexcept {
    // An if-constexpr chain across #if branches, which clang-format would misindent:
    // clang-format off
#if XSIMD_WITH_AVX512F
    if constexpr (std::is_base_of_v<xsimd::avx512f, Arch>) {
      _mm256_storeu_si256(reinterpret_cast<__m256i*>(out), _mm512_cvtepi64_epi32(x));
    } else
#endif
    // clang-format on
    {
      alignas(64) std::uint64_t lanes[xsimd::batch<std::uint64_t, Arch>::size];
      x.store_aligned(lanes);
      for (std::size_t k = 0; k < std::size(lanes); ++k) out[k] = static_cast<std::uint32_t>(lanes[k]);
    }
  }

#pragma GCC diagnostic pop

  static constexpr std::uint32_t lo(std::uint64_t x) noexcept { return static_cast<std::uint32_t>(x); }
  static constexpr std::uint32_t hi(std::uint64_t x) noexcept { return static_cast<std::uint32_t>(x >> 32); }
  r123::Philox4x32::key_type key_;
};

}  // namespace granmc
