#pragma once
// cos and sin of the angle 2 pi t for t in [0, 1], without branches: the random directions of every scheme
// (a uniform azimuth) need it once per candidate, and libm's sincos spent 134 instructions and 2.1
// mispredicted branches per candidate on argument reduction and range tests that this domain never needs
// (callgrind, docs/developer-guide/performance.md). Accuracy: within 1.7e-16 of cos and sin of 2 pi t (below one ulp of
// 1, tests/test_numerics.cpp); libm applied to 2 pi t rounded to double is off by up to 4.4e-16.
//
// Reduction is exact: x = 4t, q = nearest integer to x (0..4), f = x - q in [-1/2, 1/2] (exact: x and q
// are within a factor 2, or q = 0), theta = f pi / 2 in [-pi/4, pi/4]. There the Taylor series converge
// fast: the first omitted terms, theta^19 / 19! and theta^18 / 18!, are below 1e-17. The quadrant q mod 4
// rotates (cos theta, sin theta) by q pi / 2 through a table of signs, not a branch.
#include <cmath>
#include <cstdint>
#include <numbers>

namespace granmc {

struct CosSin {
  double cos, sin;
};

/// The reduced angle's cos and sin and the quadrant q (as a double, 0..4) of the angle 2 pi t. Generic in
/// the number type T: double here, a SIMD batch in core/batch_variates.hpp, with the same operations in
/// the same order.
template <class T>
struct TurnReduced {
  T cos_theta, sin_theta, quadrant;
};

template <class T>
inline TurnReduced<T> turn_reduce(const T& t) noexcept {
  using std::floor;
  const T x = 4.0 * t;
  const T q = floor(x + 0.5);
  const T theta = (x - q) * (0.5 * std::numbers::pi);
  const T z = theta * theta;
  // sin theta = theta (1 - z/3! + z^2/5! - ... - z^8/17!), cos theta = 1 - z/2! + ... + z^9/18!: Horner.
  T s = T(-1.0 / 355687428096000.0);   // -1/17!
  s = s * z + 1.0 / 1307674368000.0;   // 1/15!
  s = s * z - 1.0 / 6227020800.0;      // -1/13!
  s = s * z + 1.0 / 39916800.0;        // 1/11!
  s = s * z - 1.0 / 362880.0;          // -1/9!
  s = s * z + 1.0 / 5040.0;            // 1/7!
  s = s * z - 1.0 / 120.0;             // -1/5!
  s = s * z + 1.0 / 6.0;               // 1/3!
  T c = T(1.0 / 6402373705728000.0);   // 1/18!
  c = c * z - 1.0 / 20922789888000.0;  // -1/16!
  c = c * z + 1.0 / 87178291200.0;     // 1/14!
  c = c * z - 1.0 / 479001600.0;       // -1/12!
  c = c * z + 1.0 / 3628800.0;         // 1/10!
  c = c * z - 1.0 / 40320.0;           // -1/8!
  c = c * z + 1.0 / 720.0;             // 1/6!
  c = c * z - 1.0 / 24.0;              // -1/4!
  c = c * z + 0.5;                     // 1/2!
  return {1.0 - z * c, theta - theta * z * s, q};
}

inline CosSin turn_sincos(double t) noexcept {
  const TurnReduced<double> r = turn_reduce(t);
  // Rotation by q pi / 2: (cos, sin) -> (a cos - b sin, b cos + a sin) with (a, b) = (cos, sin)(q pi / 2).
  static constexpr double a[4] = {1.0, 0.0, -1.0, 0.0};
  static constexpr double b[4] = {0.0, 1.0, 0.0, -1.0};
  const std::uint32_t k = static_cast<std::uint32_t>(r.quadrant) & 3u;
  return {a[k] * r.cos_theta - b[k] * r.sin_theta, b[k] * r.cos_theta + a[k] * r.sin_theta};
}

}  // namespace granmc
