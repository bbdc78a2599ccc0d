#pragma once
// First-Sonine predictions for monodisperse inelastic hard spheres (d = 3) and hard disks (d = 2): the
// kurtosis cumulant a2 of the homogeneous cooling state and of the white-noise heated steady state (van Noije
// and Ernst, Granular Matter 1 (1998) 57, linearised in a2, for any d), and the cooling rate with its Sonine
// correction.
// Formulas and their model error: docs/methods/physics.md.

namespace granmc::theory {

/// a2 of the homogeneous cooling state: 16 (1 - alpha)(1 - 2 alpha^2) / (9 + 24 d - alpha (41 - 8 d)
/// + 30 (1 - alpha) alpha^2), a2 = d/(d+2) <V^4>/<V^2>^2 - 1.
double hcs_a2(double alpha, int dimension = 3) noexcept;

/// a2 of the white-noise driven steady state: 16 (1 - alpha)(1 - 2 alpha^2) / (73 + 56 d
/// - 3 alpha (35 + 8 d) + 30 (1 - alpha) alpha^2).
double white_noise_a2(double alpha, int dimension = 3) noexcept;

/// The collision frequency of a monodisperse Maxwellian gas, nu = (2 pi^((d-1)/2) / Gamma(d/2)) n sigma^(d-1)
/// chi sqrt(T / m): 4 sqrt(pi) n sigma^2 chi sqrt(T / m) for spheres, 2 sqrt(pi) n sigma chi sqrt(T / m) for
/// disks (T = m <V^2> / d).
double collision_frequency(double density, double diameter, double mass, double temperature, double chi,
                           int dimension = 3) noexcept;

/// Cooling rate zeta (dT/dt = -zeta T) of a monodisperse hard-sphere gas (000 eq. 6 evaluated with the
/// first Sonine distribution): zeta = (nu / d)(1 - alpha^2)(1 + 3 a2 / 16), nu the collision frequency above:
/// (4 sqrt(pi) / 3) n sigma^2 chi (1 - alpha^2) sqrt(T / m) (1 + 3 a2 / 16) for spheres, sqrt(pi) n sigma chi
/// (1 - alpha^2) sqrt(T / m) (1 + 3 a2 / 16) for disks.
double cooling_rate(double alpha, double density, double diameter, double mass, double temperature, double chi,
                    double a2, int dimension = 3) noexcept;

/// The steady temperature of a monodisperse hard-core gas heated by white noise (effects/white_noise.hpp, on
/// translation): the heating dT/dt = 2 beta m balances the cooling zeta(T) T, and zeta ~ sqrt(T), so
/// T = (2 beta m / zeta(T = 1))^(2/3) with zeta of cooling_rate at the given a2 (0: the Maxwellian closure).
double white_noise_temperature(double alpha, double density, double diameter, double mass, double chi, double beta,
                               double a2, int dimension = 3) noexcept;

/// Haff's law: T(t) = T0 / (1 + zeta0 t / 2)^2, with zeta0 the cooling rate at T0 (zeta ~ sqrt(T)).
double haff_temperature(double t, double temperature0, double cooling_rate0) noexcept;

}  // namespace granmc::theory
