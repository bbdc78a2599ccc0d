#pragma once
// The post-collision velocities of a colliding pair of 001's kernel form (collision.rate > 0, unit masses),
// from the direction its law draws, for the schemes of 001 (the event scheme, the weighted particles):
//  - spheres, and Maxwell and VHS disks: e uniform on the sphere or circle and 001 eq. (4)
//    (collide/isotropic_scattering.hpp);
//  - hard disks, whose law is not isotropic in the plane: the impact variate n of impact_variate<2>
//    (collide/impact_direction.hpp), sigma-hat from n and u = v_i - v_j, and 000's rule
//    (collide/inelastic_rule.hpp), which is 001 eq. (4) with e the reflection of u-hat in sigma-hat.
// On the sphere the two ways are the same law (docs/methods/physics.md, "001's kernels in the plane").
#include <cstddef>
#include <span>

#include "kernel/collide/collision_kernel.hpp"
#include "kernel/collide/impact_direction.hpp"
#include "kernel/collide/inelastic_rule.hpp"
#include "kernel/collide/isotropic_scattering.hpp"
#include "kernel/collide/pair_coefficients.hpp"
#include "kernel/core/batch_variates.hpp"
#include "kernel/core/sampling.hpp"
#include "kernel/core/vec3.hpp"

namespace granmc {

/// Whether the kernel's pairs scatter through an impact direction (hard disks) rather than by 001 eq. (4).
template <EventKernel Kernel>
inline constexpr bool scatters_by_impact = Kernel::dimension == 2 && Kernel::impact_law == ImpactLaw::hard_core;

/// The direction a colliding pair's law draws, from two uniforms (disks use u1 only).
template <EventKernel Kernel>
Vec3 scattering_variate(double u1, double u2) noexcept {
  if constexpr (scatters_by_impact<Kernel>)
    return impact_variate<2, ImpactLaw::hard_core>(u1, u2);
  else if constexpr (Kernel::dimension == 2)
    return unit_circle_vector(u1);
  else
    return unit_vector(u1, u2);
}

/// scattering_variate lane by lane (the same bits).
template <EventKernel Kernel, std::size_t N>
void scattering_variates(std::span<const double, N> u1, std::span<const double, N> u2, std::span<double, N> x,
                         std::span<double, N> y, std::span<double, N> z) noexcept {
  if constexpr (scatters_by_impact<Kernel>)
    impact_variates<2, ImpactLaw::hard_core>(u1, u2, x, y, z);
  else if constexpr (Kernel::dimension == 2)
    unit_circle_vectors(u1, x, y, z);
  else
    unit_vectors(u1, u2, x, y, z);
}

/// The collision of v_i and v_j with the drawn direction (001 eq. 4; hard disks by 000's rule with
/// `unit_pair`, the coefficients of two unit masses with the scene's alpha).
template <EventKernel Kernel>
void rate_form_scattering(Vec3& vi, Vec3& vj, const Vec3& drawn, double alpha,
                          const PairCoefficients& unit_pair) noexcept {
  if constexpr (scatters_by_impact<Kernel>) {
    const Vec3 u = vi - vj;
    const ImpactDirection id = impact_direction<2>(u, norm(u), drawn);
    inelastic_collision(vi, vj, id.sigma, id.g_sigma, unit_pair);
  } else {
    isotropic_scattering(vi, vj, drawn, alpha);
  }
}

}  // namespace granmc
