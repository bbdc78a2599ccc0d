#pragma once
// Hard-sphere collision kernel of the Enskog operator (000 eq. 2): a pair (k, l) with direction
// sigma-hat collides at the rate omega_kl = 4 pi sigma_ij^2 n_j chi_ij Theta(g.sigma) |g.sigma|
// (000 sec. 3, step 2). The evaluator gives the velocity-dependent factor; the pair's constant
// prefactor 4 pi sigma_ij^2 n_j chi_ij lives in PairCoefficients.
//
// A time-stepped kernel evaluator has: lambda (omega scales as |g|^lambda, so a physical rate is u^lambda
// times the stored-unit one), rate(g.sigma, |g|^2), bound(U) >= rate for relative speeds up to U, and
// from_scene(scene) (the kernel's parameters; static members where there are none). Every kernel weighs
// sigma-hat by Theta(g.sigma) (g.sigma), so its mean over sigma-hat uniform on the sphere is
// mean_rate(|g|^2) = |g|^lambda / 4 (the mean of Theta(g.sigma) (g.sigma) is |g| / 4), with
// mean_bound(U) >= mean_rate up to U (schemes/collision_stage.hpp accepts a pair with probability
// mean_rate / omega_max). mean_rate takes a double or an xsimd batch of them (the stage screens a batch's
// candidates in SIMD), and screen_candidates says whether that screen can reject any: false when the mean
// rate is a constant, so that every candidate collides.
#include <cmath>

namespace granmc {

struct HardSphere {
  static constexpr double lambda = 1.0;
  static constexpr const char* name = "hard-sphere";
  static constexpr const char* explanation =
      "hard spheres: omega_kl = 4 pi sigma_ij^2 n_j chi_ij Theta(g.sigma) (g.sigma) (000 sec. 3)";
  template <class Scene>
  static constexpr HardSphere from_scene(const Scene&) noexcept {
    return {};
  }
  /// Rate factor for normal relative speed g_sigma = g.sigma-hat > 0.
  static constexpr double rate(double g_sigma, double /*g2*/) noexcept { return g_sigma; }
  static constexpr double bound(double relative_speed) noexcept { return relative_speed; }
  static constexpr bool screen_candidates = true;
  template <class T>
  static T mean_rate(const T& g2) noexcept {
    using std::sqrt;  // xsimd's for a batch
    return 0.25 * sqrt(g2);
  }
  static constexpr double mean_bound(double relative_speed) noexcept { return 0.25 * relative_speed; }
};

}  // namespace granmc
