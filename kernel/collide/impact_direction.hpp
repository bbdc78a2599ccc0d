#pragma once
// The impact direction of a collision that is known to happen, with the kernel's ImpactLaw
// (collide/collision_kernel.hpp). On the sphere both laws weigh sigma-hat by Theta(g.sigma) (g.sigma) (hard
// spheres, 000 eq. 2; Maxwell and VHS in their impact-direction form, collide/maxwell_pseudomolecules.hpp),
// so, given that the pair collides, sigma-hat at angle theta to g-hat has density proportional to
// cos(theta) = g-hat.sigma-hat on the half sphere g-hat.sigma-hat > 0. On the circle hard disks have the
// same density, the isotropic law a uniform theta on the half circle.
//
// Spheres (d = 3): drawn from one direction n uniform on the sphere, sigma-hat = (g-hat + n) / |g-hat + n|.
// The point g-hat + n is uniform on the unit sphere centred at g-hat, which passes through the origin; the
// ray from the origin at angle theta to g-hat meets it at distance r = 2 cos(theta) and at angle theta to
// its normal there, so the area it sweeps per solid angle is r^2 / cos(theta) = 4 cos(theta): the density
// of sigma-hat is proportional to cos(theta), as required (docs/methods/physics.md).
//
// Disks (d = 2): the same construction on the circle sweeps a length r / cos(theta) = 2 per unit angle, a
// uniform theta, so it does not carry over. Instead n = (cos theta, sin theta, 0) is drawn with sin(theta)
// = 2 u - 1 uniform (density cos(theta) / 2, core/sampling.hpp's lambert_circle_vector) for hard disks, with
// theta uniform (half_circle_vector) for the isotropic law, and sigma-hat = cos(theta) g-hat + sin(theta)
// g-hat-perp, g-hat-perp = (-g_y, g_x) / |g|, g.sigma = |g| cos(theta).
#include <cmath>
#include <cstddef>
#include <span>

#include "kernel/collide/collision_kernel.hpp"
#include "kernel/core/batch_variates.hpp"
#include "kernel/core/sampling.hpp"
#include "kernel/core/unfused.hpp"
#include "kernel/core/vec3.hpp"

namespace granmc {

struct ImpactDirection {
  Vec3 sigma;      // unit vector, g.sigma > 0
  double g_sigma;  // g.sigma; not > 0 (or NaN) only when g + |g| n = 0 or g = 0, cases of probability zero
};

/// The variate n of impact_direction<d> for the impact law `law` from two uniforms (d = 2 uses u1 only).
template <int d, ImpactLaw law = ImpactLaw::hard_core>
Vec3 impact_variate(double u1, double u2) noexcept {
  if constexpr (d == 3)
    return unit_vector(u1, u2);
  else if constexpr (law == ImpactLaw::hard_core)
    return lambert_circle_vector(u1);
  else
    return half_circle_vector(u1);
}

/// impact_variate lane by lane (the same bits).
template <int d, ImpactLaw law = ImpactLaw::hard_core, std::size_t N>
void impact_variates(std::span<const double, N> u1, std::span<const double, N> u2, std::span<double, N> x,
                     std::span<double, N> y, std::span<double, N> z) noexcept {
  if constexpr (d == 3)
    unit_vectors(u1, u2, x, y, z);
  else if constexpr (law == ImpactLaw::hard_core)
    lambert_circle_vectors(u1, x, y, z);
  else
    half_circle_vectors(u1, x, y, z);
}

/// impact_direction component by component, for a double or an xsimd batch of them (a register of
/// candidates, each lane the same bits as impact_direction on it): sigma-hat = (sx, sy, sz), g.sigma.
template <int d, class T>
void impact_direction_components(const T& gx, const T& gy, const T& gz, const T& g_norm, const T& nx, const T& ny,
                                 const T& nz, T& sx, T& sy, T& sz, T& g_sigma) noexcept {
  using std::sqrt;  // xsimd's for a batch
  if constexpr (d == 3) {
    const T hx = gx + g_norm * nx, hy = gy + g_norm * ny, hz = gz + g_norm * nz;
    const T inverse = 1.0 / sqrt(hx * hx + hy * hy + hz * hz);
    sx = inverse * hx;
    sy = inverse * hy;
    sz = inverse * hz;
    g_sigma = inverse * (gx * hx + gy * hy + gz * hz);
  } else {  // n = (cos theta, sin theta, 0)
    const T inverse = 1.0 / g_norm;
    // Each product rounded on its own, in the scalar form as in SIMD (core/unfused.hpp).
    sx = inverse * (unfused(nx * gx) - unfused(ny * gy));
    sy = inverse * (unfused(nx * gy) + unfused(ny * gx));
    sz = T(0.0);
    g_sigma = nx * g_norm;
  }
}

/// sigma-hat with density proportional to Theta(g.sigma) (g.sigma), from the variate n = impact_variate<d>;
/// g_norm = |g|. Spheres: h = g + |g| n (= |g| (g-hat + n)), sigma-hat = h / |h|, g.sigma = g.h / |h|.
template <int d = 3>
ImpactDirection impact_direction(const Vec3& g, double g_norm, const Vec3& n) noexcept {
  ImpactDirection id;
  impact_direction_components<d>(g.x, g.y, g.z, g_norm, n.x, n.y, n.z, id.sigma.x, id.sigma.y, id.sigma.z, id.g_sigma);
  return id;
}

}  // namespace granmc
