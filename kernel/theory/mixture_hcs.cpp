#include "kernel/theory/mixture_hcs.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "kernel/collide/enskog_chi.hpp"

// Coefficients: output of docs/methods/derivations/mixture_hcs.py (exact rational arithmetic), see
// docs/methods/derivations/mixture-hcs.md.

namespace granmc::theory {

namespace {

const double sqrt_2pi = std::sqrt(2.0 * std::numbers::pi);

/// P(a_i, a_j) = c00 + c10 a_i + c01 a_j + c11 a_i a_j.
struct PairPoly {
  double c00, c10, c01, c11;
};

/// Geometry of the pair (i, j) at temperatures T[0], T[1].
struct Pair {
  double s;     // s = sqrt(theta_i + theta_j), theta = T/m
  double u, v;  // u = theta_i / s^2, v = 1 - u = theta_j / s^2 (computed separately, no cancellation)
  double b;     // b = mu_ji (1 + alpha_ij)
  double d;     // d = 2u - b = 2 (T_i - T_j)/((m_i + m_j) s^2) + mu_ji (1 - alpha_ij): vanishes at elastic equilibrium
  double weight;  // n_j sigma_ij^(d-1) chi_ij
  double theta_i;
};

Pair pair(const MixtureParameters& mp, int i, int j, const double T[2]) {
  Pair q{};
  const double mi = mp.mass[i], mj = mp.mass[j], M = mi + mj;
  const double thi = T[i] / mi, thj = T[j] / mj, s2 = thi + thj;
  const double mu_ji = mj / M, al = mp.alpha[i][j];
  q.s = std::sqrt(s2);
  q.u = thi / s2;
  q.v = thj / s2;
  q.b = mu_ji * (1.0 + al);
  q.d = 2.0 * (T[i] - T[j]) / (M * s2) + mu_ji * (1.0 - al);
  const double sij = 0.5 * (mp.diameter[i] + mp.diameter[j]);
  q.weight = mp.dimension == 2 ? mp.density[j] * sij * mp.chi[i][j] : mp.density[j] * sij * sij * mp.chi[i][j];
  q.theta_i = thi;
  return q;
}

/// Psi_2 = 2 sqrt(2 pi) s^3 P2 (mixture_hcs.py, "P2"):
///   P2 = -2 b (2u - b) + a_i b u^2 (3b + 2u - 8)/4 + a_j b (1-u)^2 (3b + 2u)/4
///        + a_i a_j 3 b u^2 (1-u)^2 (3b + 10u - 8)/32.
PairPoly p2(const Pair& q) {
  const double u = q.u, v = q.v, b = q.b;
  return {-2.0 * b * q.d, b * u * u * (3.0 * b + 2.0 * u - 8.0) / 4.0, b * v * v * (3.0 * b + 2.0 * u) / 4.0,
          3.0 * b * u * u * v * v * (3.0 * b + 10.0 * u - 8.0) / 32.0};
}

/// Psi_4 = (|S^(d-1)| / (2 pi)) sqrt(2 pi) s^5 P4 (mixture_hcs.py [--dimension 2], "P4"):
///   P4 = -4 b (2u - b)(2b^2 - 4bu + u^2 + k0 u)
///        - a_i b u^2 (-30b^3 + 24b^2 u + 96b^2 + 9bu^2 + k1 bu + k2 b + 6u^3 + k3 u^2 + k4 u + k5)/2
///        - a_j b (1-u)^2 (-30b^3 + 24b^2 u + 9bu^2 + k6 bu + 6u^3 + k7 u^2)/2
///        - a_i a_j b u^2 (1-u)^2 (30b^3 + 72b^2 u - 96b^2 + 135bu^2 + k8 bu + k9 b + 210u^3 + k10 u^2 + k11 u
///          + k12)/16,
/// the numbers k that depend on d below (P2 is the same in both dimensions).
struct P4Numbers {
  double k[13];
};
constexpr P4Numbers p4_spheres{{5, -87, -132, -34, 128, 80, -15, -10, -261, 132, -510, 384, -80}};
constexpr P4Numbers p4_disks{{4, -84, -120, -32, 112, 64, -12, -8, -252, 120, -480, 336, -64}};

PairPoly p4(const Pair& q, const P4Numbers& n) {
  const double* k = n.k;
  const double u = q.u, v = q.v, b = q.b, b2 = b * b, b3 = b2 * b, u2 = u * u, u3 = u2 * u;
  const double c00 = -4.0 * b * q.d * (2.0 * b2 - 4.0 * b * u + u2 + k[0] * u);
  const double c10 = -b * u2 *
                     (-30.0 * b3 + 24.0 * b2 * u + 96.0 * b2 + 9.0 * b * u2 + k[1] * b * u + k[2] * b + 6.0 * u3 +
                      k[3] * u2 + k[4] * u + k[5]) /
                     2.0;
  const double c01 =
      -b * v * v * (-30.0 * b3 + 24.0 * b2 * u + 9.0 * b * u2 + k[6] * b * u + 6.0 * u3 + k[7] * u2) / 2.0;
  const double c11 = -b * u2 * v * v *
                     (30.0 * b3 + 72.0 * b2 * u - 96.0 * b2 + 135.0 * b * u2 + k[8] * b * u + k[9] * b + 210.0 * u3 +
                      k[10] * u2 + k[11] * u + k[12]) /
                     16.0;
  return {c00, c10, c01, c11};
}

PairPoly p4(const Pair& q, const MixtureParameters& mp) { return p4(q, mp.dimension == 2 ? p4_disks : p4_spheres); }

/// |S^(d-1)| / (2 pi): Psi_p = sphere_factor sqrt(2 pi) s^(p+1) P_p (2 spheres, 1 disks).
double sphere_factor(const MixtureParameters& mp) noexcept { return mp.dimension == 2 ? 1.0 : 2.0; }

/// Linearised HCS quantities at temperatures T: zeta_i = z0[i] + z[i][0] a_0 + z[i][1] a_1 and
/// E_i = e0[i] + e[i][0] a_0 + e[i][1] a_1 (E_i up to the constant factor 2 sqrt(2 pi)).
struct Linearised {
  double z0[2], z[2][2], e0[2], e[2][2];
};

Linearised linearise(const MixtureParameters& mp, const double T[2]) {
  Linearised L{};
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      const Pair q = pair(mp, i, j, T);
      const PairPoly P2 = p2(q), P4 = p4(q, mp);
      // zeta_i = -(m_i / (d T_i)) sum_j weight Psi_2: -(2 sqrt(2 pi)/3) sum_j weight s^3 P2 / theta_i for
      // spheres, -(sqrt(2 pi)/2) for disks.
      const double prefactor = mp.dimension == 2 ? sqrt_2pi / 2.0 : 2.0 * sqrt_2pi / 3.0;
      const double cz = -prefactor * q.weight * q.s * q.s * q.s / q.theta_i;
      L.z0[i] += cz * P2.c00;
      L.z[i][i] += cz * P2.c10;
      L.z[i][j] += cz * P2.c01;
      // E_i pair term: weight s^5 [P4 - 2 (d + 2) u (1 + a_i) P2], linearised in (a_i, a_j). Its a-independent
      // part is -4 b (2u - b)(2b^2 - 4bu + u^2) in both dimensions, proportional to d, so exactly 0 at elastic
      // equilibrium.
      const double ce = q.weight * std::pow(q.s, 5);
      const double u = q.u, b = q.b, f4 = 2.0 * (mp.dimension + 2.0);
      L.e0[i] += ce * (-4.0 * b * q.d * (2.0 * b * b - 4.0 * b * u + u * u));
      L.e[i][i] += ce * (P4.c10 - f4 * u * (P2.c10 + P2.c00));
      L.e[i][j] += ce * (P4.c01 - f4 * u * P2.c01);
    }
  }
  return L;
}

