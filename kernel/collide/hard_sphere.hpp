#pragma once
// Hard spheres, in both forms of collide/collision_kernel.hpp.
//  - Time-stepped (the Enskog operator, 000 eq. 2): a pair (k, l) with direction sigma-hat collides at the rate
//    omega_kl = 4 pi sigma_ij^2 n_j chi_ij Theta(g.sigma) |g.sigma| (000 sec. 3, step 2). The evaluator gives
//    the velocity-dependent factor; the pair's constant prefactor 4 pi sigma_ij^2 n_j chi_ij lives in
//    PairCoefficients.
//  - Event (001 eq. 6): B = rate |u|, e uniform; a candidate is kept with probability |u| / U_max, the test
//    u < |u| / U_max needing no transformation of u.
#include <cmath>
#include <cstddef>
#include <span>

#include "kernel/collide/collision_kernel.hpp"

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

  static constexpr bool constant_rate = false;
  template <std::size_t N>
  static void acceptance_thresholds(std::span<double, N>) noexcept {}  // u^(1 / 1) = u
};

static_assert(SteppedKernel<HardSphere> && EventKernel<HardSphere>);

}  // namespace granmc
