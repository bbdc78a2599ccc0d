#pragma once
// Post-collision velocities of smooth inelastic hard spheres (000 eqs. 14-15):
//   V_k -> V_k - mu_ji (1 + alpha_ij) (g.sigma) sigma,   V_l -> V_l + mu_ij (1 + alpha_ij) (g.sigma) sigma,
// with g = V_k - V_l. Momentum m_i V_k + m_j V_l is conserved; the kinetic energy falls by
// (1 - alpha_ij^2) m_i m_j / (2 (m_i + m_j)) (g.sigma)^2 (PairCoefficients::energy_loss).
#include "kernel/collide/pair_coefficients.hpp"
#include "kernel/core/vec3.hpp"

namespace granmc {

inline void inelastic_collision(Vec3& vk, Vec3& vl, const Vec3& sigma, double g_sigma,
                                const PairCoefficients& p) noexcept {
  const double impulse = p.one_plus_alpha * g_sigma;
  vk -= (p.mu_ji * impulse) * sigma;  // 000 eq. (14)
  vl += (p.mu_ij * impulse) * sigma;  // 000 eq. (15)
}

}  // namespace granmc
