#pragma once
// Homogeneous cooling state (HCS) of a binary mixture of smooth inelastic hard spheres, d = 3, or disks, d = 2, Enskog
// equation with uniform chi_ij (000 eqs. 1-2 with a = 0; Garzo & Dufty, PRE 60, 5706 (1999) for the dilute
// case). In a homogeneous state chi_ij only multiplies the i-j collision rate, so the Enskog results are the
// Boltzmann ones with sigma_ij^2 -> sigma_ij^2 chi_ij. The results hold unchanged for the Gaussian-thermostat
// steady state (HSS), 000 sec. 2.
//
// Species i (index 0 or 1) has f_i = n_i phi_i(v) [1 + a2_i S2(m_i v^2 / (2 T_i))], phi_i the Maxwellian at its
// own temperature T_i, S2(x) = x^2/2 - (d+2)x/2 + d(d+2)/8, so <v^4>_i = d(d+2) (T_i/m_i)^2 (1 + a2_i); the cumulant
// c_i of 000 eqs. 19-20 and Fig. 1 is 2 a2_i. gamma = T_1/T_2 (species 0 over species 1).
//
// Collisional moments, exact and closed-form (no quadrature): for the pair (i, j), with theta_i = T_i/m_i,
// s^2 = theta_i + theta_j, u = theta_i / s^2, b = mu_ji (1 + alpha_ij), mu_ji = m_j / (m_i + m_j),
//   (1/n_i) int dv v^p J_ij = n_j sigma_ij^(d-1) chi_ij (|S^(d-1)| / (2 pi)) sqrt(2 pi) s^(p+1) P_p(u, b; a2_i, a2_j),
// p = 2, 4 (the factor 2 sqrt(2 pi) for spheres, sqrt(2 pi) for disks), P_p exactly bilinear in (a2_i, a2_j) with
// polynomial coefficients (mixture_hcs.cpp; P_2 the same in both dimensions). Derived symbolically with
// decorrelated pair coordinates and checked against independent quadrature (spheres) and Monte Carlo:
// docs/methods/derivations/mixture-hcs.md, docs/methods/derivations/mixture_hcs.py [--dimension 2].

namespace granmc::theory {

/// Mechanical parameters of the two species (index 0, 1). chi = 1 for the dilute (Boltzmann) gas. Only
/// ratios matter for gamma and a2_i; the overall density and size scales only set the time scale.
struct MixtureParameters {
  double mass[2], diameter[2], density[2];
  double alpha[2][2];  // restitution alpha_ij (symmetric)
  double chi[2][2];    // pair correlation at contact chi_ij (symmetric)
  /// 3 spheres, 2 disks (docs/methods/derivations/mixture-hcs.md, "Disks").
  int dimension = 3;
};

/// Parameters from the dimensionless set of 000 sec. 4: mu = m_1/m_2, omega = sigma_1/sigma_2,
/// delta = n_1/n_2, a common alpha, and chi_ij of Carnahan-Starling (000 eq. 3, granmc::enskog_chi) at
/// packing fraction phi (phi = 0: dilute, chi = 1). Species 1 of the paper is index 0: mass {mu, 1},
/// diameter {omega, 1}, density {delta, 1}.
MixtureParameters mixture_from_ratios(double mu, double omega, double delta, double alpha, double phi = 0.0);

/// (1/n_i) int dv v^p J_ij[f_i, f_j] for p = 2 or 4: the rate of change of n_i <v^p>_i / n_i due to
/// collisions with species j, exact for the first-Sonine f_i, f_j above (bilinear in a2_1, a2_2).
/// T1, T2, a2_1, a2_2 are those of species 0 and 1.
double collisional_moment(const MixtureParameters& mp, int i, int j, int p, double T1, double T2, double a2_1,
                          double a2_2) noexcept;

/// Partial cooling rate zeta_i (dT_i/dt = -zeta_i T_i from collisions), to first order in a2_1, a2_2:
///   zeta_i = -(m_i / (d T_i)) sum_j (1/n_i) int dv v^2 J_ij
/// with the a2_i a2_j term of P_2 dropped. For a2 = 0 and spheres this is the Maxwellian rate
///   zeta_i = (8 sqrt(2 pi)/3) sum_j n_j sigma_ij^2 chi_ij m_ij (1 + alpha_ij) s_ij^3 / T_i
///            [(T_i - T_j)/((m_i + m_j) s_ij^2) + mu_ji (1 - alpha_ij)/2],   m_ij = m_i m_j / (m_i + m_j).
double partial_cooling_rate(const MixtureParameters& mp, int i, double T1, double T2, double a2_1,
                            double a2_2) noexcept;

/// Maxwellian approximation: gamma = T_1/T_2 solving zeta_1 = zeta_2 with a2 = 0. Bracketing and bisection
/// on log gamma (any mass ratio; NaN only if no sign change within |log gamma| < 100).
double temperature_ratio_maxwell(const MixtureParameters& mp);

/// Linear first-Sonine approximation: (gamma, a2_1, a2_2) solving together
///   zeta_1 = zeta_2                     (cooling rates to first order in a2),
///   E_i = 0, i = 0, 1                   (fourth moments stationary in the HCS scaling: d<v^4>_i/dt =
///                                        -2 zeta_i <v^4>_i, linearised in a2),
///   E_i = sum_j n_j sigma_ij^(d-1) chi_ij s_ij^5 [P_4^ij - 2 (d + 2) u_ij (1 + a2_i) P_2^ij].
/// For each trial gamma the E_i are a 2x2 linear system for (a2_1, a2_2); the root in gamma nearest to the
/// Maxwellian one is bracketed on log gamma and bisected. Mechanically identical species give gamma = 1 and
/// a2_i = hcs_a2(alpha, d) (van Noije-Ernst). The linearised theory breaks down (|a2| >> 1) for a heavy, dilute,
/// strongly inelastic species (e.g. m_1/m_2 = 1000, n_1/n_2 = 1e-3, alpha = 0): see the derivation note.
struct MixtureSonine {
  double gamma, a2[2];
};
MixtureSonine mixture_first_sonine(const MixtureParameters& mp);

}  // namespace granmc::theory
