#pragma once
// The collision stage of the time-stepped ESMC/DSMC scheme for one ordered species pair (i, j)
// (000 sec. 3): `candidates` pairs {k, l} (k of species i, l of species j, l != k when i = j) chosen
// with equiprobability; for each, a direction sigma-hat uniform on the sphere, acceptance with
// probability Theta(g.sigma) omega_kl / omega_max, and the post-collision rule of 000 eqs. (14-15).
// When omega_kl exceeds the majorant, the collision is accepted and omega_max := omega_kl (000 sec. 3).
//
// Velocities are in stored units (V = u c); omega_max and omega_kl are in units of u (their physical
// values are u times these), which leaves the acceptance ratio unchanged.
#include <algorithm>
#include <cstdint>

#include "kernel/collide/inelastic_rule.hpp"
#include "kernel/collide/pair_coefficients.hpp"
#include "kernel/core/philox_stream.hpp"
#include "kernel/core/sampling.hpp"
#include "kernel/schemes/gas_state.hpp"

namespace granmc {

struct CollisionTally {
  std::uint64_t candidates = 0;
  std::uint64_t collisions = 0;
  std::uint64_t majorant_updates = 0;
  double twice_energy_loss = 0.0;  // sum over collisions of 2 x (kinetic energy lost), stored units
};

/// Random words per candidate: block 2c gives the two particle indices (64 bits each), block 2c + 1 the
/// direction (two 32-bit uniforms) and the acceptance uniform.
///
/// Candidates are drawn in batches of `batch`: the random blocks and indices of a batch first, with
/// the two velocity records of each candidate prefetched, then the candidates one by one in order. Two
/// candidates of a batch that share a particle therefore still act in sequence, and the result is the
/// same for every batch size (tests/test_collision_stage.cpp); the batch only lets the memory loads of
/// different candidates overlap (perf/bench_collisions.cpp: 1.4x at N = 10^5, 3x at N = 10^7).
template <class Kernel, std::uint64_t batch = 64>
void collide_pair(GasState& state, const PairCoefficients& p, double& omega_max, std::uint64_t candidates,
                  const RandomStream& rng, CollisionTally& tally) noexcept {
  static_assert(batch > 0);
  SpeciesStore& a = state.species[p.i];
  SpeciesStore& b = state.species[p.j];
  const bool same_species = p.i == p.j;
  const std::uint64_t na = a.size();
  const std::uint64_t nb = same_species ? na - 1 : b.size();
  std::uint64_t ks[batch], ls[batch];
  RandomBlock draws[batch];
  for (std::uint64_t c0 = 0; c0 < candidates; c0 += batch) {
    const std::uint64_t m = std::min(batch, candidates - c0);
    for (std::uint64_t q = 0; q < m; ++q) {
      const std::uint64_t c = c0 + q;
      const RandomBlock pick = rng.block(RngPurpose::collision_pair, p.rng_sub, state.step, 2 * c);
      draws[q] = rng.block(RngPurpose::collision_pair, p.rng_sub, state.step, 2 * c + 1);
      ks[q] = uniform_index(pick[0], pick[1], na);
      ls[q] = uniform_index(pick[2], pick[3], nb);
      if (same_species && ls[q] >= ks[q]) ++ls[q];  // uniform over the other N_i - 1 particles
      a.prefetch(ks[q]);
      b.prefetch(ls[q]);
    }
    for (std::uint64_t q = 0; q < m; ++q) {
      const RandomBlock& draw = draws[q];
      const Vec3 sigma = unit_vector(uniform_open(draw[0]), uniform_open(draw[1]));
      Vec3 vk = a.velocity(ks[q]);
      Vec3 vl = b.velocity(ls[q]);
      const double g_sigma = dot(vk - vl, sigma);
      if (g_sigma <= 0.0) continue;  // Theta(g.sigma): the pair is separating along sigma-hat
      const double omega = p.rate_prefactor * Kernel::rate(g_sigma);
      if (omega > omega_max) {
        omega_max = omega;
        ++tally.majorant_updates;
      } else if (uniform_open(draw[2]) * omega_max > omega) {
        continue;
      }
      inelastic_collision(vk, vl, sigma, g_sigma, p);
      a.set_velocity(ks[q], vk);
      b.set_velocity(ls[q], vl);
      ++tally.collisions;
      tally.twice_energy_loss += 2.0 * p.energy_loss * g_sigma * g_sigma;
    }
  }
  tally.candidates += candidates;
}

}  // namespace granmc
