#pragma once
// The scattering direction of hard disks, for the rule of 001 eq. (4) (collide/isotropic_scattering.hpp).
// A pair of hard disks with relative velocity u meets with impact direction sigma-hat at angle theta to
// u-hat, with density cos(theta) / 2 on (-pi/2, pi/2) (000 eq. 2 in the plane; collide/impact_direction.hpp),
// and the elastic rule reflects u-hat: e = u-hat - 2 (u-hat.sigma) sigma-hat. With s = sin(theta), uniform on
// (-1, 1), and c = cos(theta):
//   e = -cos(2 theta) u-hat - sin(2 theta) u-hat-perp = (2 s^2 - 1) u-hat - 2 s c u-hat-perp,
// u-hat-perp = (-u_y, u_x) / |u|. Then 001 eq. (4) with this e is 000 eqs. (14-15): v' = v - (1 + alpha)/2
// (u.sigma) sigma-hat. The mean of mu = u-hat.e is -1/3 (on the sphere hard spheres scatter
// isotropically, mean 0), so the energy lost per collision, (1 - alpha^2)/4 (1 - mu) |u|^2, averages
// (1 - alpha^2)/3 |u|^2.
#include <cmath>

#include "kernel/core/vec3.hpp"

namespace granmc {

/// e for the relative velocity u (in the plane z = 0, |u| = u_norm > 0) and s = sin(theta) in (-1, 1).
inline Vec3 hard_disk_scattering_direction(const Vec3& u, double u_norm, double s) noexcept {
  const double inverse = 1.0 / u_norm;
  const double along = std::fma(2.0 * s, s, -1.0);                   // -cos(2 theta)
  const double across = -2.0 * s * std::sqrt(std::fma(-s, s, 1.0));  // -sin(2 theta)
  const double hx = inverse * u.x, hy = inverse * u.y;               // u-hat
  return {along * hx - across * hy, along * hy + across * hx, 0.0};  // along u-hat + across u-hat-perp
}

}  // namespace granmc
