#pragma once
// The conversions of core/sampling.hpp over arrays of N uniforms at once, in SIMD registers (xsimd). A
// scheme that knows its next N draws ahead (their random words depend on the draw's counter only)
// prepares their exponentials, normals and directions here, so the logs, square roots and polynomials run
// several lanes wide instead of one candidate at a time (docs/developer-guide/performance.md, "Event scheme").
//
// Same formulas as the scalar versions: the directions and the angles of Box-Muller are turn_reduce of
// core/turn_sincos.hpp with identical operations, so directions agree bit for bit. The logarithm is
// xsimd's, within 1 ulp of libm's; xsimd's pow is within about 20 ulp (tests/test_numerics.cpp measures
// all three), a relative error of 5e-15 in an acceptance probability.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>

#include "kernel/core/philox_stream.hpp"
#include "kernel/core/sampling.hpp"
#include "kernel/core/simd.hpp"
#include "kernel/core/turn_sincos.hpp"
#include "kernel/core/vec3.hpp"

namespace granmc {

namespace detail {

/// x y + z rounded once, as std::fma (so that directions agree bit for bit with unit_vector). xsimd 8.1's
/// fma is fused for the FMA3 instruction sets but not for AVX-512, whose kernels inherit AVX2's; there the
/// instruction is called directly. Without FMA3, lane by lane through std::fma.
/// (A template, so that the branches for other instruction sets are not compiled.)
template <class Arch>
inline xsimd::batch<double, Arch> fused_multiply_add(const xsimd::batch<double, Arch>& x,
                                                     const xsimd::batch<double, Arch>& y,
                                                     const xsimd::batch<double, Arch>& z) noexcept {
  using Batch = xsimd::batch<double, Arch>;
  // An if-constexpr chain across #if branches, which clang-format would misindent:
  // clang-format off
#if XSIMD_WITH_AVX512F
  if constexpr (std::is_base_of_v<xsimd::avx512f, Arch>) {
    return _mm512_fmadd_pd(x, y, z);
  } else
#endif
  if constexpr (std::is_base_of_v<xsimd::fma3<xsimd::sse4_2>, Arch> ||
                       std::is_base_of_v<xsimd::fma3<xsimd::avx>, Arch> ||
                       std::is_base_of_v<xsimd::fma3<xsimd::avx2>, Arch>) {
    return xsimd::fma(x, y, z);
  } else {
    // clang-format on
    alignas(64) double a[Batch::size], b[Batch::size], c[Batch::size];
    x.store_aligned(a);
    y.store_aligned(b);
    z.store_aligned(c);
    for (std::size_t k = 0; k < Batch::size; ++k) a[k] = std::fma(a[k], b[k], c[k]);
    return Batch::load_aligned(a);
  }
}

/// (cos, sin)(2 pi t) lane by lane: turn_reduce, then the rotation by the quadrant q pi / 2 through
/// selects (the scalar version's table of signs, without a gather).
inline void turn_sincos_lanes(const SimdDouble& t, SimdDouble& cos, SimdDouble& sin) noexcept {
  const TurnReduced<SimdDouble> r = turn_reduce(t);
  const SimdDouble m = r.quadrant - 4.0 * xsimd::floor(0.25 * r.quadrant);  // q mod 4, exact
  const SimdDouble one(1.0), zero(0.0);
  const SimdDouble a = xsimd::select(m == 0.0, one, zero) - xsimd::select(m == 2.0, one, zero);
  const SimdDouble b = xsimd::select(m == 1.0, one, zero) - xsimd::select(m == 3.0, one, zero);
  cos = a * r.cos_theta - b * r.sin_theta;
  sin = b * r.cos_theta + a * r.sin_theta;
}

template <std::size_t N>
constexpr void require_whole_registers() noexcept {
  static_assert(N % SimdDouble::size == 0, "array lengths must be a multiple of the SIMD width");
}

}  // namespace detail

/// out[k] = uniform_index(hi[k], lo[k], n[k]) for ranges n[k] < 2^32: the same values, from two 32 x 32 ->
/// 64-bit products, which vectorize (the 64 x 64 -> 128-bit product of uniform_index does not):
///   floor((hi 2^32 + lo) n / 2^64) = floor((hi n + floor(lo n / 2^32)) / 2^32),
/// where hi n + floor(lo n / 2^32) < 2^32 n < 2^64, so nothing overflows.
template <std::size_t N>
inline void uniform_indices(std::span<const std::uint32_t, N> hi, std::span<const std::uint32_t, N> lo,
                            const std::array<std::uint32_t, N>& n, std::array<std::uint64_t, N>& out) noexcept {
  for (std::size_t k = 0; k < N; ++k) {
    const std::uint64_t range = n[k];
    out[k] = (hi[k] * range + ((lo[k] * range) >> 32)) >> 32;
  }
}

/// u := -log(u) for u in (0, 1): exponential variates with mean 1.
template <std::size_t N>
inline void negative_log_in_place(std::span<double, N> u) noexcept {
  detail::require_whole_registers<N>();
  for (std::size_t k = 0; k < N; k += SimdDouble::size)
    (-xsimd::log(SimdDouble::load_unaligned(&u[k]))).store_unaligned(&u[k]);
}

/// u := u^p for u in (0, 1).
template <std::size_t N>
inline void power_in_place(std::span<double, N> u, double p) noexcept {
  detail::require_whole_registers<N>();
  for (std::size_t k = 0; k < N; k += SimdDouble::size)
    xsimd::pow(SimdDouble::load_unaligned(&u[k]), SimdDouble(p)).store_unaligned(&u[k]);
}

/// Box-Muller (as standard_normal_pair) lane by lane: two independent standard normals z1[k], z2[k]
/// from the uniforms u1[k], u2[k] on (0, 1).
template <std::size_t N>
inline void standard_normal_pairs(std::span<const double, N> u1, std::span<const double, N> u2, std::span<double, N> z1,
                                  std::span<double, N> z2) noexcept {
  detail::require_whole_registers<N>();
  for (std::size_t k = 0; k < N; k += SimdDouble::size) {
    const SimdDouble r = xsimd::sqrt(-2.0 * xsimd::log(SimdDouble::load_unaligned(&u1[k])));
    SimdDouble c, s;
    detail::turn_sincos_lanes(SimdDouble::load_unaligned(&u2[k]), c, s);
    (r * c).store_unaligned(&z1[k]);
    (r * s).store_unaligned(&z2[k]);
  }
}

/// Directions uniform on the sphere lane by lane, from the uniforms u1[k], u2[k]: cos(theta) = 2 u1 - 1,
/// azimuth 2 pi u2. The same bits as unit_vector, so any N: a remainder past the last whole register is
/// done by unit_vector itself.
template <std::size_t N>
inline void unit_vectors(std::span<const double, N> u1, std::span<const double, N> u2, std::span<double, N> x,
                         std::span<double, N> y, std::span<double, N> z) noexcept {
  constexpr std::size_t whole = N - N % SimdDouble::size;
  for (std::size_t k = 0; k < whole; k += SimdDouble::size) {
    const SimdDouble cos_theta = 2.0 * SimdDouble::load_unaligned(&u1[k]) - 1.0;
    const SimdDouble sin_theta = xsimd::sqrt(detail::fused_multiply_add(-cos_theta, cos_theta, SimdDouble(1.0)));
    SimdDouble c, s;
    detail::turn_sincos_lanes(SimdDouble::load_unaligned(&u2[k]), c, s);
    (sin_theta * c).store_unaligned(&x[k]);
    (sin_theta * s).store_unaligned(&y[k]);
    cos_theta.store_unaligned(&z[k]);
  }
  for (std::size_t k = whole; k < N; ++k) {
    const Vec3 e = unit_vector(u1[k], u2[k]);
    x[k] = e.x;
    y[k] = e.y;
    z[k] = e.z;
  }
}

/// unit_circle_vector lane by lane (the same bits, any N).
template <std::size_t N>
inline void unit_circle_vectors(std::span<const double, N> u, std::span<double, N> x, std::span<double, N> y,
                                std::span<double, N> z) noexcept {
  constexpr std::size_t whole = N - N % SimdDouble::size;
  for (std::size_t k = 0; k < whole; k += SimdDouble::size) {
    SimdDouble c, s;
    detail::turn_sincos_lanes(SimdDouble::load_unaligned(&u[k]), c, s);
    c.store_unaligned(&x[k]);
    s.store_unaligned(&y[k]);
    SimdDouble(0.0).store_unaligned(&z[k]);
  }
  for (std::size_t k = whole; k < N; ++k) {
    const Vec3 e = unit_circle_vector(u[k]);
    x[k] = e.x, y[k] = e.y, z[k] = e.z;
  }
}

/// half_circle_vector lane by lane (the same bits, any N): the circle's directions, x folded.
template <std::size_t N>
inline void half_circle_vectors(std::span<const double, N> u, std::span<double, N> x, std::span<double, N> y,
                                std::span<double, N> z) noexcept {
  unit_circle_vectors(u, x, y, z);
  for (double& c : x) c = std::abs(c);
}

/// lambert_circle_vector lane by lane (the same bits, any N).
template <std::size_t N>
inline void lambert_circle_vectors(std::span<const double, N> u, std::span<double, N> x, std::span<double, N> y,
                                   std::span<double, N> z) noexcept {
  constexpr std::size_t whole = N - N % SimdDouble::size;
  for (std::size_t k = 0; k < whole; k += SimdDouble::size) {
    const SimdDouble sin_theta = 2.0 * SimdDouble::load_unaligned(&u[k]) - 1.0;
    xsimd::sqrt(detail::fused_multiply_add(-sin_theta, sin_theta, SimdDouble(1.0))).store_unaligned(&x[k]);
    sin_theta.store_unaligned(&y[k]);
    SimdDouble(0.0).store_unaligned(&z[k]);
  }
  for (std::size_t k = whole; k < N; ++k) {
    const Vec3 e = lambert_circle_vector(u[k]);
    x[k] = e.x, y[k] = e.y, z[k] = e.z;
  }
}

/// The directions of the lanes selected by the set bits of `selected` (N <= 64), in increasing order:
/// lane which[e] gets (x, y, z)[e], the direction `directions` (unit_vectors or another conversion of the
/// same signature, over whole registers) gives its uniforms u1, u2. Returns how many lanes were selected;
/// the SIMD work is for those only, in whole registers (a collision stage whose screen passes a fifth of
/// its candidates converts a fifth of their directions).
template <std::size_t N, class Directions>
std::size_t selected_directions(std::uint64_t selected, const std::array<double, N>& u1,
                                const std::array<double, N>& u2, std::array<std::uint8_t, N>& which,
                                std::array<double, N>& x, std::array<double, N>& y, std::array<double, N>& z,
                                Directions&& directions) noexcept {
  static_assert(N <= 64 && N % SimdDouble::size == 0, "one 64-bit mask, whole registers");
  constexpr std::size_t w = SimdDouble::size;
  std::array<double, N> c1, c2;  // the selected uniforms, packed
  std::size_t count = 0;
  for (; selected != 0; selected &= selected - 1, ++count) {
    const auto k = static_cast<std::uint8_t>(std::countr_zero(selected));
    which[count] = k;
    c1[count] = u1[k];
    c2[count] = u2[k];
  }
  for (std::size_t k = count; k % w != 0; ++k) c1[k] = c2[k] = 0.5;  // the last register's unused lanes
  for (std::size_t e = 0; e < count; e += w)
    directions(std::span<const double, w>(&c1[e], w), std::span<const double, w>(&c2[e], w),
               std::span<double, w>(&x[e], w), std::span<double, w>(&y[e], w), std::span<double, w>(&z[e], w));
  return count;
}

/// Standard normal vectors for N consecutive particles: particle first + k gets the block (purpose, sub,
/// step, first + k), as two Box-Muller pairs (words 0-1 and 2-3) of which the last value is unused.
template <std::size_t N>
class ParticleNormals {
 public:
  ParticleNormals(const RandomStream& rng, RngPurpose purpose, std::uint16_t sub, std::uint64_t step,
                  std::uint64_t first) noexcept {
    std::array<std::uint64_t, N> steps, index;
    for (std::size_t k = 0; k < N; ++k) {
      steps[k] = step;
      index[k] = first + k;
    }
    const RandomBlocks<N> blocks = rng.blocks(purpose, sub, steps, index);
    const auto& w = blocks.word;
    std::array<double, 2 * N> u1, u2;
    for (std::size_t k = 0; k < N; ++k) {
      u1[2 * k] = uniform_open(w[0][k]);
      u2[2 * k] = uniform_open(w[1][k]);
      u1[2 * k + 1] = uniform_open(w[2][k]);
      u2[2 * k + 1] = uniform_open(w[3][k]);
    }
    standard_normal_pairs(std::span<const double, 2 * N>(u1), std::span<const double, 2 * N>(u2), std::span(z1_),
                          std::span(z2_));
  }
  /// The normal vector of particle first + k.
  [[nodiscard]] Vec3 operator[](std::size_t k) const noexcept { return {z1_[2 * k], z2_[2 * k], z1_[2 * k + 1]}; }

 private:
  std::array<double, 2 * N> z1_, z2_;
};

/// f(k, xi) for k = 0 .. count - 1 in order, xi the normal vector of particle first + k (its own block, as
/// ParticleNormals), computed N particles at a time: the values do not depend on N.
template <std::size_t N, class F>
inline void for_each_particle_normal(const RandomStream& rng, RngPurpose purpose, std::uint16_t sub, std::uint64_t step,
                                     std::uint64_t first, std::size_t count, F&& f) {
  for (std::size_t b = 0; b < count; b += N) {
    const ParticleNormals<N> xi(rng, purpose, sub, step, first + b);
    const std::size_t in_batch = std::min(N, count - b);
    for (std::size_t k = 0; k < in_batch; ++k) f(b + k, xi[k]);
  }
}

}  // namespace granmc
