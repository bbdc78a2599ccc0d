#include "kernel/theory/mixture_viscosity.hpp"

#include <cmath>
#include <numbers>

// Coefficients: docs/methods/derivations/viscosity.py (exact), docs/methods/derivations/viscosity.md, "Binary
// mixtures". For the ordered pair (i, j): theta = T/m, s^2 = theta_i + theta_j, u = theta_i / s^2, v = theta_j / s^2 =
// 1 - u, b = mu_ji (1 + alpha_ij), mu_ji = m_j / (m_i + m_j), m_ij = m_i m_j / (m_i + m_j).

namespace granmc::theory {

namespace {

const double sqrt_2pi = std::sqrt(2.0 * std::numbers::pi);
constexpr double pi = std::numbers::pi;

struct PairTerms {
  double s, u, v, b, mu_ji, m_ij, sigma, weight;  // weight = sigma_ij^2 chi_ij
};

PairTerms pair_terms(const MixtureParameters& mp, const double T[2], int i, int j) {
  PairTerms p{};
  const double th_i = T[i] / mp.mass[i], th_j = T[j] / mp.mass[j], s2 = th_i + th_j;
  p.s = std::sqrt(s2);
  p.u = th_i / s2;
  p.v = th_j / s2;
  p.mu_ji = mp.mass[j] / (mp.mass[i] + mp.mass[j]);
  p.b = p.mu_ji * (1.0 + mp.alpha[i][j]);
  p.m_ij = mp.mass[i] * mp.mass[j] / (mp.mass[i] + mp.mass[j]);
  p.sigma = 0.5 * (mp.diameter[i] + mp.diameter[j]);
  p.weight = p.sigma * p.sigma * mp.chi[i][j];
  return p;
}

/// (1/5) int Theta (sig.g) phi_i D(v1) f_j0 : m_i [D(v1') - D(v1)] = m_i s^5 l1: f_i^(1) against f_j^(0).
double l1(const PairTerms& p, double a_j) {
  const double u = p.u, v = p.v, b = p.b;
  return -sqrt_2pi / 15.0 * b * u * u * (8.0 * (10.0 + 2.0 * u - 3.0 * b) + a_j * v * v * (3.0 * b + 6.0 * u - 10.0));
}

/// The same with f_i^(0) at v1 and phi_j D(v2) at v2: m_i s^5 l2.
double l2(const PairTerms& p, double a_i) {
  const double u = p.u, v = p.v, b = p.b;
  return -sqrt_2pi / 15.0 * b * v * v * (8.0 * (2.0 * u - 3.0 * b) + a_i * u * u * (3.0 * b + 6.0 * u - 8.0));
}

}  // namespace

MixtureShearViscosity mixture_shear_viscosity(const MixtureParameters& mp, double phi, const MixtureSonine& state,
                                              double temperature, ViscosityReference reference) noexcept {
  const double n_total = mp.density[0] + mp.density[1];
  const double x[2] = {mp.density[0] / n_total, mp.density[1] / n_total};
  const double T2 = temperature / (x[0] * state.gamma + x[1]);
  const double T[2] = {state.gamma * T2, T2};
  const double* a = state.a2;
  // Enskog density of the packing fraction: phi = (pi/6) n sum_k x_k sigma_k^3.
  const double n_enskog = 6.0 * phi / (pi * (x[0] * std::pow(mp.diameter[0], 3) + x[1] * std::pow(mp.diameter[1], 3)));
  const double nE[2] = {x[0] * n_enskog, x[1] * n_enskog};
  const double r = reference == ViscosityReference::cooling ? 0.5 : 1.0;
  const double zeta = partial_cooling_rate(mp, 0, T[0], T[1], a[0], a[1]);

  // Kinetic balance of species i: sum_j (tau_ij - r zeta delta_ij) eta_j^k = n_i T_i Y_i.
  double tau[2][2] = {{0.0, 0.0}, {0.0, 0.0}}, rhs[2];
  for (int i = 0; i < 2; ++i) {
    const double th_i = T[i] / mp.mass[i];
    rhs[i] = mp.density[i] * T[i];
    for (int j = 0; j < 2; ++j) {
      const PairTerms p = pair_terms(mp, T, i, j);
      const double th_j = T[j] / mp.mass[j], s5 = std::pow(p.s, 5);
      tau[i][i] -= mp.density[j] * p.weight * s5 * l1(p, a[j]) / (2.0 * th_i * th_i);
      tau[i][j] -= mp.density[i] * p.weight * mp.mass[i] * s5 * l2(p, a[i]) / (2.0 * mp.mass[j] * th_j * th_j);
      // Enskog gradient source (viscosity.md, item 3): 1 - (2/5) phi chi (1+alpha)(1 - 3 alpha) for one species.
      rhs[i] -= 2.0 * pi / 15.0 * mp.density[i] * nE[j] * p.weight * p.sigma * p.b *
                (4.0 * T[i] - 3.0 * p.b * mp.mass[i] * p.s * p.s);
    }
    tau[i][i] -= r * zeta;
  }
  const double det = tau[0][0] * tau[1][1] - tau[0][1] * tau[1][0];
  MixtureShearViscosity e;
  e.partial[0] = (rhs[0] * tau[1][1] - tau[0][1] * rhs[1]) / det;
  e.partial[1] = (tau[0][0] * rhs[1] - tau[1][0] * rhs[0]) / det;
  e.kinetic = e.partial[0] + e.partial[1];

  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      const PairTerms p = pair_terms(mp, T, i, j);
      // Collisional transfer of f_i^(1) (viscosity.md, item 4): (4/5) phi chi (1 + alpha) eta^k for one species.
      e.transfer += 4.0 * pi / 15.0 * e.partial[i] * nE[j] * p.b * p.weight * p.sigma;
      // Transfer across grad u by f^(0) f^(0), linear in a2_i (item 5): (384/(25 pi)) phi^2 chi (1+alpha)(1 - c0/32)
      // eta0.
      e.gradient += sqrt_2pi / 60.0 * p.m_ij * (1.0 + mp.alpha[i][j]) * p.weight * p.sigma * p.sigma * nE[i] * nE[j] *
                    p.s * (8.0 - a[i] * p.u * p.u - a[j] * p.v * p.v);
    }
  }
  e.total = e.kinetic + e.transfer + e.gradient;
  return e;
}

MixtureViscosityRatios mixture_viscosity_from_ratios(double mu, double omega, double delta, double alpha, double phi,
                                                     ViscosityReference reference) {
  const MixtureParameters mp = mixture_from_ratios(mu, omega, delta, alpha, phi);
  const MixtureParameters elastic = mixture_from_ratios(mu, omega, delta, 1.0, phi);
  const MixtureShearViscosity e = mixture_shear_viscosity(mp, phi, mixture_first_sonine(mp), 1.0, reference);
  const MixtureShearViscosity e1 = mixture_shear_viscosity(elastic, phi, {1.0, {0.0, 0.0}}, 1.0, reference);
  const double sigma_12 = 0.5 * (omega + 1.0), v0 = mixture_thermal_speed(1.0, mu, 1.0);
  return {e.total / e1.total, reduced_viscosity(e.kinetic, 1.0, sigma_12, v0),
          reduced_viscosity(e.total, 1.0, sigma_12, v0)};
}

}  // namespace granmc::theory
