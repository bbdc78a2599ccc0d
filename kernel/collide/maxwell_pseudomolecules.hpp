#pragma once
// Maxwell pseudomolecules (001 eq. 7), B = rate, in both forms of collide/collision_kernel.hpp.
//  - Event: every candidate collides (the majorant rate is the rate), so no relative speed and no majorant is
//    computed at all.
//  - Time-stepped, in the impact-direction form: a pair with direction sigma-hat collides at omega_kl = prefactor
//  Theta(g.sigma) (g.sigma) / |g|. The post-
// collision rule of 000 eqs. (14-15) with sigma-hat drawn with this weight is the rule of 001 eq. (4) with
// e uniform (the elastic scattering direction e = g' / |g| is uniform when the weight is (g.sigma)/|g|),
// and the mean of omega over sigma-hat is prefactor / 4, independent of |g|: with prefactor = 16 pi rate
// (PairCoefficients for collision.rate > 0) the total rate per pair is 4 pi rate, the kernel B = rate.
// docs/physics.md derives both.
#include <cmath>
#include <cstddef>
#include <span>

#include "kernel/collide/collision_kernel.hpp"

namespace granmc {

struct MaxwellPseudomolecules {
  static constexpr int dimension = 3;  // spheres only so far
  static constexpr double lambda = 0.0;
  static constexpr const char* name = "maxwell";
  static constexpr const char* explanation =
      "Maxwell pseudomolecules in the impact-direction form (16 pi rate (g.sigma)/|g|)";
  template <class Scene>
  static constexpr MaxwellPseudomolecules from_scene(const Scene&) noexcept {
    return {};
  }
  static double rate(double g_sigma, double g2) noexcept { return g_sigma / std::sqrt(g2); }
  static constexpr double bound(double /*relative_speed*/) noexcept { return 1.0; }
  static constexpr bool screen_candidates = false;  // every candidate collides
  static constexpr double mean_rate(double /*g2*/) noexcept { return 0.25; }
  static constexpr double mean_bound(double /*relative_speed*/) noexcept { return 0.25; }

  static constexpr bool constant_rate = true;
  template <std::size_t N>
  static void acceptance_thresholds(std::span<double, N>) noexcept {}  // never tested
};

static_assert(SteppedKernel<MaxwellPseudomolecules> && EventKernel<MaxwellPseudomolecules>);

}  // namespace granmc
