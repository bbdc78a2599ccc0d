#pragma once
// Constants of one ordered species pair (i, j) in the collision stage of 000 sec. 3.
#include <cstdint>
#include <vector>

#include "kernel/core/scene.hpp"

namespace granmc {

struct PairCoefficients {
  int i = 0, j = 0;             // species of particle k and of particle l
  double rate_prefactor = 0.0;  // 4 pi sigma_ij^2 n_j chi_ij (000 sec. 3; disks 2 pi sigma_ij n_j chi_ij), or
                                // 16 pi rate in the kernel form of 001 (collision.rate > 0): omega_kl / Kernel::rate
  double mu_ji = 0.0;           // m_j / (m_i + m_j), moves particle k (000 eq. 14)
  double mu_ij = 0.0;           // m_i / (m_i + m_j), moves particle l (000 eq. 15)
  double one_plus_alpha = 2.0;  // 1 + alpha_ij
  double energy_loss = 0.0;     // (1 - alpha_ij^2) m_i m_j / (2 (m_i + m_j)): loss / (g.sigma)^2
  double reduced_mass = 0.0;    // m_i m_j / (m_i + m_j): the impulse is (1 + alpha_ij) reduced_mass (g.sigma)
  double diameter = 0.0;        // sigma_ij = (sigma_i + sigma_j) / 2
  // Rough particles (collide/rough_rule.hpp), zero for smooth ones: the tangential impulse is
  // -tangential reduced_mass G_t, tangential = (1 + beta) / (1 + reduced_mass (1 / (kappa m_i) + 1 / (kappa m_j))),
  // which moves particle k by tangential_k = mu_ji tangential and l by tangential_l = mu_ij tangential, and turns their
  // spins by spin_k = tangential_k / kappa and spin_l = tangential_l / kappa.
  double tangential = 0.0;
  double tangential_k = 0.0, tangential_l = 0.0;
  double spin_k = 0.0, spin_l = 0.0;
};

/// The ordered pairs (i, j) of the scene's species, both orders as 000 sec. 3 does.
std::vector<PairCoefficients> pair_coefficients(const Scene& scene);

}  // namespace granmc
