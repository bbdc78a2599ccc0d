#pragma once
// Beyond-linear Sonine estimates of the homogeneous cooling state (HCS), and of the white-noise heated state,
// of smooth inelastic hard spheres, d = 3, or hard disks, d = 2 (`dimension`; the disks' forms in
// docs/methods/derivations/sonine-hcs.md, "Hard disks"), constant restitution alpha, Boltzmann equation.  For spheres
// the scaled distribution is
//   F(c) = phi(c) [1 + a2 S2(c^2) + a3 S3(c^2)],  c = v / v0,  v0 = sqrt(2T/m),  phi = pi^-3/2 exp(-c^2),
//   S2(x) = x^2/2 - 5x/2 + 15/8,  S3(x) = -x^3/6 + 7x^2/4 - 35x/8 + 35/16   (Laguerre L^(1/2)_p),
// so <c^4> = (15/4)(1 + a2), <c^6> = (105/8)(1 + 3 a2 - a3).
// Collisional moments mu_p = -int dc c^p I[F,F]; stationarity of F gives mu_p = (p/3) mu_2 <c^p>.
// The moments below are EXACT for this F (polynomials of degree 2 in a2, a3, rational in alpha); they were
// derived symbolically and checked against independent quadrature: docs/methods/derivations/sonine-hcs.md and
// docs/methods/derivations/sonine_hcs.py.  The plain linear first-Sonine a2 (van Noije & Ernst) is
// granmc::theory::hcs_a2 in kernel/theory/sonine.hpp.

namespace granmc::theory {

/// Collisional moments mu_2, mu_4, mu_6 of F = phi (1 + a2 S2 + a3 S3) in units of sqrt(2 pi), exact in
/// a2 and a3 (no truncation).  mu_2 / sqrt(2 pi) = (1 - alpha^2)(1 + 3 a2/16 + a3/64 + 9 a2^2/1024
/// + 15 a2 a3/2048 + 35 a3^2/16384); mu_4 and mu_6: sonine_hcs.cpp and the derivation note.
struct SonineMoments {
  double mu2, mu4, mu6;
};
SonineMoments hcs_collisional_moments(double alpha, double a2, double a3, int dimension = 3) noexcept;

/// Approximation 1 ("nonlinear first Sonine", in the spirit of Brilliantov & Poschel, PRE 61, 2809 (2000)):
/// a3 = 0 and the p = 4 HCS equation mu_4(a2) = 5 mu_2(a2) (1 + a2) kept exactly, a cubic in a2; returns
/// its root continuously connected to a2 = 0 at alpha = 1 (the other two real roots, below -23 and above +2.2, are
/// unphysical). Solved by Newton from the linear (van Noije-Ernst) value; 0 <= alpha <= 1.
double hcs_a2_nonlinear(double alpha, int dimension = 3) noexcept;

/// Approximation 2, LINEAR second Sonine (Brilliantov & Poschel, EPL 74, 424 (2006); Santos & Montanero,
/// Granular Matter 11, 157 (2009)): a3 kept, the p = 4 and p = 6 HCS equations linearised in (a2, a3)
/// (every product a2^2, a2 a3, a3^2, including those from mu_2 <c^p>, dropped), solved exactly:
///   a2 = 16 (1 - alpha) N2(alpha) / D(alpha),  a3 = 128 (1 - alpha) N3(alpha) / D(alpha)
/// with the polynomials given in sonine_hcs.cpp.  Coefficients of our own derivation (not transcribed).
struct SecondSonine {
  double a2, a3;
};
SecondSonine hcs_second_sonine(double alpha, int dimension = 3) noexcept;

/// The steady states whose a2, a3 the second Sonine approximation gives: the homogeneous cooling state, and
/// the state heated by white noise (df/dt = (xi / 2) Lap_v f + J[f, f]; van Noije and Ernst, Granular Matter 1
/// (1998) 57, to first order), which share the collisional moments and differ in the conditions
/// (docs/methods/derivations/sonine-hcs.md, "White noise").
enum class SonineState { cooling, white_noise };

/// Linear second Sonine of either state: the p = 4 and p = 6 conditions linearised in (a2, a3), their
/// coefficients taken from the exact moments, solved by Cramer's rule. For the cooling state the same as
/// hcs_second_sonine's closed form to rounding; for white noise, dropping a3 leaves van Noije and Ernst's
/// white_noise_a2 (tests/test_sonine_hcs.cpp).
SecondSonine second_sonine_linear(double alpha, SonineState state, int dimension = 3) noexcept;

/// Nonlinear second Sonine: both conditions (p = 4, 6) kept exactly for F = phi (1 + a2 S2 + a3 S3); Newton
/// in (a2, a3) from the linear solution. For the cooling state it differs from hcs_second_sonine by < 1e-5 in
/// a2 for alpha >= 0.6 (docs/methods/derivations/sonine-hcs.md).
SecondSonine second_sonine_nonlinear(double alpha, SonineState state, int dimension = 3) noexcept;

/// mu_2(a2, a3) / mu_2(0, 0) = zeta* / zeta*_Maxwell = 1 + 3 a2/16 + a3/64 + 9 a2^2/1024 + 15 a2 a3/2048
/// + 35 a3^2/16384 (exact for the two-term Sonine F; independent of alpha, and the same for disks).  The first-order
/// factor used by theory::cooling_rate is 1 + 3 a2/16.
double hcs_cooling_rate_factor(double a2, double a3) noexcept;

/// Model error of the first-Sonine a2 (theory::hcs_a2): its shift to the second-Sonine value,
/// |hcs_second_sonine(alpha).a2 - hcs_a2(alpha)|, dominated by the neglected a3 (docs/methods/physics.md).
double hcs_a2_model_error(double alpha, int dimension = 3) noexcept;

/// The same for white noise: |second_sonine_linear(alpha, white_noise).a2 - white_noise_a2(alpha)|.
double white_noise_a2_model_error(double alpha, int dimension = 3) noexcept;

}  // namespace granmc::theory
