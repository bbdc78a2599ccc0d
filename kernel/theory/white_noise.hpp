#pragma once
// Theory of the uniformly heated gas of 001 (df/dt - beta Lap_v f = gamma Q_alpha(f), unit mass) with the
// kernel B = rate |u|^lambda, rate = gamma C_lambda, e uniform on the sphere, in d = 3 or, with e uniform on
// the circle, d = 2 (hard disks scatter by their own law instead, collide/impact_direction.hpp). Every
// pair collides at |S^(d-1)| rate |u|^lambda: 4 pi rate |u|^lambda for spheres, 2 pi for disks.
// Derivations: docs/methods/physics.md.
#include "kernel/theory/sonine_hcs.hpp"

namespace granmc::theory {

/// Decay rate of T for Maxwell pseudomolecules: kappa = |S^(d-1)| rate (1 - alpha^2) / 4, pi rate (1 - alpha^2)
/// for spheres (001 eq. 16, gamma C_0 = rate), pi/2 rate (1 - alpha^2) for disks.
double maxwell_relaxation_rate(double rate, double alpha, int dimension = 3) noexcept;

/// Exact Maxwell relaxation (001 eqs. 16-17): T(t) = T0 e^{-kappa t} + T_inf (1 - e^{-kappa t}),
/// T_inf = 2 beta / kappa.
double maxwell_temperature(double t, double temperature0, double beta, double rate, double alpha,
                           int dimension = 3) noexcept;

/// The expected bulk-subtracted temperature of the n-particle system of 001 sec. 4 with a Maxwell kernel:
/// exactly (1 - 1/n) T(t), with T(t) the Boltzmann solution above (docs/methods/physics.md derives it; the
/// noise feeds the bulk velocity a share 1/n of the heating, and the initial sample loses 1/n to its mean).
double maxwell_temperature_particles(double t, double temperature0, double beta, double rate, double alpha,
                                     double particles, int dimension = 3) noexcept;

/// The expected temperature of the same system without removing the bulk velocity V, (1/d) m <|v|^2>
/// (001's estimator, eq. 35): (1 - 1/n) T(t) + m |V|^2 / d with E[m |V(t)|^2 / d] = (T(0) + 2 m beta t) / n
/// when the initial sample keeps its mean (001 step 1.2; zero_momentum false) and 2 m beta t / n when it
/// is removed: collisions keep V, and the noise moves it as the mean of n independent Brownian paths
/// (docs/methods/physics.md, "001's temperature estimator").
double maxwell_temperature_uncentred(double t, double temperature0, double beta, double rate, double alpha,
                                     double particles, double mass, bool zero_momentum, int dimension = 3) noexcept;

/// The same with the time-stepped scheme's first-order splitting (collisions, then the noise of the whole
/// step, effects/white_noise.hpp), at t = k dt: T_{k+1} = e^{-kappa dt} T_k + 2 beta dt, i.e.
/// T_k = T_dt + (T0 - T_dt) e^{-kappa t}, T_dt = 2 beta dt / (1 - e^{-kappa dt}); times (1 - 1/n) for n
/// particles. The steady state is too hot by T_dt / T_inf - 1 = kappa dt / 2 + O(dt^2) (docs/methods/physics.md).
/// e^{-kappa dt} is the limit of many particles: with M whole collisions per step the exact factor is
/// (1 - (1 - alpha^2) / (2 (n - 1)))^M, the same to O(1/n) (tests/test_white_noise.cpp).
double maxwell_temperature_splitting(double t, double dt, double temperature0, double beta, double rate, double alpha,
                                     double particles, int dimension = 3) noexcept;

/// The exact steady a2 of Maxwell pseudomolecules heated by white noise in d dimensions
/// (docs/methods/derivations/maxwell-white-noise-a2.md):
///   a2 = 2 (d + 1) (1 - alpha)^2 (1 + alpha) / (19 d - 5 - (11 d + 3) alpha + (d + 1) (alpha^2 - alpha^3)),
/// independent of rate and beta: 2 (1 - alpha)^2 (1 + alpha) / (13 - 9 alpha + alpha^2 - alpha^3) for spheres
/// (alpha = 1/2: 2/23 = 0.0870), 6 (1 - alpha)^2 (1 + alpha) / (33 - 25 alpha + 3 alpha^2 - 3 alpha^3) for disks
/// (alpha = 1/2: 18/167 = 0.1078).
double maxwell_white_noise_a2(double alpha, int dimension = 3) noexcept;

/// The first-Sonine steady a2 of the kernel B = rate |u|^lambda with e uniform on the sphere (circle for disks)
/// heated by white noise (docs/methods/derivations/vhs-white-noise-a2.md): 16 (1 - alpha) N / D, rational in alpha,
/// lambda and d. Exact for lambda = 0 (maxwell_white_noise_a2); lambda = 1, d = 3 is van Noije and Ernst's
/// hard-sphere a2 (white_noise_a2 of theory/sonine.hpp); for VHS disks and spheres in between. Not for hard
/// disks, which do not scatter e uniformly (white_noise_a2 with d = 2).
double isotropic_white_noise_a2(double alpha, double lambda, int dimension = 3) noexcept;

/// The second-Sonine steady (a2, a3) of the same kernels, F = phi (1 + a2 S2 + a3 S3), linear in (a2, a3) as
/// second_sonine_linear does it for hard cores (docs/methods/derivations/vhs-white-noise-a2.md, "Second Sonine"): the
/// pair averages of the fourth and sixth moments' changes, weighted by |u|^lambda, evaluated term by term. lambda = 1,
/// d = 3 is the hard spheres' second_sonine_linear(alpha, SonineState::white_noise); lambda = 0 keeps the exact a2
/// of maxwell_white_noise_a2. |a2 - isotropic_white_noise_a2| is the first Sonine's truncation error (0.00126 for VHS
/// disks, lambda = 1/2, alpha = 1/2).
SecondSonine isotropic_white_noise_second_sonine(double alpha, double lambda, int dimension = 3);

/// <|u|^p> over pairs of independent Maxwellian unit-mass particles at temperature T in d dimensions:
/// (4 T)^{p/2} Gamma((d + p)/2) / Gamma(d/2).
double maxwellian_relative_speed_moment(double p, double temperature, int dimension = 3) noexcept;

/// Steady white-noise temperature from the energy balance
///   2 beta = |S^(d-1)| rate (1 - alpha^2) <1 - mu> <|u|^{2+lambda}> / (8 d)
/// (001 eq. 15 for d = 3: (1 - alpha^2)/24 4 pi rate <|u|^{2+lambda}>), <1 - mu> = 1 for e uniform and 4/3 for
/// hard disks (tests/test_collision_rule.cpp, HardDiskScattering), with a Maxwellian closure, times the first-Sonine
/// factor (1 + lambda (lambda + 2) a2 / 16) of <|u|^{2+lambda}> (3/16 for hard cores; pass a2 = 0 for the closure
/// alone). Exact for lambda = 0 (2 beta / kappa).
double white_noise_steady_temperature(double lambda, double rate, double alpha, double beta, double a2,
                                      int dimension = 3) noexcept;

/// High-velocity tail exponent b of f ~ exp(-a |v|^b) (001 eqs. 19-21): b = 1 + lambda / 2.
double tail_exponent(double lambda) noexcept;

/// The same in the freely cooling (homogeneous cooling) state, f(c) ~ exp(-a c^b) in the scaled speed c:
/// b = lambda (hard spheres b = 1: van Noije and Ernst, Granular Matter 1 (1998) 57; lambda in (0, 1]:
/// Ernst, Trizac and Barrat, J. Stat. Phys. 124 (2006) 549). Maxwell pseudomolecules (lambda = 0) have an
/// algebraic tail instead.
double free_cooling_tail_exponent(double lambda) noexcept;

}  // namespace granmc::theory
