#pragma once
// Variable hard spheres (001 eq. 8, B = rate |u|^lambda, 0 < lambda < 1, e uniform on the sphere; on the
// circle for d = 2), in both forms of collide/collision_kernel.hpp.
//  - Event: a candidate is kept with probability (|u| / U_max)^lambda (001 eq. 26), tested as
//    u^(1 / lambda) < |u| / U_max.
//  - Time-stepped, in the impact-direction form: omega_kl = prefactor Theta(g.sigma) (g.sigma / |g|)^(d - 2)
//    |g|^lambda. As for Maxwell pseudomolecules (collide/maxwell_pseudomolecules.hpp), the isotropic law
//    makes the scattering direction uniform, and the mean over sigma-hat, prefactor |g|^lambda / 4
//    (spheres) or / 2 (disks), with prefactor = |S^(d-1)| rate / that mean gives the total rate
//    |S^(d-1)| rate |g|^lambda per pair. lambda is the scene's, so this kernel is a value, not only a type.
#include <cmath>
#include <cstddef>
#include <span>

#include "kernel/collide/collision_kernel.hpp"
#include "kernel/core/batch_variates.hpp"
#include "kernel/core/scene.hpp"

namespace granmc {

template <int d>
struct VhsKernel {
  static_assert(d == 2 || d == 3);
  static constexpr int dimension = d;
  static constexpr ImpactLaw impact_law = ImpactLaw::isotropic;
  static constexpr const char* name = d == 3 ? "vhs" : "vhs-disk";
  static constexpr const char* explanation =
      d == 3 ? "variable hard spheres in the impact-direction form (16 pi rate (g.sigma) |g|^(lambda - 1))"
             : "variable hard disks in the impact-direction form (4 pi rate Theta(g.sigma) |g|^lambda)";
  static constexpr double mean_weight = mean_angular_weight(d, impact_law);
  double lambda = 0.5;

  static VhsKernel from_scene(const Scene& scene) noexcept { return {scene.collision.lambda}; }
  [[nodiscard]] double rate(double g_sigma, double g2) const noexcept {
    if constexpr (d == 3)
      return g_sigma * std::pow(g2, 0.5 * (lambda - 1.0));
    else
      return std::pow(g2, 0.5 * lambda);
  }
  [[nodiscard]] double bound(double relative_speed) const noexcept { return std::pow(relative_speed, lambda); }
  static constexpr bool screen_candidates = true;
  template <class T>
  [[nodiscard]] T mean_rate(const T& g2) const noexcept {
    using std::pow;  // xsimd's for a batch
    return mean_weight * pow(g2, T(0.5 * lambda));
  }
  [[nodiscard]] double mean_bound(double relative_speed) const noexcept {
    return mean_weight * std::pow(relative_speed, lambda);
  }

  static constexpr bool constant_rate = false;
  template <std::size_t N>
  void acceptance_thresholds(std::span<double, N> u) const noexcept {
    if (lambda == 0.5) {  // u^2 (001 Example 9): one rounding, and a tenth of xsimd's pow in time
      for (double& x : u) x *= x;
    } else {
      power_in_place(u, 1.0 / lambda);
    }
  }
};

using VariableHardSpheres = VhsKernel<3>;
using VariableHardDisks = VhsKernel<2>;

static_assert(SteppedKernel<VariableHardSpheres> && EventKernel<VariableHardSpheres>);
static_assert(SteppedKernel<VariableHardDisks> && EventKernel<VariableHardDisks>);

}  // namespace granmc
