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

namespace granmc {

using SimdDouble = xsimd::batch<double>;  // the widest registers the build targets

/// Bit k set where !(a[k] > b[k]) (so also where either is NaN), for the SIMD width's lanes.
template <class Arch>
inline std::uint64_t not_greater_bits(const xsimd::batch<double, Arch>& a, const xsimd::batch<double, Arch>& b) noexcept {
  if constexpr (std::is_base_of_v<xsimd::avx512f, Arch>) {
    return _mm512_cmp_pd_mask(a, b, _CMP_NGT_UQ);
  } else if constexpr (std::is_base_of_v<xsimd::avx, Arch>) {
    return static_cast<std::uint64_t>(_mm256_movemask_pd(_mm256_cmp_pd(a, b, _CMP_NGT_UQ)));
  } else {
    alignas(64) double x[xsimd::batch<double, Arch>::size], y[xsimd::batch<double, Arch>::size];
    a.store_aligned(x);
    b.store_aligned(y);
    std::uint64_t bits = 0;
    for (std::size_t k = 0; k < std::size(x); ++k) bits |= static_cast<std::uint64_t>(!(x[k] > y[k])) << k;
    return bits;
  }
}

}  // namespace granmc
