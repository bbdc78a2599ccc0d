#pragma once
// Variable hard spheres (001 eq. 8, B = rate |u|^lambda, 0 < lambda < 1) in the impact-direction form of
// the time-stepped scheme: omega_kl = prefactor Theta(g.sigma) (g.sigma) |g|^(lambda - 1). As for Maxwell
// pseudomolecules (collide/maxwell_pseudomolecules.hpp), the angular weight (g.sigma)/|g| makes the
// scattering direction uniform, and the mean over sigma-hat, prefactor |g|^lambda / 4, with prefactor =
// 16 pi rate gives the total rate 4 pi rate |g|^lambda per pair. lambda is the scene's, so this kernel
// is a value, not only a type.
#include <cmath>

#include "kernel/collide/collision_kernel.hpp"
#include "kernel/core/scene.hpp"

namespace granmc {

struct VariableHardSpheres {
  static constexpr const char* name = "vhs";
  static constexpr const char* explanation =
      "variable hard spheres in the impact-direction form (16 pi rate (g.sigma) |g|^(lambda - 1))";
  double lambda = 0.5;

  static VariableHardSpheres from_scene(const Scene& scene) noexcept { return {scene.collision.lambda}; }
  [[nodiscard]] double rate(double g_sigma, double g2) const noexcept {
    return g_sigma * std::pow(g2, 0.5 * (lambda - 1.0));
  }
  [[nodiscard]] double bound(double relative_speed) const noexcept { return std::pow(relative_speed, lambda); }
  static constexpr bool screen_candidates = true;
  template <class T>
  [[nodiscard]] T mean_rate(const T& g2) const noexcept {
    using std::pow;  // xsimd's for a batch
    return 0.25 * pow(g2, T(0.5 * lambda));
  }
  [[nodiscard]] double mean_bound(double relative_speed) const noexcept {
    return 0.25 * std::pow(relative_speed, lambda);
  }
};

static_assert(SteppedKernel<VariableHardSpheres>);

}  // namespace granmc
