#pragma once
// The impact direction of a collision that is known to happen. Every kernel of the time-stepped scheme
// weighs sigma-hat by Theta(g.sigma) (g.sigma) (hard spheres, 000 eq. 2; Maxwell and VHS in their
// impact-direction form, collide/maxwell_pseudomolecules.hpp), so, given that the pair collides,
// sigma-hat has the density (g-hat.sigma-hat) / pi on the hemisphere g-hat.sigma-hat > 0.
//
// Drawn from one direction n uniform on the sphere: sigma-hat = (g-hat + n) / |g-hat + n|. The point
// g-hat + n is uniform on the unit sphere centred at g-hat, which passes through the origin; the ray from
// the origin at angle theta to g-hat meets it at distance r = 2 cos(theta) and at angle theta to its
// normal there, so the area it sweeps per solid angle is r^2 / cos(theta) = 4 cos(theta): the density of
// sigma-hat is proportional to cos(theta) = g-hat.sigma-hat, as required (docs/physics.md).
#include <cmath>

#include "kernel/core/vec3.hpp"

namespace granmc {

struct ImpactDirection {
  Vec3 sigma;      // unit vector, g.sigma > 0
  double g_sigma;  // g.sigma; not > 0 (or NaN) only when g + |g| n = 0, a case of probability zero
};

/// impact_direction component by component, for a double or an xsimd batch of them (a register of
/// candidates, each lane the same bits as impact_direction on it): sigma-hat = (sx, sy, sz), g.sigma.
template <class T>
void impact_direction_components(const T& gx, const T& gy, const T& gz, const T& g_norm, const T& nx, const T& ny,
                                 const T& nz, T& sx, T& sy, T& sz, T& g_sigma) noexcept {
  using std::sqrt;  // xsimd's for a batch
  const T hx = gx + g_norm * nx, hy = gy + g_norm * ny, hz = gz + g_norm * nz;
  const T inverse = 1.0 / sqrt(hx * hx + hy * hy + hz * hz);
  sx = inverse * hx;
  sy = inverse * hy;
  sz = inverse * hz;
  g_sigma = inverse * (gx * hx + gy * hy + gz * hz);
}

/// sigma-hat with density proportional to Theta(g.sigma) (g.sigma), from n uniform on the unit sphere;
/// g_norm = |g|. Computed as h = g + |g| n (= |g| (g-hat + n)), sigma-hat = h / |h|, g.sigma = g.h / |h|.
inline ImpactDirection impact_direction(const Vec3& g, double g_norm, const Vec3& n) noexcept {
  ImpactDirection d;
  impact_direction_components(g.x, g.y, g.z, g_norm, n.x, n.y, n.z, d.sigma.x, d.sigma.y, d.sigma.z, d.g_sigma);
  return d;
}

}  // namespace granmc
