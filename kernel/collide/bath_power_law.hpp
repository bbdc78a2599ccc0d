#pragma once
// Power-law bath of point particles (mass m = 1) for the Gillespie intruder (002 eq. 23):
// f(v) = sqrt(2a) / pi / (1 + a^2 v^4), <v^2> = 1/a, T_B = m <v^2> = 1/a, number density rho.
//
// flux_right and try_sample_right as in bath_gaussian.hpp, for this law. In x = sqrt(a) v the density is
// (sqrt 2 / pi) / (1 + x^4) and, with A(x) = int_0^x dt / (1 + t^4),
//   phi_+(x1) = (rho / sqrt a)(sqrt 2 / pi) [x1 (pi / (2 sqrt 2) + A(x1)) - (atan(x1^2) - pi/2) / 2];
// for x1 < -2 the bracket is summed as sum_k (-1)^k y^(-4k-2) / ((4k+2)(4k+3)), y = -x1, which avoids the
// cancellation of the closed form in the far tail. Exact sampling of g_+ (w = x1 - x >= 0):
//   x1 <= 0, |x1| < 1: proposal w / (1 + w^4) (w = sqrt(tan(pi U / 2))), accept (1 + w^4) / (1 + (|x1| + w)^4);
//   x1 <= 0, |x1| >= 1: proposal w / (|x1| + w)^4, drawn as w = |x1| y / (1 - y) with y ~ Beta(2, 2) (the median
//                       of three uniforms), accept (|x1| + w)^4 / (1 + (|x1| + w)^4) >= 1/2;
//   x1 > 0: z = w - x1, h(z) = (z + x1) / (1 + z^4) [z >= -x1] <= E(z) = x1 k / (1 + z^2) + z / (1 + z^4) [z >= 0],
//           k = (1 + sqrt 2) / 2 = max (1 + z^2) / (1 + z^4); draw z from the mixture E (a Cauchy piece of
//           weight x1 k pi, or the exact z / (1 + z^4) piece of weight pi / 4), accept with h(z) / E(z);
//           acceptance >= 0.58.
// For the needle (collide/needle_flux.hpp, docs/methods/derivations/needle.md, "Power-law bath"): the flux on both
// sides phi(u) = (rho / sqrt a) phihat(sqrt(a) u) and its mean over a window, from
//   phihat(y) = (sqrt 2 / pi) [2 |y| A(|y|) + atan(1 / y^2)],
//   Ghat(z) = (sqrt 2 / pi) [z^2 A(z) + B(z) + z atan(1 / z^2)] (odd, Ghat' = phihat), B(z) = int_0^z t^2 dt / (1 +
//   t^4).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "kernel/core/philox_stream.hpp"
#include "kernel/core/sampling.hpp"

namespace granmc {

struct PowerLawBath {
  static constexpr const char* name = "power-law-bath";
  static constexpr const char* explanation = "power-law bath (002 eq. 23)";
  double a = 1.0;    // 1 / T_B, velocity^-2
  double rho = 1.0;  // number density of the bath

  [[nodiscard]] double temperature() const noexcept { return 1.0 / a; }  // T_B = m <v^2> (m = 1)

  /// A(x) = int_0^x dt / (1 + t^4), odd in x.
  static double quartic_integral(double x) noexcept {
    constexpr double r2 = std::numbers::sqrt2;
    return (std::log((x * x + r2 * x + 1.0) / (x * x - r2 * x + 1.0)) / (4.0 * r2) +
            (std::atan(r2 * x + 1.0) + std::atan(r2 * x - 1.0)) / (2.0 * r2));
  }

  /// B(x) = int_0^x t^2 dt / (1 + t^4), odd in x.
  static double quartic_square_integral(double x) noexcept {
    constexpr double r2 = std::numbers::sqrt2;
    return (-std::log((x * x + r2 * x + 1.0) / (x * x - r2 * x + 1.0)) / (4.0 * r2) +
            (std::atan(r2 * x + 1.0) + std::atan(r2 * x - 1.0)) / (2.0 * r2));
  }

  /// phihat(y): phi(u) = phi_+(u) + phi_-(u) in units of rho / sqrt(a), y = sqrt(a) u; even and convex,
  /// phihat'' = 2 (sqrt 2 / pi) / (1 + y^4).
  static double unit_flux(double y) noexcept {
    y = std::fabs(y);
    return std::numbers::sqrt2 / std::numbers::pi * (2.0 * y * quartic_integral(y) + std::atan2(1.0, y * y));
  }

