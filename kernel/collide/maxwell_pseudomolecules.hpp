#pragma once
// Maxwell pseudomolecules (001 eq. 7), B = rate with e uniform, on the sphere (d = 3) or the circle (d = 2),
// in both forms of collide/collision_kernel.hpp.
//  - Event: every candidate collides (the majorant rate is the rate), so no relative speed and no majorant is
//    computed at all.
//  - Time-stepped, in the impact-direction form: a pair with direction sigma-hat collides at omega_kl =
//    prefactor Theta(g.sigma) (g.sigma / |g|)^(d - 2), the isotropic law of ImpactLaw: the post-collision
//    rule of 000 eqs. (14-15) with sigma-hat drawn with this weight is the rule of 001 eq. (4) with e
//    uniform. Its mean over sigma-hat is prefactor / 4 (spheres) or prefactor / 2 (disks), independent of
//    |g|: with prefactor = |S^(d-1)| rate / that mean (PairCoefficients for collision.rate > 0; 16 pi rate
//    for spheres, 4 pi rate for disks) the total rate per pair is |S^(d-1)| rate, the kernel B = rate.
//    docs/methods/physics.md derives both.
#include <cmath>
#include <cstddef>
#include <span>

#include "kernel/collide/collision_kernel.hpp"

namespace granmc {

template <int d>
struct MaxwellKernel {
  static_assert(d == 2 || d == 3);
  static constexpr int dimension = d;
  static constexpr ImpactLaw impact_law = ImpactLaw::isotropic;
  static constexpr double lambda = 0.0;
  static constexpr const char* name = d == 3 ? "maxwell" : "maxwell-disk";
  static constexpr const char* explanation =
      d == 3 ? "Maxwell pseudomolecules in the impact-direction form (16 pi rate (g.sigma)/|g|)"
             : "Maxwell pseudomolecules in the plane, impact-direction form (4 pi rate Theta(g.sigma))";
  static constexpr double mean_weight = mean_angular_weight(d, impact_law);
  template <class Scene>
  static constexpr MaxwellKernel from_scene(const Scene&) noexcept {
    return {};
  }
  static double rate(double g_sigma, double g2) noexcept {
    if constexpr (d == 3)
      return g_sigma / std::sqrt(g2);
    else
      return 1.0;
  }
  static constexpr double bound(double /*relative_speed*/) noexcept { return 1.0; }
  static constexpr bool screen_candidates = false;  // every candidate collides
  static constexpr double mean_rate(double /*g2*/) noexcept { return mean_weight; }
  static constexpr double mean_bound(double /*relative_speed*/) noexcept { return mean_weight; }

  static constexpr bool constant_rate = true;
  template <std::size_t N>
  static void acceptance_thresholds(std::span<double, N>) noexcept {}  // never tested
};

using MaxwellPseudomolecules = MaxwellKernel<3>;
using MaxwellDisks = MaxwellKernel<2>;

static_assert(SteppedKernel<MaxwellPseudomolecules> && EventKernel<MaxwellPseudomolecules>);
static_assert(SteppedKernel<MaxwellDisks> && EventKernel<MaxwellDisks>);

}  // namespace granmc
