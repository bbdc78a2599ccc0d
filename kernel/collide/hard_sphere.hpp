#pragma once
// Hard spheres (d = 3) and hard disks (d = 2), in both forms of collide/collision_kernel.hpp.
//  - Time-stepped (the Enskog operator, 000 eq. 2, in d dimensions): a pair (k, l) with direction sigma-hat
//    uniform on the unit sphere (circle) collides at the rate omega_kl = S_d sigma_ij^(d-1) n_j chi_ij
//    Theta(g.sigma) |g.sigma|, with S_d the measure of the unit sphere (4 pi; 2 pi for the circle; 000 sec. 3,
//    step 2). The evaluator gives the velocity-dependent factor; the pair's constant prefactor lives in
//    PairCoefficients. The mean of Theta(g.sigma) (g.sigma) over sigma-hat uniform is |g| / 4 for d = 3 and
//    |g| / pi for d = 2 (the integral of cos over a half circle, 2, over 2 pi), so the total rate per pair is
//    pi sigma^2 n chi |g| (spheres) and 2 sigma n chi |g| (disks).
//  - Event (001 eq. 6): B = rate |u|, e uniform on the sphere for spheres; disks collide as in the
//    time-stepped form (impact direction and 000's rule, schemes/event_scheme.hpp); a candidate is kept with
//    probability |u| / U_max, the test u < |u| / U_max needing no transformation of u.
#include <cmath>
#include <cstddef>
#include <span>

#include "kernel/collide/collision_kernel.hpp"

namespace granmc {

/// Hard cores in d = 3 (spheres) or d = 2 (disks), smooth or `is_rough`: rough particles collide at the
/// same rate (the rate follows the centres' g.sigma) by the rule of collide/rough_rule.hpp, and spin.
template <int d, bool is_rough = false>
struct HardCore {
  static_assert(d == 2 || d == 3);
  static constexpr int dimension = d;
  static constexpr ImpactLaw impact_law = ImpactLaw::hard_core;
  static constexpr bool rough = is_rough;
  static constexpr double lambda = 1.0;
  static constexpr const char* name =
      d == 3 ? (rough ? "rough-hard-sphere" : "hard-sphere") : (rough ? "rough-hard-disk" : "hard-disk");
  static constexpr const char* explanation =
      d == 3 ? (rough ? "rough hard spheres: omega_kl = 4 pi sigma_ij^2 n_j chi_ij Theta(g.sigma) (g.sigma) (000 sec. "
                        "3), normal and tangential restitution (collide/rough_rule.hpp)"
                      : "hard spheres: omega_kl = 4 pi sigma_ij^2 n_j chi_ij Theta(g.sigma) (g.sigma) (000 sec. 3)")
             : (rough ? "rough hard disks: omega_kl = 2 pi sigma_ij n_j chi_ij Theta(g.sigma) (g.sigma) (000 sec. 3 "
                        "in d = 2), normal and tangential restitution (collide/rough_rule.hpp)"
                      : "hard disks: omega_kl = 2 pi sigma_ij n_j chi_ij Theta(g.sigma) (g.sigma) (000 sec. 3 in d = "
                        "2)");
  /// The mean of Theta(g.sigma) (g.sigma) / |g| over sigma-hat uniform on the unit sphere (circle).
  static constexpr double mean_g_sigma = mean_angular_weight(d, impact_law);
  template <class Scene>
  static constexpr HardCore from_scene(const Scene&) noexcept {
    return {};
  }
  /// Rate factor for normal relative speed g_sigma = g.sigma-hat > 0.
  static constexpr double rate(double g_sigma, double /*g2*/) noexcept { return g_sigma; }
  static constexpr double bound(double relative_speed) noexcept { return relative_speed; }
  static constexpr bool screen_candidates = true;
  template <class T>
  static T mean_rate(const T& g2) noexcept {
    using std::sqrt;  // xsimd's for a batch
    return mean_g_sigma * sqrt(g2);
  }
  static constexpr double mean_bound(double relative_speed) noexcept { return mean_g_sigma * relative_speed; }

  static constexpr bool constant_rate = false;
  template <std::size_t N>
  static void acceptance_thresholds(std::span<double, N>) noexcept {}  // u^(1 / 1) = u
};

using HardSphere = HardCore<3>;
using HardDisk = HardCore<2>;
using RoughHardSphere = HardCore<3, true>;
using RoughHardDisk = HardCore<2, true>;

static_assert(SteppedKernel<HardSphere> && EventKernel<HardSphere> && SteppedKernel<HardDisk> && EventKernel<HardDisk>);
static_assert(SteppedKernel<RoughHardSphere> && SteppedKernel<RoughHardDisk>);

}  // namespace granmc
