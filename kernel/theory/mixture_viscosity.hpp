#pragma once
// Navier-Stokes shear viscosity of a binary mixture of smooth inelastic hard spheres, d = 3, Enskog equation with
// uniform chi_ij, first Sonine approximation around the HCS (or the Gaussian-thermostat HSS) with unequal partial
// temperatures: the theory behind 000 Figs. 7-12 (000 refs. [7], [8]: Montanero & Garzo, PRE 67, 021308 (2003);
// Garzo & Montanero, PRE 68, 041302 (2003)). Derived here from the Enskog equation, not transcribed:
// docs/methods/derivations/viscosity.md, "Binary mixtures" (every coefficient exact, checked by independent
// quadrature; identical species give kernel/theory/viscosity.hpp exactly; elastic limits give
// Hirschfelder-Curtiss-Bird's dilute mixture and Thorne's Enskog mixture).
//
// Species i: f_i^(0) = n_i phi_i [1 + a2_i S2] at its own T_i (mixture_hcs.hpp), f_i^(1) the first-Sonine shear
// perturbation -(m_i eta_i^k / (n_i T_i^2)) phi_i n_i D(V):grad u. eta_i^k solve the 2x2 system
//   sum_j (tau_ij - r zeta delta_ij) eta_j^k = n_i T_i Y_i,       r = 1/2 cooling state, 1 Gaussian thermostat,
// and eta = sum_i eta_i^k (1 + (4 pi/15) sum_j n_j mu_ji (1 + alpha_ij) sigma_ij^3 chi_ij) + eta^c0.
#include "kernel/theory/mixture_hcs.hpp"
#include "kernel/theory/viscosity.hpp"

namespace granmc::theory {

struct MixtureShearViscosity {
  double partial[2] = {0.0, 0.0};  // eta_i^k, kinetic part carried by species i
  double kinetic = 0.0;            // eta^k = eta_1^k + eta_2^k (000 Fig. 10)
  double transfer = 0.0;           // collisional transfer of f^(1)
  double gradient = 0.0;  // collisional transfer across the velocity gradient by f^(0) (3/5 kappa when elastic)
  double total = 0.0;     // eta = kinetic + transfer + gradient (000 eq. 11, Figs. 7-9, 11-12)
};

/// eta at mixture temperature T = x_1 T_1 + x_2 T_2 (x_i = n_i / n), in the units of mp.
/// mp: masses, diameters, alpha_ij, chi_ij; its densities n_i set the composition (the viscosity does not depend
/// on their scale). The Enskog terms use the density of the packing fraction phi,
/// n = 6 phi / (pi sum_k x_k sigma_k^3) (phi = 0: Boltzmann gas); chi_ij should be those of phi
/// (mixture_from_ratios). state: gamma = T_1/T_2 and the a2_i (mixture_first_sonine, or the Maxwellian state
/// {temperature_ratio_maxwell, {0, 0}}); zeta is species 0's partial cooling rate (equal to species 1's there).
MixtureShearViscosity mixture_shear_viscosity(const MixtureParameters& mp, double phi, const MixtureSonine& state,
                                              double temperature, ViscosityReference reference) noexcept;

/// 000 sec. 4 quantities for mu = m_1/m_2, omega = sigma_1/sigma_2, delta = n_1/n_2, common alpha, packing
/// fraction phi (chi_ij Carnahan-Starling), first-Sonine state: eta(alpha)/eta(1) of the same mixture at the same
/// phi (000 Figs. 7-9) and eta^k*, eta* = sqrt(pi) n sigma_12^2 v0 eta / (n T) (000 Figs. 10-12).
struct MixtureViscosityRatios {
  double over_elastic = 1.0;
  double kinetic_star = 0.0;
  double star = 0.0;
};
MixtureViscosityRatios mixture_viscosity_from_ratios(double mu, double omega, double delta, double alpha, double phi,
                                                     ViscosityReference reference);

}  // namespace granmc::theory
