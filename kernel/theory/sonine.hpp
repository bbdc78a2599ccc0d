#pragma once
// First-Sonine predictions for monodisperse inelastic hard spheres in d = 3: the kurtosis cumulant a2 of
// the homogeneous cooling state and of the white-noise heated steady state (van Noije and Ernst,
// Granular Matter 1 (1998) 57, linearised in a2), and the cooling rate with its Sonine correction.
// Formulas and their model error: docs/physics.md.

namespace granmc::theory {

/// a2 of the homogeneous cooling state: 16 (1 - alpha)(1 - 2 alpha^2) / (9 + 24 d - alpha (41 - 8 d)
/// + 30 (1 - alpha) alpha^2), d = 3.
double hcs_a2(double alpha) noexcept;

/// a2 of the white-noise driven steady state: 16 (1 - alpha)(1 - 2 alpha^2) / (73 + 56 d
/// - 3 alpha (35 + 8 d) + 30 (1 - alpha) alpha^2), d = 3.
double white_noise_a2(double alpha) noexcept;

/// Cooling rate zeta (dT/dt = -zeta T) of a monodisperse hard-sphere gas (000 eq. 6 evaluated with the
/// first Sonine distribution): zeta = (4 sqrt(pi) / 3) n sigma^2 chi (1 - alpha^2) sqrt(T / m) (1 + 3 a2 / 16).
double cooling_rate(double alpha, double density, double diameter, double mass, double temperature, double chi,
                    double a2) noexcept;

/// Haff's law: T(t) = T0 / (1 + zeta0 t / 2)^2, with zeta0 the cooling rate at T0 (zeta ~ sqrt(T)).
double haff_temperature(double t, double temperature0, double cooling_rate0) noexcept;

}  // namespace granmc::theory
