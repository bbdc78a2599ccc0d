#pragma once
// Rough hard spheres (d = 3) and disks (d = 2) with normal restitution alpha, tangential restitution beta and
// reduced moment of inertia kappa = 4 I / (m sigma^2), monodisperse, in the Maxwellian approximation
// (translation at T, rotation at T_r, independent Gaussians; Huthmann and Zippelius, Phys. Rev. E 56 (1997)
// R6275; Luding, Huthmann, McNamara and Zippelius, Phys. Rev. E 58 (1998) 3416). With b = (1 + beta) kappa /
// (2 (1 + kappa)) and nu the smooth gas's collision frequency at T (theory::collision_frequency):
//   dT/dt   = (nu / d)   {-(1 - alpha^2) T + 2 (d - 1) [-b T + b^2 (T + T_r / kappa)]},
//   dT_r/dt = (nu / d_r) 2 (d - 1) (b / kappa) [-T_r + b (T + T_r / kappa)],     d_r = d (d - 1) / 2.
// docs/derivations/rough-hcs.md derives them (docs/derivations/rough_hcs.py checks them by Monte Carlo).

namespace granmc::theory {

/// b = (1 + beta) kappa / (2 (1 + kappa)): the tangential impulse is -m b g_t.
double rough_tangential_factor(double beta, double kappa) noexcept;

/// The two energy production rates over nu at the ratio theta = T_r / T: zeta_tr = -(dT/dt) / (nu T) and
/// zeta_rot = -(dT_r/dt) / (nu T_r).
struct RoughCoolingRates {
  double translation = 0.0;
  double rotation = 0.0;
};
RoughCoolingRates rough_cooling_rates(double alpha, double beta, double kappa, double theta, int dimension) noexcept;

/// theta = T_r / T of the homogeneous cooling state (zeta_tr = zeta_rot): the positive root of a quadratic;
/// 0 for smooth particles (beta = -1), whose rotation does not couple.
double rough_hcs_theta(double alpha, double beta, double kappa, int dimension) noexcept;

/// theta of the steady state heated by white noise on translation only (dT_r/dt = 0): b kappa / (kappa - b),
/// whatever alpha and d.
double rough_white_noise_theta(double beta, double kappa) noexcept;

/// theta of the steady state heated by white noise of which a share `rotational_share` epsilon of the power kicks
/// the rotation (effects/white_noise.hpp; Megias and Santos, Front. Phys. 10 (2022) 971671): the power balances
/// (1 - epsilon) d_r theta zeta_rot = epsilon d zeta_tr, whose left side minus right side grows with theta, so
/// it has one root, found by bisection. epsilon = 0 gives rough_white_noise_theta.
double rough_split_noise_theta(double alpha, double beta, double kappa, double rotational_share,
                               int dimension) noexcept;

}  // namespace granmc::theory
