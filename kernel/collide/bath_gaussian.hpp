#pragma once
// Gaussian bath of point particles (mass m = 1) for the Gillespie intruder (002 sec. 3.1):
// f(v) = sqrt(a / pi) exp(-a v^2) (002 eq. 18), T_B = m / (2 a), number density rho.
//
// flux_right(v1) is phi_+(v1) = rho int_{-inf}^{v1} (v1 - v) f(v) dv (002 eqs. 5, 19); the left flux is
// phi_-(v1) = phi_+(-v1) by symmetry. try_sample_right draws the velocity of the bath particle that hits
// the right side, from g_+(v; v1) proportional to (v1 - v) f(v) on v <= v1 (002 eq. 14), EXACTLY for every
// v1: one attempt of a rejection scheme whose proposal covers the whole half-line (no window), with an
// acceptance bounded below by about 0.35 for every v1. Work in x = sqrt(a) v, w = x1 - x >= 0:
//   x1 <= 0, |x1| < 1: h(w) ~ w exp(-w^2) exp(-2 |x1| w): Rayleigh proposal, accept exp(-2 |x1| w);
//   x1 <= 0, |x1| >= 1: Gamma(2, 2 |x1|) proposal, accept exp(-w^2);
//   x1 > 0: with z = w - x1, h(z) = (z + x1) exp(-z^2) [z >= -x1] <= E(z) = x1 exp(-z^2) + z exp(-z^2) [z >= 0]:
//           draw z from the mixture E (pick a piece by its weight, x1 sqrt(pi) or 1/2, then draw from it),
//           accept with h(z) / E(z) = [z >= -x1] (z + x1) / (x1 + max(z, 0)); acceptance >= 0.7.
#include <cmath>
#include <numbers>

#include "kernel/core/philox_stream.hpp"
#include "kernel/core/sampling.hpp"

namespace granmc {

struct GaussianBath {
  static constexpr const char* name = "gaussian-bath";
  static constexpr const char* explanation = "Gaussian bath (002 eq. 18)";
  double a = 1.0;    // 1 / (2 T_B), velocity^-2
  double rho = 1.0;  // number density of the bath

  [[nodiscard]] double temperature() const noexcept { return 0.5 / a; }  // T_B (m = 1)

  /// phihat(y) = exp(-y^2) / sqrt(pi) + y erf(y): phi(u) = phi_+(u) + phi_-(u) in units of rho / sqrt(a),
  /// y = sqrt(a) u (002 eq. 20). For the needle (collide/needle_flux.hpp).
  static double unit_flux(double y) noexcept {
    return std::exp(-y * y) / std::sqrt(std::numbers::pi) + y * std::erf(y);
  }

  /// Phihat(y, s): the mean of phihat over [y - s, y + s], i.e. the needle's total flux Phi in units of
  /// rho L / sqrt(a) (002 eq. 26 for general a and L, docs/methods/derivations/needle.md). Evaluated without
  /// cancellation: a Taylor series for s < 1e-2 (next term below 3e-15), the sum Ghat(s + |y|) + Ghat(s - |y|) of
  /// positive terms for |y| <= s, and for |y| > s the split Ghat(z) = z^2 / 2 + 1/4 + T(z) (z >= 0), whose polynomial
  /// part differences to 2 |y| s exactly.
  static double unit_total_flux(double y, double s) noexcept {
    const double inv_sqrt_pi = 1.0 / std::sqrt(std::numbers::pi);
    y = std::fabs(y);
    if (s < 1e-2) {
      const double e = 2.0 * inv_sqrt_pi * std::exp(-y * y);  // phihat''(y)
      const double s2 = s * s;
      return unit_flux(y) + e * s2 / 6.0 + e * (4.0 * y * y - 2.0) * s2 * s2 / 120.0;
    }
    if (y <= s) {
      auto g = [&](double z) { return (0.5 * z * z + 0.25) * std::erf(z) + 0.5 * inv_sqrt_pi * z * std::exp(-z * z); };
      return (g(s + y) + g(s - y)) / (2.0 * s);
    }
    auto tail = [&](double z) {
      return -(0.5 * z * z + 0.25) * std::erfc(z) + 0.5 * inv_sqrt_pi * z * std::exp(-z * z);
    };
    return y + (tail(y + s) - tail(y - s)) / (2.0 * s);
  }

  /// phi_+(v1), 002 eq. (19): (rho / (2 sqrt a)) (x1 erfc(-x1) + exp(-x1^2) / sqrt(pi)), x1 = sqrt(a) v1.
  [[nodiscard]] double flux_right(double v1) const noexcept {
    const double x1 = std::sqrt(a) * v1;
    return rho / (2.0 * std::sqrt(a)) * (x1 * std::erfc(-x1) + std::exp(-x1 * x1) / std::sqrt(std::numbers::pi));
  }

  /// One rejection attempt with the four uniforms of `u`; on acceptance sets v and returns true.
  bool try_sample_right(double v1, const RandomBlock& u, double& v) const noexcept {
    const double sa = std::sqrt(a);
    const double x1 = sa * v1;
    double x;  // the bath particle's velocity in units of 1 / sqrt(a)
    if (x1 <= 0.0) {
      const double c = -x1;
      double w;
      if (c < 1.0) {
        w = std::sqrt(-std::log(uniform_open(u[0])));  // density ~ w exp(-w^2)
        if (uniform_open(u[1]) >= std::exp(-2.0 * c * w)) return false;
      } else {
        w = -(std::log(uniform_open(u[0])) + std::log(uniform_open(u[1]))) / (2.0 * c);  // Gamma(2, 2c)
        if (uniform_open(u[2]) >= std::exp(-w * w)) return false;
      }
      x = x1 - w;
    } else {
      const double weight_gauss = x1 * std::sqrt(std::numbers::pi);  // int x1 e^{-z^2} over all z
      const double weight_rayleigh = 0.5;                            // int z e^{-z^2}, z >= 0
      double z;
      if (uniform_open(u[0]) * (weight_gauss + weight_rayleigh) < weight_gauss) {
        z = std::sqrt(-std::log(uniform_open(u[1]))) * std::cos(2.0 * std::numbers::pi * uniform_open(u[2]));
      } else {
        z = std::sqrt(-std::log(uniform_open(u[1])));
      }
      if (z < -x1) return false;  // h = 0: outside the half-line v <= v1
      if (uniform_open(u[3]) * (x1 + std::max(z, 0.0)) >= z + x1) return false;
      x = -z;
    }
    v = x / sa;
    return true;
  }
};

}  // namespace granmc
