#pragma once
// The steady uniform shear flow of a dilute gas of smooth inelastic hard spheres without a thermostat (000
// sec. 5): viscous heating balances the collisional cooling, so the reduced shear rate a* is fixed by alpha
// and the rheology is nonlinear. Grad's 13-moment solution of the Boltzmann equation (Santos, Garzo and
// Dufty, Phys. Rev. E 69, 061303 (2004); Montanero, Garzo, Santos and Brey, J. Fluid Mech. 389, 391 (1999)).
//
// With the pressure tensor P reduced by p = n T and the rates by nu0 = n T / eta0 (theory/viscosity.hpp),
// the collisional moment of a Grad distribution is Lambda_ij = nu0 [beta (P_ij - p delta_ij) + zeta* p delta_ij],
// beta and zeta* the first-Sonine nu_eta* and zeta* of a Maxwellian (c0 = 0) in d dimensions,
//   beta = (3 / (4 d)) (1 - alpha + 2 d / 3)(1 + alpha),  zeta* = ((d + 2) / (4 d)) (1 - alpha^2)
// ((1 + alpha)(3 - alpha) / 4 and (5/12)(1 - alpha^2) for spheres, (1 + alpha)(7 - 3 alpha) / 8 and
// (1 - alpha^2) / 2 for disks; docs/methods/derivations/viscosity.md, "Disks"). The steady moment equations
// dP_ij/dt + a_ik P_kj + a_jk P_ki + Lambda_ij = 0 give
//   P_yy = P_zz = p (1 - zeta*/beta),  P_xx = p (1 + (d - 1) zeta*/beta),  P_xy = -a* P_yy / beta,
//   and, from the trace (energy balance), a*^2 = (d/2) zeta* beta^2 / (beta - zeta*), eta/eta0 = (beta - zeta*)/beta^2.

namespace granmc::theory {

struct SteadyShearFlow {
  int dimension = 3;             // 3 spheres, 2 disks
  double shear_rate_nu0 = 0.0;   // a / nu0, nu0 = n T / eta0 = (16/5) n sigma^2 sqrt(pi T / m) (disks 2 n sigma ...)
  double shear_rate_star = 0.0;  // a* = a / nu, nu = sqrt(pi) n sigma^2 sqrt(2 T / m): granmc's a* (000 Fig. 10;
                                 // disks observe/pressure_tensor.hpp's nu = (sqrt(pi) / 2) n sigma sqrt(2 T / m))
  double eta_over_eta0 = 1.0;    // eta = -P_xy / a, by eta0 of the same temperature
  double eta_star = 0.0;         // eta* = nu eta / (n T) (000 Figs. 10-12)
  double pressure_xx = 1.0;      // P_xx / p
  double pressure_yy = 1.0;      // P_yy / p = P_zz / p
  double pressure_xy = 0.0;      // P_xy / p
};

/// Grad's solution at restitution alpha in (0, 1], spheres (dimension 3) or disks (2); alpha = 1 gives the
/// equilibrium limit a* = 0, eta = eta0.
SteadyShearFlow steady_shear_grad(double alpha, int dimension = 3) noexcept;

/// The steady temperature that a dilute gas sheared at rate a reaches: a / nu0(T) = shear_rate_nu0 (density per
/// area for disks).
double steady_shear_temperature(const SteadyShearFlow& s, double shear_rate, double density, double diameter,
                                double mass) noexcept;

}  // namespace granmc::theory