/// a2 solving the linearised fourth-moment equations E_0 = E_1 = 0 at temperatures T (Cramer's rule).
void solve_a2(const Linearised& L, double a[2]) {
  const double det = L.e[0][0] * L.e[1][1] - L.e[0][1] * L.e[1][0];
  a[0] = (-L.e0[0] * L.e[1][1] + L.e[0][1] * L.e0[1]) / det;
  a[1] = (-L.e[0][0] * L.e0[1] + L.e0[0] * L.e[1][0]) / det;
}

/// zeta_1 - zeta_2 at gamma = exp(x) (T = {gamma, 1}); the a2 from the linear system when sonine.
double rate_difference(const MixtureParameters& mp, double x, bool sonine) {
  const double T[2] = {std::exp(x), 1.0};
  const Linearised L = linearise(mp, T);
  double a[2] = {0.0, 0.0};
  if (sonine) solve_a2(L, a);
  const double z0 = L.z0[0] + L.z[0][0] * a[0] + L.z[0][1] * a[1];
  const double z1 = L.z0[1] + L.z[1][0] * a[0] + L.z[1][1] * a[1];
  return z0 - z1;
}

/// Root of f(x) nearest to x0: step outward on both sides (steps 0.01 * 1.5^k, |x - x0| < 100) until the sign
/// changes between consecutive points, then bisect to the last bit. NaN if no sign change is found.
template <class F>
double nearest_root(F f, double x0) {
  const double f0 = f(x0);
  if (f0 == 0.0) return x0;
  if (!std::isfinite(f0)) return std::numeric_limits<double>::quiet_NaN();
  double lo = x0, hi = x0, flo = f0, fhi = f0;
  double a = 0.0, b = 0.0, fa = 0.0;
  bool found = false;
  for (double d = 0.01; d < 100.0 && !found; d *= 1.5) {
    const double nhi = x0 + d, nlo = x0 - d;
    const double fnhi = f(nhi), fnlo = f(nlo);
    if (std::isfinite(fnhi) && (fnhi > 0.0) != (fhi > 0.0)) {
      a = hi, b = nhi, fa = fhi, found = true;
    } else if (std::isfinite(fnlo) && (fnlo > 0.0) != (flo > 0.0)) {
      a = nlo, b = lo, fa = fnlo, found = true;
    } else {
      hi = nhi, lo = nlo, fhi = fnhi, flo = fnlo;
    }
  }
  if (!found) return std::numeric_limits<double>::quiet_NaN();
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (a + b);
    if (mid == a || mid == b) break;
    const double fm = f(mid);
    if (fm == 0.0) return mid;
    if ((fm > 0.0) == (fa > 0.0)) {
      a = mid, fa = fm;
    } else {
      b = mid;
    }
  }
  return 0.5 * (a + b);
}

}  // namespace

