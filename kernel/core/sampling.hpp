#pragma once
// Exact conversions of random words into the variates the schemes need.
#include <cmath>
#include <cstdint>
#include <numbers>

#include "kernel/core/turn_sincos.hpp"
#include "kernel/core/vec3.hpp"

namespace granmc {

/// Relative margin of a comparison made on another form of the same quantities (squares instead of a
/// ratio, SIMD instead of libm): far above the few roundings (2^-53 each, or xsimd's ulps) between the two
/// forms, so an outcome outside it is the one the exact form gives (event thinning, the stage's screen).
inline constexpr double rounding_margin = 1e-12;

/// Uniform on (0, 1) from 32 random bits: (w + 1/2) 2^-32, never 0 or 1.
constexpr double uniform_open(std::uint32_t w) noexcept { return (static_cast<double>(w) + 0.5) * 0x1p-32; }

/// Uniform on (0, 1) with 2^-52 resolution from two words: (b + 1/2) 2^-52 with b < 2^52 is exact in
/// double, so the result is never 0 or 1.
constexpr double uniform_open52(std::uint32_t hi, std::uint32_t lo) noexcept {
  const std::uint64_t bits = ((static_cast<std::uint64_t>(hi) << 32) | lo) >> 12;
  return (static_cast<double>(bits) + 0.5) * 0x1p-52;
}

/// Index uniform on {0, ..., n-1} from 64 random bits (multiply-high; the bias is below n / 2^64).
constexpr std::uint64_t uniform_index(std::uint32_t hi, std::uint32_t lo, std::uint64_t n) noexcept {
  __extension__ using uint128 = unsigned __int128;
  const std::uint64_t bits = (static_cast<std::uint64_t>(hi) << 32) | lo;
  return static_cast<std::uint64_t>((static_cast<uint128>(bits) * n) >> 64);
}

/// Direction uniform on the unit sphere from two uniforms (Archimedes: cos(theta) is uniform).
inline Vec3 unit_vector(double u1, double u2) noexcept {
  const double cos_theta = 2.0 * u1 - 1.0;
  const double sin_theta = std::sqrt(std::fma(-cos_theta, cos_theta, 1.0));
  const CosSin phi = turn_sincos(u2);  // azimuth 2 pi u2
  return {sin_theta * phi.cos, sin_theta * phi.sin, cos_theta};
}

/// Direction (cos phi, sin phi, 0) uniform on the unit circle from one uniform: phi = 2 pi u.
inline Vec3 unit_circle_vector(double u) noexcept {
  const CosSin phi = turn_sincos(u);
  return {phi.cos, phi.sin, 0.0};
}

/// Direction (cos theta, sin theta, 0) uniform on the half circle x > 0 from one uniform: the uniform
/// direction on the circle folded onto x > 0 (the reflection x -> -x keeps the uniform law).
inline Vec3 half_circle_vector(double u) noexcept {
  const CosSin phi = turn_sincos(u);
  return {std::abs(phi.cos), phi.sin, 0.0};
}

/// Direction (cos theta, sin theta, 0) on the half circle x > 0 with density cos(theta) / 2 in theta
/// (Lambert's law in the plane) from one uniform: sin(theta) = 2 u - 1 is uniform.
inline Vec3 lambert_circle_vector(double u) noexcept {
  const double sin_theta = 2.0 * u - 1.0;
  return {std::sqrt(std::fma(-sin_theta, sin_theta, 1.0)), sin_theta, 0.0};
}

/// Two independent standard normals from two uniforms on (0, 1) (Box-Muller).
inline void standard_normal_pair(double u1, double u2, double& z1, double& z2) noexcept {
  const double r = std::sqrt(-2.0 * std::log(u1));
  const CosSin phi = turn_sincos(u2);  // angle 2 pi u2
  z1 = r * phi.cos;
  z2 = r * phi.sin;
}

}  // namespace granmc
