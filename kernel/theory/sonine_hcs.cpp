#include "kernel/theory/sonine_hcs.hpp"

#include <cmath>

#include "kernel/theory/sonine.hpp"

// Coefficients: output of docs/derivations/sonine_hcs.py (exact rational arithmetic), see
// docs/derivations/sonine-hcs.md.  All moments are in units of sqrt(2 pi).

namespace granmc::theory {

namespace {

/// Coefficients of mu_p / sqrt(2 pi) = c00 + c10 a2 + c01 a3 + c20 a2^2 + c11 a2 a3 + c02 a3^2.
struct MomentPoly {
  double c00, c10, c01, c20, c11, c02;
  [[nodiscard]] double operator()(double a2, double a3) const noexcept {
    return c00 + c10 * a2 + c01 * a3 + c20 * a2 * a2 + c11 * a2 * a3 + c02 * a3 * a3;
  }
};

MomentPoly mu2_poly(double al) noexcept {
  const double e = 1.0 - al * al;
  return {e, 3.0 * e / 16.0, e / 64.0, 9.0 * e / 1024.0, 15.0 * e / 2048.0, 35.0 * e / 16384.0};
}

MomentPoly mu4_poly(double al) noexcept {
  const double p = 1.0 + al, a = al, a2 = a * a, a3 = a2 * a;
  const double q = 30.0 * a3 - 30.0 * a2 - 9.0 * a + 137.0;  // shared by the a2^2 and a2 a3 terms
  return {(1.0 - a2) * (9.0 + 2.0 * a2) / 2.0,
          p * (271.0 - 207.0 * a + 30.0 * a2 - 30.0 * a3) / 32.0,
          p * (10.0 * a3 - 10.0 * a2 + 117.0 * a - 181.0) / 128.0,
          p * q / 2048.0,
          p * q / 4096.0,
          5.0 * p * (10.0 * a3 - 10.0 * a2 - 27.0 * a + 91.0) / 32768.0};
}

MomentPoly mu6_poly(double al) noexcept {
  const double p = 1.0 + al, a = al, a2 = a * a, a3 = a2 * a, a4 = a3 * a, a5 = a4 * a;
  const double r = 280.0 * a5 - 280.0 * a4 - 60.0 * a3 + 1084.0 * a2 + 217.0 * a + 551.0;  // a2^2, a2 a3
  return {3.0 * (1.0 - a2) * (115.0 + 44.0 * a2 + 8.0 * a4) / 16.0,
          3.0 * p * (8297.0 - 6889.0 * a + 2852.0 * a2 - 2340.0 * a3 + 280.0 * a4 - 280.0 * a5) / 256.0,
          3.0 * p * (280.0 * a5 - 280.0 * a4 + 3940.0 * a3 - 5476.0 * a2 + 12617.0 * a - 16841.0) / 1024.0,
          -9.0 * p * r / 16384.0,
          -3.0 * p * r / 32768.0,
          -3.0 * p * (280.0 * a5 - 280.0 * a4 - 860.0 * a3 + 2396.0 * a2 + 1193.0 * a - 3113.0) / 262144.0};
}

/// HCS residuals E4 = mu_4 - (4/3) mu_2 <c^4>, E6 = mu_6 - 2 mu_2 <c^6> (units of sqrt(2 pi)).
struct Residual {
  double e4, e6;
};
Residual hcs_residual(double alpha, double a2, double a3) noexcept {
  const SonineMoments m = hcs_collisional_moments(alpha, a2, a3);
  return {m.mu4 - 5.0 * m.mu2 * (1.0 + a2), m.mu6 - 26.25 * m.mu2 * (1.0 + 3.0 * a2 - a3)};
}

}  // namespace

SonineMoments hcs_collisional_moments(double alpha, double a2, double a3) noexcept {
  return {mu2_poly(alpha)(a2, a3), mu4_poly(alpha)(a2, a3), mu6_poly(alpha)(a2, a3)};
}

double hcs_a2_nonlinear(double alpha) noexcept {
  // E4(a2, a3 = 0) = k3 a2^3 + k2 a2^2 + k1 a2 + k0 (units of sqrt(2 pi)):
  //   k3 = -45 (1 - alpha^2) / 1024,
  //   k2 = (1 + alpha)(30 alpha^3 - 30 alpha^2 + 2001 alpha - 1873) / 2048,
  //   k1 = (1 + alpha)(81 - 17 alpha + 30 alpha^2 - 30 alpha^3) / 32,
  //   k0 = (1 - alpha^2)(2 alpha^2 - 1) / 2.
  // Dropping k2, k3 gives the van Noije-Ernst a2 = -k0 / k1 (theory::hcs_a2).
  const double a = alpha, p = 1.0 + a, a2 = a * a, a3 = a2 * a;
  const double k3 = -45.0 * (1.0 - a2) / 1024.0;
  const double k2 = p * (30.0 * a3 - 30.0 * a2 + 2001.0 * a - 1873.0) / 2048.0;
  const double k1 = p * (81.0 - 17.0 * a + 30.0 * a2 - 30.0 * a3) / 32.0;
  const double k0 = (1.0 - a2) * (2.0 * a2 - 1.0) / 2.0;
  double x = hcs_a2(alpha);  // = -k0 / k1
  // The physical root (|a2| < 0.22) is simple and the two others are far away (x < -23 and x > 2.2 on
  // [0, 1]), so Newton from the linear value converges quadratically in a handful of steps.
  for (int it = 0; it < 50; ++it) {
    const double f = ((k3 * x + k2) * x + k1) * x + k0;
    const double df = (3.0 * k3 * x + 2.0 * k2) * x + k1;
    const double dx = f / df;
    x -= dx;
    if (std::abs(dx) <= 1e-16 * (1.0 + std::abs(x))) break;
  }
  return x;
}

SecondSonine hcs_second_sonine(double alpha) noexcept {
  // Linear system A_p + B_p a2 + C_p a3 = 0 (units of sqrt(2 pi), from E4 and E6 linearised):
  //   A_4 = (1 - alpha^2)(2 alpha^2 - 1) / 2
  //   B_4 = (1 + alpha)(81 - 17 alpha + 30 alpha^2 - 30 alpha^3) / 32
  //   C_4 = (1 + alpha)(10 alpha^3 - 10 alpha^2 + 127 alpha - 191) / 128
  //   A_6 = 3 (1 - alpha^2)(8 alpha^4 + 44 alpha^2 - 25) / 16
  //   B_6 = 3 (1 + alpha)(1157 + 251 alpha + 2852 alpha^2 - 2340 alpha^3 + 280 alpha^4 - 280 alpha^5) / 256
  //   C_6 = 3 (1 + alpha)(280 alpha^5 - 280 alpha^4 + 3940 alpha^3 - 5476 alpha^2 + 3797 alpha - 8021) / 1024
  // Cramer's rule, common factors cancelled:
  const double a = alpha, a2 = a * a, a3 = a2 * a, a4 = a3 * a, a5 = a4 * a, a6 = a5 * a, a7 = a6 * a, a8 = a7 * a;
  const double n2 = 240.0 * a7 - 240.0 * a6 + 3072.0 * a5 - 4352.0 * a4 - 842.0 * a3 - 1206.0 * a2 - 311.0 * a + 1623.0;
  const double n3 = 80.0 * a7 - 80.0 * a6 + 736.0 * a5 - 864.0 * a4 - 710.0 * a3 + 838.0 * a2 + 169.0 * a - 217.0;
  // D > 0 on [0, 1] (its real roots are 1.510 and 2.028).
  const double d = 2800.0 * a8 - 5600.0 * a7 + 34800.0 * a6 - 84480.0 * a5 - 4410.0 * a4 + 25716.0 * a3 +
                   112155.0 * a2 - 172458.0 * a + 214357.0;
  return {16.0 * (1.0 - a) * n2 / d, 128.0 * (1.0 - a) * n3 / d};
}

SecondSonine hcs_second_sonine_nonlinear(double alpha) noexcept {
  SecondSonine s = hcs_second_sonine(alpha);
  // Newton on (E4, E6) = 0; the Jacobian is analytic since the moments are quadratic in (a2, a3).
  const MomentPoly m2 = mu2_poly(alpha), m4 = mu4_poly(alpha), m6 = mu6_poly(alpha);
  for (int it = 0; it < 50; ++it) {
    const Residual r = hcs_residual(alpha, s.a2, s.a3);
    const double x = s.a2, y = s.a3;
    const double mu2 = m2(x, y);
    const double d2x = m2.c10 + 2.0 * m2.c20 * x + m2.c11 * y, d2y = m2.c01 + m2.c11 * x + 2.0 * m2.c02 * y;
    const double d4x = m4.c10 + 2.0 * m4.c20 * x + m4.c11 * y, d4y = m4.c01 + m4.c11 * x + 2.0 * m4.c02 * y;
    const double d6x = m6.c10 + 2.0 * m6.c20 * x + m6.c11 * y, d6y = m6.c01 + m6.c11 * x + 2.0 * m6.c02 * y;
    const double c4 = 5.0 * (1.0 + x), c6 = 26.25 * (1.0 + 3.0 * x - y);
    const double j11 = d4x - 5.0 * mu2 - c4 * d2x, j12 = d4y - c4 * d2y;
    const double j21 = d6x - 3.0 * 26.25 * mu2 - c6 * d2x, j22 = d6y + 26.25 * mu2 - c6 * d2y;
    const double det = j11 * j22 - j12 * j21;
    const double dx = (r.e4 * j22 - r.e6 * j12) / det, dy = (j11 * r.e6 - j21 * r.e4) / det;
    s.a2 -= dx;
    s.a3 -= dy;
    if (std::abs(dx) + std::abs(dy) <= 1e-15) break;
  }
  return s;
}

double hcs_cooling_rate_factor(double a2, double a3) noexcept {
  return 1.0 + 3.0 * a2 / 16.0 + a3 / 64.0 + 9.0 * a2 * a2 / 1024.0 + 15.0 * a2 * a3 / 2048.0 +
         35.0 * a3 * a3 / 16384.0;
}

double hcs_a2_model_error(double alpha) noexcept { return std::fabs(hcs_second_sonine(alpha).a2 - hcs_a2(alpha)); }

}  // namespace granmc::theory
