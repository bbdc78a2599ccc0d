#pragma once
// Rough hard spheres (d = 3) and disks (d = 2) with normal restitution alpha, tangential restitution beta and
// reduced moment of inertia kappa = 4 I / (m sigma^2), monodisperse, in the Maxwellian approximation
// (translation at T, rotation at T_r, independent Gaussians; Huthmann and Zippelius, Phys. Rev. E 56 (1997)
// R6275; Luding, Huthmann, McNamara and Zippelius, Phys. Rev. E 58 (1998) 3416). With b = (1 + beta) kappa /
// (2 (1 + kappa)) and nu the smooth gas's collision frequency at T (theory::collision_frequency):
//   dT/dt   = (nu / d)   {-(1 - alpha^2) T + 2 (d - 1) [-b T + b^2 (T + T_r / kappa)]},
//   dT_r/dt = (nu / d_r) 2 (d - 1) (b / kappa) [-T_r + b (T + T_r / kappa)],     d_r = d (d - 1) / 2.
// docs/methods/derivations/rough-hcs.md derives them (docs/methods/derivations/rough_hcs.py checks them by Monte
// Carlo).
//
// Binary mixtures (species i, j; docs/methods/derivations/rough-hcs.md, "Mixtures"): with V2 = T_i / m_i + T_j / m_j,
// W2 = (T_r,i / m_i + T_r,j / m_j) / kappa, mu = m_i m_j / (m_i + m_j) and the tangential factor
// t = (1 + beta) / (1 + mu (1 / (kappa m_i) + 1 / (kappa m_j))) of collide/rough_rule.hpp, a collision of i with j
// changes the kinetic energies of i on average by
//   <dK_tr,i>  = -(mu T_i / m_i) [2 (1 + alpha_ij) + (d - 1) t] + (mu^2 / (2 m_i)) [2 (1 + alpha_ij)^2 V2
//                + (d - 1) t^2 (V2 + W2)],
//   <dK_rot,i> = (d - 1) (mu t / (kappa m_i)) [-T_r,i + mu t (V2 + W2) / 2],
// and dT_i/dt = (2/d) sum_j nu_ij <dK_tr,i>, dT_r,i/dt = (2/d_r) sum_j nu_ij <dK_rot,i>, with nu_ij the
// Maxwellian collision frequency of one i with the j: n_j chi_ij sigma_ij^2 sqrt(8 pi V2) (spheres),
// n_j chi_ij sigma_ij sqrt(2 pi V2) (disks). Two species alike give the monodisperse rates above.

#include "kernel/theory/mixture_hcs.hpp"

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

/// A binary mixture of rough particles: the smooth mixture's parameters (theory/mixture_hcs.hpp; index 0 and 1)
/// and one tangential restitution beta and one reduced moment of inertia kappa for every species and pair.
struct RoughMixture {
  MixtureParameters gas{};
  double beta = -1.0, kappa = 0.4;
};

/// The translational and rotational temperatures of the two species, or their rates of change.
struct RoughTemperatures {
  double translation[2] = {0.0, 0.0};
  double rotation[2] = {0.0, 0.0};
};

/// dT_i/dt and dT_r,i/dt from the collisions, at these temperatures (Maxwellian approximation; rough.hpp above).
RoughTemperatures rough_mixture_collision_rates(const RoughMixture& m, const RoughTemperatures& t) noexcept;

/// A steady (or scaled-steady) state of a rough mixture: T_1 / T_2 of the translational temperatures (species 0
/// over species 1) and theta_i = T_r,i / T_i.
struct RoughMixtureState {
  double temperature_ratio = 1.0;
  double theta[2] = {0.0, 0.0};
};

/// The homogeneous cooling state: the four temperatures decay at one rate. Smooth particles (beta = -1): the
/// smooth mixture's ratio (theory::temperature_ratio_maxwell) and theta = 0. Throws std::runtime_error if it
/// finds no state: near beta = -1 theta grows as 1 / b^2 and the slowest relaxation rate falls as b^2, and the
/// solver is checked to beta = -0.99 (theta up to 10^5; tests/test_rough_theory.cpp). Closer to -1 it may fail
/// (m 1 and 4, sigma 1 and 2, n 1 and 0.2, alpha = 0.8: it finds the state at beta = -0.998, not at -0.999).
RoughMixtureState rough_mixture_hcs(const RoughMixture& m);

/// The steady state under white noise (effects/white_noise.hpp): every particle's velocity kicked with the same
/// strength, a share `rotational_share` epsilon of each particle's power on its spin, so that the noise heats
/// T_i at 2 m_i beta_wn (1 - epsilon) and T_r,i at 2 m_i beta_wn epsilon d / d_r. The ratios do not depend on
/// beta_wn.
RoughMixtureState rough_mixture_white_noise(const RoughMixture& m, double rotational_share);

}  // namespace granmc::theory
