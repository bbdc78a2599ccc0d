#pragma once
// Exact sampler of the first-Sonine Maxwellian of the homogeneous cooling state: 003 (f^(0) of the
// BGK-like relaxation term), a2 = c0/2 first Sonine; spheres, and disks (below). In the reduced velocity c = V / v0, v0
// = sqrt(2T/m),
//   phi(c) = pi^(-3/2) e^(-c^2) [1 + a2 S2(c^2)],   S2(x) = x^2/2 - 5x/2 + 15/8   (d = 3),
// normalised, with <c^2> = 3/2 and <c^4> = (15/4)(1 + a2). For a2 < 0 the bracket is negative beyond
// x* = c*^2 = (5 + sqrt(10 - 8/a2))/2 (the only positive root for |a2| < 8/15), so phi is no density: we
// sample its positive part max(phi, 0) / (1 + m), where m = truncated_mass() is the negative mass removed.
// The mass sits at large c, so the moments move more than m suggests: the sampled a2_eff = (8/15) <S2> is
// -0.01457 at a2 = -0.0146 (alpha = 0.9, m = 5.2e-7) but -0.0465 at a2 = -0.05 (m = 1.7e-4).
//
// Method. In x = c^2 the density of phi is a signed mixture of Gamma(s, 1) densities g_s:
//   f(x) = x^(1/2) e^(-x) [1 + a2 S2(x)] / Gamma(3/2) = w1 g_{3/2} + w2 g_{5/2} + w3 g_{7/2},
//   w1 = 1 + 15 a2/8,  w2 = -15 a2/4,  w3 = 15 a2/8   (w1 + w2 + w3 = 1; w1 > 0 for |a2| <= 1/2).
// The proposal is the positive-weight part f+ = sum_{w_i > 0} w_i g_i, of mass W+ = 1 + 15 a2/4 for
// a2 >= 0 (Gamma(3/2) and Gamma(7/2)) and W+ = 1 - 15 a2/8 for a2 < 0 (Gamma(3/2) and Gamma(5/2)). A
// proposed x is accepted with probability max(f, 0) / f+ <= 1, which is the bracket max(B(x), 0) over its
// positive-coefficient part P(x) (g_{5/2} / g_{3/2} = 2x/3, g_{7/2} / g_{3/2} = 4x^2/15). Plain rejection
// from f+ / W+ under the envelope f+ >= max(f, 0): accepted x have density exactly max(f, 0) / (1 + m),
// and an attempt is accepted with probability (1 + m) / W+ = acceptance(). phi is isotropic, so the
// direction is uniform on the sphere, independent of x.
// Gamma(n + 1/2) = z^2/2 + E_1 + ... + E_n (z standard normal, E_i standard exponential), and z^2/2 is
// -ln(u1) cos^2(2 pi u2) (Box-Muller): exact (to the resolution of the uniforms), with n + 2 uniforms.
//
// Truncated mass, a2 < 0: with Q(s + 1, x) = Q(s, x) + x^s e^(-x) / Gamma(s + 1), Q(1/2, x) = erfc(sqrt(x)),
// and B(x*) = 0, m = -int_{x*}^inf f dx = (5|a2|/2)(x* - 3/2) sqrt(x*/pi) e^(-x*) - erfc(sqrt(x*)).
//
// Disks (d = 2): phi(c) = pi^-1 e^(-c^2) [1 + a2 S2(c^2)], S2(x) = x^2/2 - 2x + 1 (<c^2> = 1, <c^4> = 2 (1 + a2)),
// and in x = c^2 the Gamma densities of integer order: f(x) = e^(-x) [1 + a2 S2(x)] = (1 + a2) g_1 - 2 a2 g_2 +
// a2 g_3 (x g_1 = g_2, x^2 g_1 = 2 g_3), proposed from Gamma(1) or Gamma(n), n = 2 (a2 < 0) or 3, each the sum of
// n standard exponentials; x* = 2 + sqrt(2 - 2/a2) and m = -int_{x*}^inf f dx = |a2| (x* - 1) e^(-x*). The
// direction is uniform on the circle (z = 0).
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "kernel/core/sampling.hpp"
#include "kernel/core/vec3.hpp"

namespace granmc {

/// What the sampler precomputes from a2: the bracket B(x) = 1 + a2 S2(x) = b0 + b1 x + b2 x^2, its
/// positive-coefficient part P(x) = b0 + p1 x + p2 x^2 (the envelope f+ over g_{3/2}), and the proposal.
struct SoninePositivePart {
  double b0, b1, b2;            // 1 + 15 a2/8, -5 a2/2, a2/2
  double p1, p2;                // max(b1, 0), max(b2, 0)
  int high_exponentials;        // second proposal component Gamma(n + 1/2): n = 2 (a2 < 0), 3 (a2 >= 0)
  double low_weight = 1.0;      // probability w1 / W+ of proposing from Gamma(3/2) instead
  double truncated_mass = 0.0;  // m
  double acceptance = 1.0;      // (1 + m) / W+