MixtureParameters mixture_from_ratios(double mu, double omega, double delta, double alpha, double phi) {
  MixtureParameters mp{};
  mp.mass[0] = mu, mp.mass[1] = 1.0;
  mp.diameter[0] = omega, mp.diameter[1] = 1.0;
  mp.density[0] = delta, mp.density[1] = 1.0;
  const std::vector<double> x{delta / (1.0 + delta), 1.0 / (1.0 + delta)}, sigma{omega, 1.0};
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      mp.alpha[i][j] = alpha;
      mp.chi[i][j] = phi > 0.0 ? granmc::enskog_chi(phi, x, sigma, i, j) : 1.0;
    }
  }
  return mp;
}

double collisional_moment(const MixtureParameters& mp, int i, int j, int p, double T1, double T2, double a2_1,
                          double a2_2) noexcept {
  const double T[2] = {T1, T2}, a[2] = {a2_1, a2_2};
  if (p != 2 && p != 4) return std::numeric_limits<double>::quiet_NaN();
  const Pair q = pair(mp, i, j, T);
  const PairPoly P = p == 2 ? p2(q) : p4(q, mp);
  const double val = P.c00 + P.c10 * a[i] + P.c01 * a[j] + P.c11 * a[i] * a[j];
  return q.weight * sphere_factor(mp) * sqrt_2pi * std::pow(q.s, p + 1) * val;
}

double partial_cooling_rate(const MixtureParameters& mp, int i, double T1, double T2, double a2_1,
                            double a2_2) noexcept {
  const double T[2] = {T1, T2};
  const Linearised L = linearise(mp, T);
  return L.z0[i] + L.z[i][0] * a2_1 + L.z[i][1] * a2_2;
}

double temperature_ratio_maxwell(const MixtureParameters& mp) {
  return std::exp(nearest_root([&](double x) { return rate_difference(mp, x, false); }, 0.0));
}

MixtureSonine mixture_first_sonine(const MixtureParameters& mp) {
  MixtureSonine r{};
  const double xm = std::log(temperature_ratio_maxwell(mp));
  const double x = nearest_root([&](double y) { return rate_difference(mp, y, true); }, xm);
  r.gamma = std::exp(x);
  const double T[2] = {r.gamma, 1.0};
  solve_a2(linearise(mp, T), r.a2);
  return r;
}

}  // namespace granmc::theory
