#pragma once
// Post-collision velocities and spins of rough inelastic hard spheres (disks) with constant normal and
// tangential restitution (Huthmann and Zippelius, Phys. Rev. E 56 (1997) R6275; Luding, Huthmann, McNamara and
// Zippelius, Phys. Rev. E 58 (1998) 3416), docs/methods/derivations/rough-hcs.md. With sigma-hat from particle k to
// particle l and the spins s = (sigma / 2) omega (core/species_store.hpp), the relative velocity of the contact
// points is
//   G = g - sigma-hat x (s_k + s_l),   g = V_k - V_l,   G.sigma-hat = g.sigma-hat,
// and the impulse J on k (-J on l) makes G.sigma-hat -> -alpha G.sigma-hat and G_t -> -beta G_t, G_t the part
// of G normal to sigma-hat:
//   J = -mu_ij [(1 + alpha) (g.sigma) sigma-hat + tangential G_t],
//   tangential = (1 + beta) / (1 + mu_ij (1 / (kappa m_i) + 1 / (kappa m_j)))   (kappa / (1 + kappa) (1 + beta) for
//   equal masses, twice the b = kappa (1 + beta) / (2 (1 + kappa)) of kernel/theory/rough.hpp),
// V_k += J / m_k, V_l -= J / m_l and, from the torques (sigma / 2) sigma-hat x J of both, s_k += sigma-hat x J /
// (kappa m_k), s_l += sigma-hat x J / (kappa m_l). Momentum and the angular momentum about the contact point
// are conserved; beta = -1 is the smooth rule of collide/inelastic_rule.hpp, and beta = 1 with alpha = 1
// conserves the total energy. Disks: sigma-hat and G_t lie in the plane and the spins along z.
#include "kernel/collide/pair_coefficients.hpp"
#include "kernel/core/vec3.hpp"

namespace granmc {

/// The collision of rough particles k and l along sigma-hat with g.sigma = g_sigma > 0; returns twice the
/// translational kinetic energy the pair lost (masses in scene units, velocities in the units given).
inline double rough_collision(Vec3& vk, Vec3& vl, Vec3& sk, Vec3& sl, const Vec3& sigma, double g_sigma,
                              const PairCoefficients& p) noexcept {
  const Vec3 g = vk - vl;
  const Vec3 contact = g - cross(sigma, sk + sl);
  const Vec3 slip = contact - g_sigma * sigma;  // G_t
  const double impulse = p.one_plus_alpha * g_sigma;
  // The normal part as collide/inelastic_rule.hpp computes it, so that tangential = 0 gives its bits.
  vk -= (p.mu_ji * impulse) * sigma + p.tangential_k * slip;
  vl += (p.mu_ij * impulse) * sigma + p.tangential_l * slip;
  const Vec3 turn = cross(sigma, slip);
  sk -= p.spin_k * turn;
  sl -= p.spin_l * turn;
  // 2 mu_ij (K.g - K^2 / 2) with K = impulse sigma-hat + tangential G_t: the normal part, then the tangential one.
  return 2.0 * p.energy_loss * g_sigma * g_sigma +
         p.reduced_mass * p.tangential * (2.0 * dot(slip, g) - p.tangential * norm2(slip));
}

}  // namespace granmc
