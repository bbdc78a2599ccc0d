#pragma once
// Post-collision velocities for a kernel independent of the scattering angle (001 eq. 4):
//   v' = (v + w)/2 + (1 - alpha)/4 u + (1 + alpha)/4 |u| e,
//   w' = (v + w)/2 - (1 - alpha)/4 u - (1 + alpha)/4 |u| e,   u = v - w, e uniform on the sphere.
// Momentum is conserved; |v'|^2 + |w'|^2 - |v|^2 - |w|^2 = -(1 - alpha^2)/4 (1 - mu) |u|^2 with
// mu = (u, e)/|u| (001 sec. 2).
#include "kernel/core/vec3.hpp"

namespace granmc {

inline void isotropic_scattering(Vec3& v, Vec3& w, const Vec3& e, double alpha) noexcept {
  const Vec3 centre = 0.5 * (v + w);
  const Vec3 u = v - w;
  const Vec3 half_change = (0.25 * (1.0 - alpha)) * u + (0.25 * (1.0 + alpha) * norm(u)) * e;  // 001 eq. (4)
  v = centre + half_change;
  w = centre - half_change;
}

}  // namespace granmc
