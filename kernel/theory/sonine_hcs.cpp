#include "kernel/theory/sonine_hcs.hpp"

#include <array>
#include <cmath>
#include <cstddef>

#include "kernel/theory/sonine.hpp"

// Coefficients: output of docs/methods/derivations/sonine_hcs.py (exact rational arithmetic), see
// docs/methods/derivations/sonine-hcs.md.  All moments are in units of sqrt(2 pi).

namespace granmc::theory {

namespace {

/// Coefficients of mu_p / sqrt(2 pi) = c00 + c10 a2 + c01 a3 + c20 a2^2 + c11 a2 a3 + c02 a3^2.
struct MomentPoly {
  double c00, c10, c01, c20, c11, c02;
  [[nodiscard]] double operator()(double a2, double a3) const noexcept {
    return c00 + c10 * a2 + c01 * a3 + c20 * a2 * a2 + c11 * a2 * a3 + c02 * a3 * a3;
  }
};

/// mu_2: its Sonine factor is the same in every dimension; the disks' prefactor is half the spheres'.
MomentPoly mu2_poly(double al, int d) noexcept {
  const double e = d == 3 ? 1.0 - al * al : (1.0 - al * al) / 2.0;
  return {e, 3.0 * e / 16.0, e / 64.0, 9.0 * e / 1024.0, 15.0 * e / 2048.0, 35.0 * e / 16384.0};
}

MomentPoly mu4_poly(double al, int d) noexcept {
  const double p = 1.0 + al, a = al, a2 = a * a, a3 = a2 * a;
  if (d == 2) {
    const double q = 30.0 * a3 - 30.0 * a2 - 39.0 * a + 103.0;  // shared by the a2^2 and a2 a3 terms
    return {(1.0 - a2) * (7.0 + 2.0 * a2) / 4.0,
            p * (209.0 - 177.0 * a + 30.0 * a2 - 30.0 * a3) / 64.0,
            p * (10.0 * a3 - 10.0 * a2 + 107.0 * a - 139.0) / 256.0,
            p * q / 4096.0,
            p * q / 8192.0,
            5.0 * p * (10.0 * a3 - 10.0 * a2 - 37.0 * a + 69.0) / 65536.0};
  }
  const double q = 30.0 * a3 - 30.0 * a2 - 9.0 * a + 137.0;  // shared by the a2^2 and a2 a3 terms
  return {(1.0 - a2) * (9.0 + 2.0 * a2) / 2.0,
          p * (271.0 - 207.0 * a + 30.0 * a2 - 30.0 * a3) / 32.0,
          p * (10.0 * a3 - 10.0 * a2 + 117.0 * a - 181.0) / 128.0,
          p * q / 2048.0,
          p * q / 4096.0,
          5.0 * p * (10.0 * a3 - 10.0 * a2 - 27.0 * a + 91.0) / 32768.0};
}

MomentPoly mu6_poly(double al, int d) noexcept {
  const double p = 1.0 + al, a = al, a2 = a * a, a3 = a2 * a, a4 = a3 * a, a5 = a4 * a;
  if (d == 2) {
    const double r = 280.0 * a5 - 280.0 * a4 - 340.0 * a3 + 852.0 * a2 + 225.0 * a - 97.0;  // a2^2, a2 a3
    return {3.0 * (1.0 - a2) * (75.0 + 36.0 * a2 + 8.0 * a4) / 32.0,
            3.0 * p * (5361.0 - 4785.0 * a + 2316.0 * a2 - 2060.0 * a3 + 280.0 * a4 - 280.0 * a5) / 512.0,
            3.0 * p * (280.0 * a5 - 280.0 * a4 + 3660.0 * a3 - 4428.0 * a2 + 9105.0 * a - 10833.0) / 2048.0,
            -9.0 * p * r / 32768.0,
            -3.0 * p * r / 65536.0,
            -3.0 * p * (280.0 * a5 - 280.0 * a4 - 1140.0 * a3 + 1908.0 * a2 + 1905.0 * a - 3249.0) / 524288.0};
  }
  const double r = 280.0 * a5 - 280.0 * a4 - 60.0 * a3 + 1084.0 * a2 + 217.0 * a + 551.0;  // a2^2, a2 a3
  return {3.0 * (1.0 - a2) * (115.0 + 44.0 * a2 + 8.0 * a4) / 16.0,
          3.0 * p * (8297.0 - 6889.0 * a + 2852.0 * a2 - 2340.0 * a3 + 280.0 * a4 - 280.0 * a5) / 256.0,
          3.0 * p * (280.0 * a5 - 280.0 * a4 + 3940.0 * a3 - 5476.0 * a2 + 12617.0 * a - 16841.0) / 1024.0,
          -9.0 * p * r / 16384.0,
          -3.0 * p * r / 32768.0,
          -3.0 * p * (280.0 * a5 - 280.0 * a4 - 860.0 * a3 + 2396.0 * a2 + 1193.0 * a - 3113.0) / 262144.0};
}

/// The stationarity conditions E4 = mu_4 - f4 mu_2 g4 = 0, E6 = mu_6 - f6 mu_2 g6 = 0, f4 = d + 2 (5 for
/// spheres, 4 for disks), f6 = 3 (d + 2)(d + 4) / 4 (26.25, 18), with <c^4> = d(d+2)/4 (1 + a2) and <c^6> =
/// d(d+2)(d+4)/8 (1 + 3 a2 - a3):
///  - the cooling state, mu_p = (p/d) mu_2 <c^p>: g4 = 1 + a2, g6 = 1 + 3 a2 - a3;
///  - white noise, mu_p = (p (p + d - 2) / d) mu_2 <c^(p - 2)> (the noise term (xi/2) Lap_c F, xi = mu_2 / d,
///    against c^p): g4 = 1, g6 = 1 + a2 (docs/methods/derivations/sonine-hcs.md, "White noise").
double f4(int d) noexcept { return d + 2.0; }
double f6(int d) noexcept { return 3.0 * (d + 2.0) * (d + 4.0) / 4.0; }

/// g4, g6 and their derivatives in a2 (x) and a3 (y); g4 does not depend on a3.
struct StateWeights {
  double g4, g4x, g6, g6x, g6y;
};
StateWeights state_weights(SonineState state, double a2, double a3) noexcept {
  if (state == SonineState::cooling) return {1.0 + a2, 1.0, 1.0 + 3.0 * a2 - a3, 3.0, -1.0};
  return {1.0, 0.0, 1.0 + a2, 1.0, 0.0};
}

/// Residuals E4, E6 (units of sqrt(2 pi)).
struct Residual {
  double e4, e6;
};
Residual residual(double alpha, double a2, double a3, int d, SonineState state) noexcept {
  const SonineMoments m = hcs_collisional_moments(alpha, a2, a3, d);
  const StateWeights g = state_weights(state, a2, a3);
  return {m.mu4 - f4(d) * m.mu2 * g.g4, m.mu6 - f6(d) * m.mu2 * g.g6};
}

/// sum_k c[k] a^k, from the highest power down (the order the closed forms below were written in); the
/// powers a, a^2 = a a, a^3 = a^2 a, ... (1 a and c[0] 1 are exact).
template <std::size_t n>
double descending(const std::array<double, n>& c, double a) noexcept {
  std::array<double, n> power{};
  power[0] = 1.0;
  for (std::size_t k = 1; k < n; ++k) power[k] = power[k - 1] * a;
  double sum = c[n - 1] * power[n - 1];
  for (std::size_t k = n - 1; k-- > 0;) sum += c[k] * power[k];
  return sum;
}

}  // namespace

SonineMoments hcs_collisional_moments(double alpha, double a2, double a3, int dimension) noexcept {
  return {mu2_poly(alpha, dimension)(a2, a3), mu4_poly(alpha, dimension)(a2, a3), mu6_poly(alpha, dimension)(a2, a3)};
}

double hcs_a2_nonlinear(double alpha, int dimension) noexcept {
  // E4(a2, a3 = 0) = k3 a2^3 + k2 a2^2 + k1 a2 + k0 (units of sqrt(2 pi)); spheres:
  //   k3 = -45 (1 - alpha^2) / 1024,
  //   k2 = (1 + alpha)(30 alpha^3 - 30 alpha^2 + 2001 alpha - 1873) / 2048,
  //   k1 = (1 + alpha)(81 - 17 alpha + 30 alpha^2 - 30 alpha^3) / 32,
  //   k0 = (1 - alpha^2)(2 alpha^2 - 1) / 2;
  // disks: -9 (1 - alpha^2) / 512, (1 + alpha)(30 alpha^3 - 30 alpha^2 + 1569 alpha - 1505) / 4096,
  //   (1 + alpha)(57 - 25 alpha + 30 alpha^2 - 30 alpha^3) / 64, (1 - alpha^2)(2 alpha^2 - 1) / 4.
  // Dropping k2, k3 gives the van Noije-Ernst a2 = -k0 / k1 (theory::hcs_a2).
  const double a = alpha, p = 1.0 + a, a2 = a * a, a3 = a2 * a;
  const bool disks = dimension == 2;
  const double k3 = disks ? -9.0 * (1.0 - a2) / 512.0 : -45.0 * (1.0 - a2) / 1024.0;
  const double k2 = disks ? p * (30.0 * a3 - 30.0 * a2 + 1569.0 * a - 1505.0) / 4096.0
                          : p * (30.0 * a3 - 30.0 * a2 + 2001.0 * a - 1873.0) / 2048.0;
  const double k1 = disks ? p * (57.0 - 25.0 * a + 30.0 * a2 - 30.0 * a3) / 64.0
                          : p * (81.0 - 17.0 * a + 30.0 * a2 - 30.0 * a3) / 32.0;
  const double k0 = disks ? (1.0 - a2) * (2.0 * a2 - 1.0) / 4.0 : (1.0 - a2) * (2.0 * a2 - 1.0) / 2.0;
  double x = hcs_a2(alpha, dimension);  // = -k0 / k1
  // The physical root (|a2| < 0.3) is simple and the two others are far away (x < -23 and x > 2 on
  // [0, 1], both dimensions), so Newton from the linear value converges quadratically in a handful of steps.
  for (int it = 0; it < 50; ++it) {
    const double f = ((k3 * x + k2) * x + k1) * x + k0;
    const double df = (3.0 * k3 * x + 2.0 * k2) * x + k1;
    const double dx = f / df;
    x -= dx;
    if (std::abs(dx) <= 1e-16 * (1.0 + std::abs(x))) break;
  }
  return x;
}

SecondSonine hcs_second_sonine(double alpha, int dimension) noexcept {
  // Spheres: the linear system A_p + B_p a2 + C_p a3 = 0 (units of sqrt(2 pi), from E4 and E6 linearised):
  //   A_4 = (1 - alpha^2)(2 alpha^2 - 1) / 2
  //   B_4 = (1 + alpha)(81 - 17 alpha + 30 alpha^2 - 30 alpha^3) / 32
  //   C_4 = (1 + alpha)(10 alpha^3 - 10 alpha^2 + 127 alpha - 191) / 128
  //   A_6 = 3 (1 - alpha^2)(8 alpha^4 + 44 alpha^2 - 25) / 16
  //   B_6 = 3 (1 + alpha)(1157 + 251 alpha + 2852 alpha^2 - 2340 alpha^3 + 280 alpha^4 - 280 alpha^5) / 256
  //   C_6 = 3 (1 + alpha)(280 alpha^5 - 280 alpha^4 + 3940 alpha^3 - 5476 alpha^2 + 3797 alpha - 8021) / 1024
  // Cramer's rule, common factors cancelled: a2 = 16 (1 - alpha) N2 / D, a3 = 128 (1 - alpha) N3 / D with the
  // coefficients below (of alpha^0, alpha^1, ...; the disks' from docs/methods/derivations/sonine_hcs.py --dimension
  // 2). D > 0 on [0, 1]: its real roots are 1.510 and 2.028 for spheres, 1.291 and 1.642 for disks.
  struct Coefficients {
    std::array<double, 8> n2, n3;
    std::array<double, 9> d;
  };
  static constexpr Coefficients spheres{
      {1623.0, -311.0, -1206.0, -842.0, -4352.0, 3072.0, -240.0, 240.0},
      {-217.0, 169.0, 838.0, -710.0, -864.0, 736.0, -80.0, 80.0},
      {214357.0, -172458.0, 112155.0, 25716.0, -4410.0, -84480.0, 34800.0, -5600.0, 2800.0}};
  static constexpr Coefficients disks{
      {849.0, -321.0, -30.0, -738.0, -3520.0, 2880.0, -240.0, 240.0},
      {-183.0, 159.0, 702.0, -638.0, -704.0, 640.0, -80.0, 80.0},
      {102195.0, -128358.0, 70017.0, 9060.0, 15950.0, -74240.0, 34800.0, -5600.0, 2800.0}};
  const Coefficients& c = dimension == 2 ? disks : spheres;
  const double n2 = descending(c.n2, alpha), n3 = descending(c.n3, alpha), d = descending(c.d, alpha);
  return {16.0 * (1.0 - alpha) * n2 / d, 128.0 * (1.0 - alpha) * n3 / d};
}

SecondSonine second_sonine_linear(double alpha, SonineState state, int dimension) noexcept {
  // E_p linearised about (0, 0): A_p + B_p a2 + C_p a3 with A = mu_p.c00 - f mu_2.c00 (every g is 1 there),
  // B = mu_p.c10 - f (mu_2.c10 + mu_2.c00 g_x), C = mu_p.c01 - f (mu_2.c01 + mu_2.c00 g_y); Cramer's rule.
  const MomentPoly m2 = mu2_poly(alpha, dimension), m4 = mu4_poly(alpha, dimension), m6 = mu6_poly(alpha, dimension);
  const StateWeights g = state_weights(state, 0.0, 0.0);
  const double h4 = f4(dimension), h6 = f6(dimension);
  const double a4 = m4.c00 - h4 * m2.c00, b4 = m4.c10 - h4 * (m2.c10 + m2.c00 * g.g4x), c4 = m4.c01 - h4 * m2.c01;
  const double a6 = m6.c00 - h6 * m2.c00, b6 = m6.c10 - h6 * (m2.c10 + m2.c00 * g.g6x),
               c6 = m6.c01 - h6 * (m2.c01 + m2.c00 * g.g6y);
  const double det = b4 * c6 - c4 * b6;
  return {(c4 * a6 - a4 * c6) / det, (a4 * b6 - b4 * a6) / det};
}

SecondSonine second_sonine_nonlinear(double alpha, SonineState state, int dimension) noexcept {
  SecondSonine s = second_sonine_linear(alpha, state, dimension);
  // Newton on (E4, E6) = 0; the Jacobian is analytic since the moments are quadratic in (a2, a3).
  const MomentPoly m2 = mu2_poly(alpha, dimension), m4 = mu4_poly(alpha, dimension), m6 = mu6_poly(alpha, dimension);
  const double h4 = f4(dimension), h6 = f6(dimension);
  for (int it = 0; it < 50; ++it) {
    const Residual r = residual(alpha, s.a2, s.a3, dimension, state);
    const double x = s.a2, y = s.a3;
    const StateWeights g = state_weights(state, x, y);
    const double mu2 = m2(x, y);
    const double d2x = m2.c10 + 2.0 * m2.c20 * x + m2.c11 * y, d2y = m2.c01 + m2.c11 * x + 2.0 * m2.c02 * y;
    const double d4x = m4.c10 + 2.0 * m4.c20 * x + m4.c11 * y, d4y = m4.c01 + m4.c11 * x + 2.0 * m4.c02 * y;
    const double d6x = m6.c10 + 2.0 * m6.c20 * x + m6.c11 * y, d6y = m6.c01 + m6.c11 * x + 2.0 * m6.c02 * y;
    const double j11 = d4x - h4 * (g.g4x * mu2 + g.g4 * d2x), j12 = d4y - h4 * g.g4 * d2y;
    const double j21 = d6x - h6 * (g.g6x * mu2 + g.g6 * d2x), j22 = d6y - h6 * (g.g6y * mu2 + g.g6 * d2y);
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

double hcs_a2_model_error(double alpha, int dimension) noexcept {
  return std::fabs(hcs_second_sonine(alpha, dimension).a2 - hcs_a2(alpha, dimension));
}

double white_noise_a2_model_error(double alpha, int dimension) noexcept {
  return std::fabs(second_sonine_linear(alpha, SonineState::white_noise, dimension).a2 -
                   white_noise_a2(alpha, dimension));
}

}  // namespace granmc::theory
