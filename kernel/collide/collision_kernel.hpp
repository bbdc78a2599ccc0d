#pragma once
// What a collision kernel is, as C++20 concepts: the contract the schemes rely on, checked where a kernel is
// used (schemes/dsmc.hpp, schemes/event_scheme.hpp). A kernel is one struct per physical law
// (collide/hard_sphere.hpp, maxwell_pseudomolecules.hpp, variable_hard_spheres.hpp) with both faces.
//
// A time-stepped kernel (the impact-direction form of 000 sec. 3) gives the velocity-dependent factor of the rate
// omega_kl of a pair with direction sigma-hat; the pair's constant prefactor lives in PairCoefficients. It has
// lambda (omega scales as |g|^lambda, so a physical rate is u^lambda times the stored-unit one),
// rate(g.sigma, |g|^2), bound(U) >= rate for relative speeds up to U, from_scene(scene) (the kernel's
// parameters), dimension (3, or 2 for disks) and impact_law, how it weighs sigma-hat (ImpactLaw below). Its
// mean over sigma-hat uniform on the sphere is mean_rate(|g|^2) = mean_angular_weight |g|^lambda, with
// mean_bound(U) >= mean_rate up to U (schemes/collision_stage.hpp accepts a pair with probability
// mean_rate / omega_max). mean_rate takes a double or an xsimd batch of them (the stage screens a batch's
// candidates in SIMD), and screen_candidates says whether that screen can reject any: false when the mean
// rate is a constant, so that every candidate collides. name and explanation are what `--explain` prints.
//
// An event kernel (001 eqs. 6-8) is B = rate |u|^lambda with e uniform on the sphere (circle)
// (collide/isotropic_scattering.hpp), rate = gamma C_lambda (001 eq. 1); hard disks scatter by their own law
// instead (collide/impact_direction.hpp). The event scheme draws candidates at
// the constant majorant rate of 001 eq. (25) and keeps a candidate with probability (|u| / U_max)^lambda
// (001 eq. 26), tested as u^(1 / lambda) < |u| / U_max on a batch of uniforms: the kernel has lambda,
// constant_rate (every candidate is real: no relative speed and no majorant is computed) and
// acceptance_thresholds, which maps a batch of u to u^(1 / lambda).
#include <concepts>
#include <numbers>
#include <span>

#include "kernel/core/scene.hpp"

namespace granmc {

/// How a kernel weighs the impact direction sigma-hat of a pair, given |g|:
///  - hard_core: Theta(g.sigma) (g.sigma), the hard-core law (000 eq. 2);
///  - isotropic: so that the scattering direction e of 001 eq. (4) is uniform on the sphere (circle), the
///    weight Theta(g.sigma) (g.sigma)^(d - 2): (g.sigma) for spheres, the hard-core law again (hard spheres
///    scatter isotropically), and constant on the half circle for disks (the angle of e to g-hat is
///    pi - 2 theta when sigma-hat is at theta).
enum class ImpactLaw { hard_core, isotropic };

/// |S^(d-1)|, the area of the unit sphere (4 pi) or the length of the unit circle (2 pi).
constexpr double unit_sphere_area(int dimension) noexcept {
  return dimension == 2 ? 2.0 * std::numbers::pi : 4.0 * std::numbers::pi;
}

/// The mean over sigma-hat uniform on the sphere (circle) of the law's weight at |g| = 1: Theta(g.sigma)
/// (g.sigma) averages 1/4 on the sphere and 1/pi on the circle; Theta(g.sigma) averages 1/2 on the circle.
constexpr double mean_angular_weight(int dimension, ImpactLaw law) noexcept {
  if (dimension == 3) return 0.25;
  return law == ImpactLaw::hard_core ? std::numbers::inv_pi : 0.5;
}

template <class K>
concept SteppedKernel = requires(const K& kernel, double g_sigma, double g2, double speed, const Scene& scene) {
  { K::name } -> std::convertible_to<const char*>;
  { K::dimension } -> std::convertible_to<int>;
  { K::impact_law } -> std::convertible_to<ImpactLaw>;
  { K::explanation } -> std::convertible_to<const char*>;
  { kernel.lambda } -> std::convertible_to<double>;
  { K::screen_candidates } -> std::convertible_to<bool>;
  { K::from_scene(scene) } -> std::same_as<K>;
  { kernel.rate(g_sigma, g2) } -> std::same_as<double>;
  { kernel.bound(speed) } -> std::same_as<double>;
  { kernel.mean_rate(g2) } -> std::same_as<double>;
  { kernel.mean_bound(speed) } -> std::same_as<double>;
};

/// Whether a kernel's particles are rough (collide/hard_sphere.hpp): they spin, and collide by
/// collide/rough_rule.hpp.
template <class K>
inline constexpr bool rough_kernel = requires {
  requires K::rough;
};

template <class K>
concept EventKernel = requires(const K& kernel, std::span<double, 64> uniforms) {
  { K::name } -> std::convertible_to<const char*>;
  { K::dimension } -> std::convertible_to<int>;
  { K::impact_law } -> std::convertible_to<ImpactLaw>;
  { K::constant_rate } -> std::convertible_to<bool>;
  { kernel.lambda } -> std::convertible_to<double>;
  kernel.acceptance_thresholds(uniforms);
};

}  // namespace granmc