  /// Phihat(y, s): the mean of phihat over [y - s, y + s] (the needle's total flux in units of rho L / sqrt a).
  /// As for the Gaussian bath (collide/bath_gaussian.hpp): a Taylor series for s < 1e-2 (within 1e-14),
  /// Ghat(s + |y|) + Ghat(s - |y|) of positive terms for |y| <= s, and for |y| > s the split
  /// Ghat(z) = (z^2 + 1) / 2 + T(z), z >= 0, whose polynomial part differences to 2 |y| s exactly, with
  /// T(z) = (sqrt 2 / pi) [z atan(1 / z^2) - z^2 R1(z) - R2(z)], R1 = int_z^inf dt / (1 + t^4),
  /// R2 = int_z^inf t^2 dt / (1 + t^4) (alternating series in z^-4 for z > 2).
  static double unit_total_flux(double y, double s) noexcept {
    constexpr double c = std::numbers::sqrt2 / std::numbers::pi;
    y = std::fabs(y);
    if (s < 1e-2) {
      const double y2 = y * y, q = 1.0 + y2 * y2;
      const double second = 2.0 * c / q;                                                // phihat''
      const double fourth = 2.0 * c * (20.0 * y2 * y2 * y2 - 12.0 * y2) / (q * q * q);  // phihat''''
      const double s2 = s * s;
      return unit_flux(y) + second * s2 / 6.0 + fourth * s2 * s2 / 120.0;
    }
    auto g = [&](double z) {  // Ghat(z), z >= 0
      return c * (z * z * quartic_integral(z) + quartic_square_integral(z) + z * std::atan2(1.0, z * z));
    };
    if (y <= s) return (g(s + y) + g(s - y)) / (2.0 * s);
    auto tail = [&](double z) {                                                         // T(z), z >= 0
      constexpr double half_integral = std::numbers::pi / (2.0 * std::numbers::sqrt2);  // A(inf) = B(inf)
      double r1, r2;
      if (z > 2.0) {
        const double q = 1.0 / (z * z * z * z);
        double term = 1.0, sum1 = 0.0, sum2 = 0.0;
        for (int k = 0; k < 30 && term > 1e-18; ++k, term *= q) {
          const double sign = k % 2 == 0 ? 1.0 : -1.0;
          sum1 += sign * term / (4.0 * k + 3.0);
          sum2 += sign * term / (4.0 * k + 1.0);
        }
        r1 = sum1 / (z * z * z);
        r2 = sum2 / z;
      } else {
        r1 = half_integral - quartic_integral(z);
        r2 = half_integral - quartic_square_integral(z);
      }
      return c * (z * std::atan2(1.0, z * z) - z * z * r1 - r2);
    };
    return y + (tail(y + s) - tail(y - s)) / (2.0 * s);
  }

  /// phi_+(v1) (002 eq. 5 with eq. 23).
  [[nodiscard]] double flux_right(double v1) const noexcept {
    constexpr double r2 = std::numbers::sqrt2;
    constexpr double pi = std::numbers::pi;
    const double x1 = std::sqrt(a) * v1;
    double bracket;
    if (x1 < -2.0) {  // far left tail: alternating series in y^-4, terms fall by 16x or more
      const double y2 = 1.0 / (x1 * x1), y4 = y2 * y2;
      double term = y2, sum = 0.0;
      for (int k = 0; k < 40 && term > 1e-18 * y2; ++k, term *= y4)
        sum += (k % 2 == 0 ? 1.0 : -1.0) * term / ((4.0 * k + 2.0) * (4.0 * k + 3.0));
      bracket = sum;
    } else {
      bracket = x1 * (pi / (2.0 * r2) + quartic_integral(x1)) - 0.5 * (std::atan(x1 * x1) - 0.5 * pi);
    }
    return rho / std::sqrt(a) * (r2 / pi) * bracket;
  }

  /// One rejection attempt with the four uniforms of `u`; on acceptance sets v and returns true.
  bool try_sample_right(double v1, const RandomBlock& u, double& v) const noexcept {
    constexpr double pi = std::numbers::pi;
    const double sa = std::sqrt(a);
    const double x1 = sa * v1;
    double x;
    if (x1 <= 0.0) {
      const double c = -x1;
      double w;
      if (c < 1.0) {
        w = std::sqrt(std::tan(0.5 * pi * uniform_open(u[0])));  // density ~ w / (1 + w^4)
        const double s = c + w;
        if (uniform_open(u[1]) * (1.0 + s * s * s * s) >= 1.0 + w * w * w * w) return false;
      } else {
        const double u0 = uniform_open(u[0]), u1 = uniform_open(u[1]), u2 = uniform_open(u[2]);
        const double y = std::max(std::min(u0, u1), std::min(std::max(u0, u1), u2));  // median: Beta(2, 2)
        w = c * y / (1.0 - y);                                                        // density ~ w / (c + w)^4
        const double s4 = std::pow(c + w, 4);
        if (uniform_open(u[3]) * (1.0 + s4) >= s4) return false;
      }
      x = x1 - w;
    } else {
      constexpr double r2 = std::numbers::sqrt2;
      constexpr double k = 0.5 * (1.0 + r2);
      const double weight_cauchy = x1 * k * pi;  // int x1 k / (1 + z^2) over all z
      const double weight_tail = 0.25 * pi;      // int z / (1 + z^4), z >= 0
      double z;
      if (uniform_open(u[0]) * (weight_cauchy + weight_tail) < weight_cauchy) {
        z = std::tan(pi * (uniform_open(u[1]) - 0.5));  // Cauchy
      } else {
        z = std::sqrt(std::tan(0.5 * pi * uniform_open(u[1])));  // density ~ z / (1 + z^4), z >= 0
      }
      if (z < -x1) return false;  // h = 0: outside the half-line v <= v1
      const double z4 = z * z * z * z;
      const double envelope = x1 * k * (1.0 + z4) / (1.0 + z * z) + std::max(z, 0.0);  // E(z) (1 + z^4)
      if (uniform_open(u[3]) * envelope >= z + x1) return false;
      x = -z;
    }
    v = x / sa;
    return true;
  }
};

}  // namespace granmc
