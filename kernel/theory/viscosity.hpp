#pragma once
// Navier-Stokes shear viscosity of monodisperse smooth inelastic hard spheres, d = 3, Enskog equation,
// first Sonine approximation (003, "First Sonine approximation"; Garzo & Dufty, PRE 59, 5895 (1999) for the
// cooling state, Garzo & Montanero, Physica A 313, 336 (2002) for the Gaussian thermostat), and the reduced
// viscosity eta* of 000 Figs. 10-12. Every collision integral is re-derived exactly in
// docs/methods/derivations/viscosity.md (script docs/methods/derivations/viscosity.py).
//
// In units of eta0 = (5 / (16 sigma^2)) sqrt(m T / pi) (003; elastic dilute, first Sonine) and of
// nu0 = n T / eta0, with c0 = 2 a2 the HCS cumulant (003's c0 is 2 hcs_a2, van Noije-Ernst):
//   nu_eta* = chi (1 - (1 - alpha)^2 / 4)(1 - c0 / 64),  zeta* = (5/12) chi (1 - alpha^2)(1 + 3 c0 / 32),
//   eta^k / eta0 = [1 - (2/5) phi chi (1 + alpha)(1 - 3 alpha)] / (nu_eta* - r zeta*),
//   eta / eta0 = eta^k / eta0 [1 + (4/5) phi chi (1 + alpha)] + (384 / (25 pi)) phi^2 chi (1 + alpha)(1 - c0/32),
// r = 1/2 for the cooling state and 1 for the Gaussian thermostat alone (ViscosityReference).

namespace granmc::theory {

/// The homogeneous state the shear flow perturbs. Only the term that the time dependence of the cooling
/// state, or the thermostat, adds to the P_xy balance differs: -(zeta/2) P_xy or -zeta P_xy.
enum class ViscosityReference {
  /// Homogeneous cooling state (Garzo-Dufty 1999; 000 Fig. 6 curve a). Also 003's modified shear flow
  /// (Gaussian thermostat plus BGK-like relaxation to f^(0)), built to reproduce exactly this coefficient.
  cooling,
  /// Heated steady state of 000 (Gaussian thermostat, 000 eqs. 8-9, 16, with uniform shear, eq. 11;
  /// Garzo-Montanero 2002; 000 Fig. 6 curve b).
  gaussian_thermostat,
};

struct ShearViscosity {
  double nu_eta = 1.0;   // nu_eta* (reduced by nu0 = n T / eta0)
  double zeta = 0.0;     // zeta*, the first-Sonine cooling rate in the same units
  double kinetic = 1.0;  // eta^k / eta0
  double total = 1.0;    // eta / eta0 = (eta^k + eta^c) / eta0
};

/// eta0 = (5 / (16 sigma^2)) sqrt(m T / pi) (003).
double elastic_dilute_viscosity(double mass, double diameter, double temperature) noexcept;

/// First-Sonine eta^k and eta at restitution alpha, packing fraction phi = pi n sigma^3 / 6 (disks pi n sigma^2 /
/// 4) and contact value chi (phi = 0, chi = 1: the dilute Boltzmann gas). c0 = 2 hcs_a2(alpha, d). Disks
/// (dimension 2): eta0 = ((d + 2) / 8) Gamma(d / 2) pi^(-(d - 1) / 2) sigma^(1 - d) sqrt(m T) = (1 / (2 sigma))
/// sqrt(m T / pi), and the d-dimensional forms of the terms above (Brey, Dufty, Kim and Santos, PRE 58, 4638
/// (1998) dilute; Garzo and Montanero, Physica A 313, 336 (2002) dense; docs/methods/derivations/viscosity.md,
/// "Disks"):
///   nu_eta* = (3 / (4 d)) chi (1 - alpha + 2 d / 3)(1 + alpha)(1 - c0 / 64),
///   zeta* = ((d + 2) / (4 d)) chi (1 - alpha^2)(1 + 3 c0 / 32),
///   eta^k / eta0 = [1 - (2^(d-2) / (d + 2)) phi chi (1 + alpha)(1 - 3 alpha)] / (nu_eta* - r zeta*),
///   eta / eta0 = eta^k / eta0 [1 + (2^(d-1) / (d + 2)) phi chi (1 + alpha)]
///                + (d / (d + 2)) (2^(2d+1) / (pi (d + 2))) phi^2 chi (1 + alpha)(1 - c0 / 32).
ShearViscosity shear_viscosity(double alpha, double phi, double chi, ViscosityReference reference,
                               int dimension = 3) noexcept;

/// The same with chi of Carnahan-Starling (003; 000 eq. 3 for one species, granmc::enskog_chi), or Henderson's
/// for disks (granmc::enskog_chi_disks).
ShearViscosity shear_viscosity(double alpha, double phi, ViscosityReference reference, int dimension = 3);

/// 000 Figs. 10-12: eta* = nu eta / (n T), nu = sqrt(pi) n sigma_12^2 v0; for one species sigma_12 = sigma,
/// v0 = sqrt(2 T / m), so eta* = (5 sqrt(2) / 16) eta / eta0. Disks: nu = (sqrt(pi) / 2) n sigma v0
/// (observe/pressure_tensor.hpp) and eta0 of d = 2, so eta* = (4 sqrt(2) / 16) eta / eta0; in d dimensions
/// nu0 / nu = 16 / ((d + 2) sqrt 2).
double reduced_viscosity_one_species(double eta_over_eta0, int dimension = 3) noexcept;

/// Mixture normalisation of 000 Figs. 10-12: eta* = sqrt(pi) sigma_12^2 v0 eta / T, with v0 of 000 eq. (7)
/// (mixture_thermal_speed). For identical species v0 = sqrt(4 T / m), sqrt(2) times the one-species v0.
double reduced_viscosity(double eta, double temperature, double sigma_12, double v0) noexcept;

/// v0 = sqrt(2 T (m_1 + m_2) / (m_1 m_2)) (000 eq. 7).
double mixture_thermal_speed(double temperature, double mass_1, double mass_2) noexcept;

}  // namespace granmc::theory
