#pragma once
// Hard-sphere collision kernel of the Enskog operator (000 eq. 2): a pair (k, l) with direction
// sigma-hat collides at the rate omega_kl = 4 pi sigma_ij^2 n_j chi_ij Theta(g.sigma) |g.sigma|
// (000 sec. 3, step 2). The evaluator gives the velocity-dependent factor; the pair's constant
// prefactor 4 pi sigma_ij^2 n_j chi_ij lives in PairCoefficients.
namespace granmc {

struct HardSphere {
  /// Rate factor for normal relative speed g_sigma = g.sigma-hat > 0.
  static constexpr double rate(double g_sigma) noexcept { return g_sigma; }
};

}  // namespace granmc
