#pragma once
// xsimd, and the register of doubles the build targets (AVX-512: 8 lanes, AVX2: 4).

// GCC 12 warns inside its own AVX-512 headers (the _mm512_undefined_* idiom) wherever xsimd inlines them.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <xsimd/xsimd.hpp>
#pragma GCC diagnostic pop

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <type_traits>
#include <utility>

#include "kernel/core/rounded_float.hpp"

namespace granmc {

using SimdDouble = xsimd::batch<double>;  // the widest registers the build targets

/// Bit k set where lane k of the mask is true, for the SIMD width's lanes.
/// (Here and below, a branch for an instruction set is compiled only where the build enables it: the
/// intrinsics' names exist only there. `make portable-test` builds the tests without them.)
template <class Arch>
inline std::uint64_t lane_bits(const xsimd::batch_bool<double, Arch>& mask) noexcept {
  // An if-constexpr chain across #if branches, which clang-format would misindent:
  // clang-format off
#if XSIMD_WITH_AVX512F
  if constexpr (std::is_base_of_v<xsimd::avx512f, Arch>) {
    return static_cast<__mmask8>(mask);
  } else
#endif
#if XSIMD_WITH_AVX
  if constexpr (std::is_base_of_v<xsimd::avx, Arch>) {
    return static_cast<std::uint64_t>(_mm256_movemask_pd(mask));
  } else
#endif
  // clang-format on
  {
    alignas(64) bool x[xsimd::batch_bool<double, Arch>::size];
    mask.store_aligned(x);
    std::uint64_t bits = 0;
    for (std::size_t k = 0; k < std::size(x); ++k) bits |= static_cast<std::uint64_t>(x[k]) << k;
    return bits;
  }
}

/// Bit k set where !(a[k] > b[k]) (so also where either is NaN), for the SIMD width's lanes.
template <class Arch>
inline std::uint64_t not_greater_bits(const xsimd::batch<double, Arch>& a,
                                      const xsimd::batch<double, Arch>& b) noexcept {
  return lane_bits(!(a > b));
}

/// x rounded to Real (float: to nearest) and widened to double again, lane by lane: the value a store of
/// precision Real gives back (core/species_store.hpp). The identity for double.
template <class Real, class Arch>
inline xsimd::batch<double, Arch> rounded_to(const xsimd::batch<double, Arch>& x) noexcept {
  static_assert(std::is_same_v<Real, double> || std::is_same_v<Real, float>);
  if constexpr (std::is_same_v<Real, double>) {
    return x;
  } else
  // An if-constexpr chain across #if branches, which clang-format would misindent:
  // clang-format off
#if XSIMD_WITH_AVX512F
  if constexpr (std::is_base_of_v<xsimd::avx512f, Arch>) {
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"  // as for xsimd's include, above
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
    return _mm512_cvtps_pd(_mm512_cvtpd_ps(x));
#pragma GCC diagnostic pop
  } else
#endif
#if XSIMD_WITH_AVX
  if constexpr (std::is_base_of_v<xsimd::avx, Arch>) {
    return _mm256_cvtps_pd(_mm256_cvtpd_ps(x));
  } else
#endif
  // clang-format on
  {
    alignas(64) double v[xsimd::batch<double, Arch>::size];
    x.store_aligned(v);
    for (double& d : v) d = rounded_float(d);
    return xsimd::batch<double, Arch>::load_aligned(v);
  }
}

namespace detail {
template <unsigned R>
struct Rotation {
  static constexpr unsigned get(unsigned k, unsigned size) { return (k + R) % size; }
};
/// Whether a[k] == b[(k + R) % size] for some k, for every R in Rs.
template <class Arch, unsigned... Rs>
inline bool any_equal_rotated(const xsimd::batch<std::uint64_t, Arch>& a, const xsimd::batch<std::uint64_t, Arch>& b,
                              std::integer_sequence<unsigned, Rs...>) noexcept {
  using Batch = xsimd::batch<std::uint64_t, Arch>;
  return (xsimd::any(a == xsimd::swizzle(b, xsimd::make_batch_constant<Batch, Rotation<Rs>>())) || ...);
}
}  // namespace detail

/// Whether the 2 size values a[0..size) and b[0..size) are all different: each register against every
/// rotation of the other and against half the rotations of itself.
template <class Arch>
inline bool all_different(const xsimd::batch<std::uint64_t, Arch>& a,
                          const xsimd::batch<std::uint64_t, Arch>& b) noexcept {
  constexpr unsigned size = xsimd::batch<std::uint64_t, Arch>::size;
  using Others = std::make_integer_sequence<unsigned, size>;
  if (detail::any_equal_rotated(a, b, Others{})) return false;
  if constexpr (size > 1) {
    // Rotations 1 .. size / 2 of a register against itself compare every two of its lanes
    using Self = decltype([]<unsigned... Rs>(std::integer_sequence<unsigned, Rs...>) {
      return std::integer_sequence<unsigned, (Rs + 1)...>{};
    }(std::make_integer_sequence<unsigned, size / 2>{}));
    if (detail::any_equal_rotated(a, a, Self{}) || detail::any_equal_rotated(b, b, Self{})) return false;
  }
  return true;
}

}  // namespace granmc
