#pragma once
// A naive scalar reference for the DSMC collision stage, written the way a researcher would first write
// it: an array of structs {vx, vy, vz}, std::mt19937_64 with the standard distributions, one candidate at
// a time. Same algorithm as granmc's collision stage (kernel/schemes/collision_stage.hpp, 000 sec. 3),
// for one species of equal-mass inelastic hard spheres:
//   1. pick k != l uniformly among the N particles;
//   2. sigma-hat uniform on the unit sphere;
//   3. accept with probability Theta(g.sigma) omega_kl / omega_max, omega_kl = 4 pi sigma^2 n |g.sigma|;
//      when omega_kl > omega_max, accept and set omega_max := omega_kl;
//   4. V_k -= (1 + alpha)/2 (g.sigma) sigma-hat, V_l += (1 + alpha)/2 (g.sigma) sigma-hat  (000 eqs. 14-15,
//      m_k = m_l).
// It is the baseline of perf/bench_collisions.cpp and is not used by the library.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

namespace granmc::naive {

struct Particle {
  double vx, vy, vz;
};

struct NaiveTally {
  std::uint64_t candidates = 0;
  std::uint64_t collisions = 0;
  double twice_energy_loss = 0.0;  // sum over collisions of 2 x (kinetic energy lost), m = 1
};

class NaiveDsmc {
 public:
  /// N particles with Maxwellian velocities at temperature T (m = 1), zero total momentum, and the
  /// initial majorant omega_max = 4 pi sigma^2 n (2 max_k |v_k|) (an exact bound at t = 0).
  NaiveDsmc(std::size_t n_particles, std::uint64_t seed, double temperature, double alpha, double density,
            double diameter)
      : particles(n_particles), gen(seed), alpha_(alpha), density_(density), diameter_(diameter) {
    std::normal_distribution<double> maxwell(0.0, std::sqrt(temperature));
    double mx = 0.0, my = 0.0, mz = 0.0;
    for (Particle& p : particles) {
      p.vx = maxwell(gen);
      p.vy = maxwell(gen);
      p.vz = maxwell(gen);
      mx += p.vx;
      my += p.vy;
      mz += p.vz;
    }
    mx /= static_cast<double>(n_particles);
    my /= static_cast<double>(n_particles);
    mz /= static_cast<double>(n_particles);
    double vmax2 = 0.0;
    for (Particle& p : particles) {
      p.vx -= mx;
      p.vy -= my;
      p.vz -= mz;
      vmax2 = std::max(vmax2, p.vx * p.vx + p.vy * p.vy + p.vz * p.vz);
    }
    omega_max = 4.0 * std::numbers::pi * diameter_ * diameter_ * density_ * 2.0 * std::sqrt(vmax2);
  }

  /// Runs `candidates` candidate pairs of the collision stage.
  NaiveTally collide(std::uint64_t candidates) {
    NaiveTally tally;
    const std::size_t n = particles.size();
    std::uniform_int_distribution<std::size_t> pick(0, n - 1);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    const double pi = std::numbers::pi;
    for (std::uint64_t c = 0; c < candidates; ++c) {
      const std::size_t k = pick(gen);
      std::size_t l = pick(gen);
      while (l == k) l = pick(gen);

      // sigma-hat uniform on the sphere: cos(theta) uniform on [-1, 1], phi uniform on [0, 2 pi)
      const double cos_theta = 2.0 * uniform(gen) - 1.0;
      const double sin_theta = std::sqrt(1.0 - cos_theta * cos_theta);
      const double phi = 2.0 * pi * uniform(gen);
      const double sx = sin_theta * std::cos(phi);
      const double sy = sin_theta * std::sin(phi);
      const double sz = cos_theta;

      Particle& pk = particles[k];
      Particle& pl = particles[l];
      const double gx = pk.vx - pl.vx;
      const double gy = pk.vy - pl.vy;
      const double gz = pk.vz - pl.vz;
      const double g_sigma = gx * sx + gy * sy + gz * sz;
      if (g_sigma <= 0.0) continue;  // Theta(g.sigma)

      const double omega = 4.0 * pi * diameter_ * diameter_ * density_ * g_sigma;
      if (omega > omega_max) {
        omega_max = omega;  // majorant exceeded: accept and update (000 sec. 3)
      } else if (uniform(gen) >= omega / omega_max) {
        continue;
      }

      const double impulse = 0.5 * (1.0 + alpha_) * g_sigma;  // equal masses: mu = 1/2
      pk.vx -= impulse * sx;                                  // 000 eq. (14)
      pk.vy -= impulse * sy;
      pk.vz -= impulse * sz;
      pl.vx += impulse * sx;  // 000 eq. (15)
      pl.vy += impulse * sy;
      pl.vz += impulse * sz;
      ++tally.collisions;
      tally.twice_energy_loss += 0.5 * (1.0 - alpha_ * alpha_) * g_sigma * g_sigma;
    }
    tally.candidates = candidates;
    return tally;
  }

  std::vector<Particle> particles;
  std::mt19937_64 gen;
  double omega_max = 0.0;

 private:
  double alpha_, density_, diameter_;
};

}  // namespace granmc::naive