  SoninePositivePart(double a2, int dimension)
      : b0(dimension == 2 ? 1.0 + a2 : 1.0 + 15.0 * a2 / 8.0),
        b1(dimension == 2 ? -2.0 * a2 : -2.5 * a2),
        b2(0.5 * a2),
        p1(std::fmax(b1, 0.0)),
        p2(std::fmax(b2, 0.0)),
        high_exponentials(a2 < 0.0 ? 2 : 3) {
    if (dimension == 2) {
      const double w_plus = b0 + p1 + 2.0 * p2;  // int P g_1 dx, as <x> = 1, <x^2> = 2
      low_weight = b0 / w_plus;
      if (a2 < 0.0) {
        const double xs = 2.0 + std::sqrt(2.0 - 2.0 / a2);
        truncated_mass = -a2 * (xs - 1.0) * std::exp(-xs);
      }
      acceptance = (1.0 + truncated_mass) / w_plus;
      return;
    }
    const double w_plus = b0 + 1.5 * p1 + 3.75 * p2;  // int P g_{3/2} dx, as <x> = 3/2, <x^2> = 15/4
    low_weight = b0 / w_plus;
    if (a2 < 0.0) {
      const double xs = 0.5 * (5.0 + std::sqrt(10.0 - 8.0 / a2));
      truncated_mass =
          -2.5 * a2 * (xs - 1.5) * std::sqrt(xs / std::numbers::pi) * std::exp(-xs) - std::erfc(std::sqrt(xs));
    }
    acceptance = (1.0 + truncated_mass) / w_plus;
  }
};

class SonineMaxwellian {
 public:
  /// Throws std::invalid_argument unless |a2| <= 1/2 (the first-Sonine HCS a2 lies in [-0.0155, 0.1976] for
  /// spheres, [-0.0280, 0.2807] for disks).
  explicit SonineMaxwellian(double a2, int dimension = 3)
      : a2_(checked(a2)), dimension_(dimension), part_(a2, dimension) {}

  /// One reduced velocity c (V = v0 c) from max(phi, 0) / (1 + m); next_uniform() returns doubles on (0, 1).
  /// Consumes a random number of uniforms: per attempt 1 (component) + n + 2 (gamma) + 1 (accept), then 2;
  /// disks 1 + n + 1 per attempt, then 1.
  template <class Uniforms>
  Vec3 sample(Uniforms& next_uniform) const {
    double x;
    if (dimension_ == 2) {
      for (;;) {
        const int n = next_uniform() < part_.low_weight ? 1 : part_.high_exponentials;
        double product = 1.0;
        for (int i = 0; i < n; ++i) product *= next_uniform();
        x = -std::log(product);
        const double bracket = part_.b0 + x * (part_.b1 + x * part_.b2);
        const double envelope = part_.b0 + x * (part_.p1 + x * part_.p2);
        if (next_uniform() * envelope < bracket) break;
      }
      return std::sqrt(x) * unit_circle_vector(next_uniform());
    }
    for (;;) {
      const int n = next_uniform() < part_.low_weight ? 1 : part_.high_exponentials;
      const double u1 = next_uniform();
      const double cos_phi = std::cos(2.0 * std::numbers::pi * next_uniform());
      double product = 1.0;
      for (int i = 0; i < n; ++i) product *= next_uniform();
      x = -std::log(u1) * cos_phi * cos_phi - std::log(product);
      const double bracket = part_.b0 + x * (part_.b1 + x * part_.b2);
      const double envelope = part_.b0 + x * (part_.p1 + x * part_.p2);
      if (next_uniform() * envelope < bracket) break;
    }
    const double u1 = next_uniform();  // sequenced: argument evaluation order is unspecified
    const double u2 = next_uniform();
    return std::sqrt(x) * unit_vector(u1, u2);
  }

  /// m = int max(-phi, 0) d^3c: the negative mass dropped (0 for a2 >= 0); max(phi, 0) has mass 1 + m.
  double truncated_mass() const noexcept { return part_.truncated_mass; }
  /// Probability that one attempt of sample() is accepted, (1 + m) / W+.
  double acceptance() const noexcept { return part_.acceptance; }
  double a2() const noexcept { return a2_; }

 private:
  static double checked(double a2) {
    if (!(std::fabs(a2) <= 0.5)) throw std::invalid_argument("SonineMaxwellian: need |a2| <= 1/2");
    return a2;
  }

  double a2_;
  int dimension_;
  SoninePositivePart part_;
};

}  // namespace granmc
