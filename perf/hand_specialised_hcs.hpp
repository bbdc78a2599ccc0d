#pragma once
// A hand-specialised time step for the plain scene of perf/bench_effects.cpp, written for that case
// alone: one species of equal-mass inelastic hard spheres, dilute (chi = 1), no thermostat, no other
// effect. It is the reference the library's plain scene is held to (within 3%).
//
// Same algorithm and random-number layout as collide_step<HardSphere> (kernel/schemes/collision_stage.hpp,
// 000 sec. 3): candidate s of step t uses Philox block (collision_pair, 0, t, 2 s) for the indices k and
// l != k, block 2 s + 1 for the direction n (words 0, 1) and the acceptance uniform (word 2); acceptance
// on the mean of omega over sigma-hat, prefactor |g| / 4, then sigma-hat = (g-hat + n) / |g-hat + n|
// (collide/impact_direction.hpp); candidates
// are drawn in batches of 64 (Philox over the batch's counters as arrays, the indices lane by lane), a
// batch ahead of their use;
// each batch is screened in SIMD (omega of all its candidates, the ones rejected with certainty and
// sharing no particle with an earlier candidate of the batch left out), and candidate b prefetches the
// records of candidate b of the next batch; the directions of the candidates that pass the screen in
// SIMD, and for those that share no particle with an earlier one sigma-hat and g.sigma too; then those
// candidates in order. The result is the same bits as collide_step on the same state
// and seed (checked at the start of bench_effects).
//
// What it leaves out of the generic stage: the pair table (the constants are locals), the interleaving
// of species pairs (no pair draw, no per-candidate pair lookup), the Kernel template (omega = prefactor
// |g| / 4 inline), the effects, and the tally and majorant held through references (here locals that
// stay in registers). The velocity record is the library's 32-byte (x, y, z, aux) record in a huge-page
// buffer, since that layout is a separate, measured choice (perf/bench_layout.cpp). Not used by the
// library.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <span>

#include "kernel/collide/impact_direction.hpp"
#include "kernel/core/aligned_buffer.hpp"
#include "kernel/core/batch_variates.hpp"
#include "kernel/core/philox_stream.hpp"
#include "kernel/core/sampling.hpp"
#include "kernel/core/vec3.hpp"

namespace granmc::perf {

struct alignas(32) HandRecord {
  double x, y, z, aux;
};
static_assert(sizeof(HandRecord) == 32);

struct HandConstants {
  double rate_prefactor = 0.0;     // 4 pi sigma^2 n (000 sec. 3, chi = 1)
  double one_plus_alpha = 2.0;     // 1 + alpha
  double twice_energy_loss = 0.0;  // 2 x (1 - alpha^2) m / 4: twice the energy lost / (g.sigma)^2

  /// The same expressions as pair_coefficients, so the same bits.
  static HandConstants of(double alpha, double diameter, double density, double mass) noexcept {
    const double sigma = 0.5 * (diameter + diameter);
    return {4.0 * std::numbers::pi * sigma * sigma * density, 1.0 + alpha,
            2.0 * (0.5 * (1.0 - alpha * alpha) * mass * mass / (mass + mass))};
  }
};

struct HandTally {
  std::uint64_t collisions = 0;
  std::uint64_t majorant_updates = 0;
  double twice_energy_loss = 0.0;
};

/// The collision stage of step `step`: `candidates` candidate pairs among the n < 2^32 records of v.
template <std::uint64_t batch = 64>
HandTally hand_collide(HandRecord* v, std::uint64_t n, double& omega_max, std::uint64_t candidates,
                       const RandomStream& rng, std::uint64_t step, const HandConstants& c) noexcept {
  const double prefactor = c.rate_prefactor, one_plus_alpha = c.one_plus_alpha, loss = c.twice_energy_loss;
  double majorant = omega_max;
  HandTally t;
  static_assert(batch % SimdDouble::size == 0 && batch <= 64);
  using Lanes = std::array<double, batch>;
  struct Drawn {
    std::uint64_t ks[batch], ls[batch];
    Lanes accept;  // acceptance uniforms
    Lanes dir1, dir2;
  };
  std::array<std::uint64_t, 2 * batch> steps, index;
  steps.fill(step);
  std::array<std::uint32_t, batch> range_k, range_l;  // n < 2^32 (hand_collide's precondition)
  range_k.fill(static_cast<std::uint32_t>(n));
  range_l.fill(static_cast<std::uint32_t>(n - 1));
  auto draw_batch = [&](Drawn& d, std::uint64_t s0, std::uint64_t m) {
    for (std::uint64_t b = 0; b < batch; ++b) {  // block 2s in lane b, block 2s + 1 in lane batch + b
      index[b] = 2 * (s0 + b);
      index[batch + b] = 2 * (s0 + b) + 1;
    }
    const RandomBlocks<2 * batch> blocks = rng.blocks(RngPurpose::collision_pair, 0, steps, index);
    const auto& w = blocks.word;
    auto pick = [&](std::size_t word) { return std::span<const std::uint32_t, batch>(w[word].data(), batch); };
    std::array<std::uint64_t, batch> ks, ls;
    uniform_indices(pick(0), pick(1), range_k, ks);
    uniform_indices(pick(2), pick(3), range_l, ls);
    for (std::uint64_t b = 0; b < m; ++b) {
      d.ks[b] = ks[b];
      d.ls[b] = ls[b] + static_cast<std::uint64_t>(ls[b] >= ks[b]);  // uniform over the other n - 1
    }
    for (std::uint64_t b = 0; b < batch; ++b) {
      d.dir1[b] = uniform_open(w[0][batch + b]);
      d.dir2[b] = uniform_open(w[1][batch + b]);
      d.accept[b] = uniform_open(w[2][batch + b]);
    }
  };
  // The screen's table of batch stamps, by particle index (two particles can share a slot).
  constexpr std::uint64_t slots = std::uint64_t{1} << 14;
  std::array<std::uint8_t, slots> seen{};
  std::uint8_t stamp = 0;
  Lanes g2s{}, sx, sy, sz;
  Lanes gx_passed, gy_passed, gz_passed, g2_passed, sigma_x, sigma_y, sigma_z, g_sigma_passed;
  std::array<std::uint8_t, batch> which;
  std::array<Drawn, 2> drawn{};
  if (candidates > 0) {
    draw_batch(drawn[0], 0, std::min(batch, candidates));
    for (std::uint64_t b = 0; b < std::min(batch, candidates); ++b) {
      __builtin_prefetch(v + drawn[0].ks[b], 1, 3);
      __builtin_prefetch(v + drawn[0].ls[b], 1, 3);
    }
  }
  for (std::uint64_t s0 = 0, current = 0; s0 < candidates; s0 += batch, current ^= 1) {
    const std::uint64_t m = std::min(batch, candidates - s0);
    const std::uint64_t m_next = s0 + m < candidates ? std::min(batch, candidates - s0 - m) : 0;
    const Drawn& d = drawn[current];
    Drawn& next = drawn[current ^ 1];
    if (m_next > 0) draw_batch(next, s0 + m, m_next);
    if (++stamp == 0) {
      seen.fill(0);
      stamp = 1;
    }
    std::uint64_t shared = 0;                // bit b: candidate b shares a particle (or a slot) with an earlier one
    for (std::uint64_t b = 0; b < m; ++b) {  // the screen
      if (b < m_next) {
        __builtin_prefetch(v + next.ks[b], 1, 3);
        __builtin_prefetch(v + next.ls[b], 1, 3);
      }
      const HandRecord& a = v[d.ks[b]];
      const HandRecord& e = v[d.ls[b]];
      const double gx = a.x - e.x, gy = a.y - e.y, gz = a.z - e.z;
      g2s[b] = gx * gx + gy * gy + gz * gz;
      const std::uint64_t sk = d.ks[b] & (slots - 1), sl = d.ls[b] & (slots - 1);
      shared |= static_cast<std::uint64_t>((seen[sk] == stamp) | (seen[sl] == stamp)) << b;
      seen[sk] = stamp;
      seen[sl] = stamp;
    }
    std::uint64_t passes = 0;  // threshold against omega_hi lane by lane, the outcomes as bits
    for (std::uint64_t k = 0; k < batch; k += SimdDouble::size)
      passes |= not_greater_bits(
                    SimdDouble::load_unaligned(&d.accept[k]) * majorant,
                    prefactor * (0.25 * xsimd::sqrt(SimdDouble::load_unaligned(&g2s[k]))) * (1.0 + rounding_margin))
                << k;
    const std::uint64_t full_test = shared | (passes & (m >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << m) - 1));
    const std::size_t passed =
        selected_directions(full_test, d.dir1, d.dir2, which, sx, sy, sz,
                            [](auto u1, auto u2, auto x, auto y, auto z) { unit_vectors(u1, u2, x, y, z); });
    // sigma-hat and g.sigma of the candidates that share no particle, from the screen's velocities, a
    // register at a time (as the stage)
    for (std::size_t e = 0; e < passed; ++e) {
      const HandRecord& a = v[d.ks[which[e]]];
      const HandRecord& f = v[d.ls[which[e]]];
      gx_passed[e] = a.x - f.x, gy_passed[e] = a.y - f.y, gz_passed[e] = a.z - f.z, g2_passed[e] = g2s[which[e]];
    }
    for (std::size_t e = passed; e % SimdDouble::size != 0; ++e)
      gx_passed[e] = gy_passed[e] = gz_passed[e] = g2_passed[e] = 1.0;
    for (std::size_t e = 0; e < passed; e += SimdDouble::size) {
      const auto at = [e](const Lanes& x) { return SimdDouble::load_unaligned(&x[e]); };
      SimdDouble x, y, z, gs;
      impact_direction_components<3>(at(gx_passed), at(gy_passed), at(gz_passed), xsimd::sqrt(at(g2_passed)), at(sx),
                                     at(sy), at(sz), x, y, z, gs);
      x.store_unaligned(&sigma_x[e]), y.store_unaligned(&sigma_y[e]), z.store_unaligned(&sigma_z[e]);
      gs.store_unaligned(&g_sigma_passed[e]);
    }
    for (std::size_t e = 0; e < passed; ++e) {  // the full test, in order
      const std::uint64_t b = which[e];
      const bool clean = ((shared >> b) & 1u) == 0;
      HandRecord& a = v[d.ks[b]];
      HandRecord& f = v[d.ls[b]];
      const double gx = a.x - f.x, gy = a.y - f.y, gz = a.z - f.z;
      const double g2 = clean ? g2s[b] : gx * gx + gy * gy + gz * gz;
      const double omega_b = prefactor * (0.25 * std::sqrt(g2));  // the mean of prefactor Theta(g.sigma) g.sigma
      if (omega_b > majorant) {
        majorant = omega_b;  // majorant exceeded: accept and update (000 sec. 3)
        ++t.majorant_updates;
      } else if (d.accept[b] * majorant > omega_b) {
        continue;
      }
      Vec3 s{sigma_x[e], sigma_y[e], sigma_z[e]};
      double g_sigma = g_sigma_passed[e];
      if (!clean) {
        const double g_norm = std::sqrt(g2);  // sigma-hat along g-hat + n
        const double hx = gx + g_norm * sx[e], hy = gy + g_norm * sy[e], hz = gz + g_norm * sz[e];
        const double inverse = 1.0 / std::sqrt(hx * hx + hy * hy + hz * hz);
        s = {inverse * hx, inverse * hy, inverse * hz};
        g_sigma = inverse * (gx * hx + gy * hy + gz * hz);
      }
      if (!(g_sigma > 0.0)) continue;                     // g + |g| n = 0: probability zero
      const double h = 0.5 * (one_plus_alpha * g_sigma);  // equal masses: mu = 1/2
      a.x -= h * s.x;                                     // 000 eq. (14)
      a.y -= h * s.y;
      a.z -= h * s.z;
      f.x += h * s.x;  // 000 eq. (15)
      f.y += h * s.y;
      f.z += h * s.z;
      ++t.collisions;
      t.twice_energy_loss += loss * g_sigma * g_sigma;
    }
  }
  omega_max = majorant;
  return t;
}

/// Whole time steps of the plain scene with hand_collide: 1/2 (N - 1) omega_max u dt candidates (the
/// fraction carried), the stored energy tracked from the losses, and the same rescaling as Dsmc (remove
/// the centre-of-mass velocity, unit stored temperature, scale into log u) when the stored energy has
/// fallen by a factor 1.25. The gas only cools, so only the lower bound is checked.
class HandHcs {
 public:
  static constexpr double rescale_factor = 1.25;  // as Dsmc

  /// `c0`: the n initial stored velocities with scale log_u; initial majorant as Dsmc's, prefactor 2 max |c| / 4.
  template <class Velocities>
  HandHcs(const Velocities& c0, std::uint64_t n, double log_u, const HandConstants& constants, const RandomStream& rng)
      : v_(n), n_(n), c_(constants), rng_(rng), log_u_(log_u) {
    double max2 = 0.0;
    for (std::uint64_t k = 0; k < n; ++k) {
      const Vec3 c = c0(k);
      v_[k] = {c.x, c.y, c.z, 0.0};
    }
    rescale();
    for (std::uint64_t k = 0; k < n; ++k)
      max2 = std::max(max2, v_[k].x * v_[k].x + v_[k].y * v_[k].y + v_[k].z * v_[k].z);
    const double max_speed = std::sqrt(max2);
    omega_max_ = c_.rate_prefactor * (0.25 * (max_speed + max_speed));  // majorant_bound<NoCollisionShift>
    rescales_ = 0;
  }

  void step(double dt) noexcept {
    const double wanted = 0.5 * static_cast<double>(n_ - 1) * omega_max_ * std::exp(log_u_) * dt + carried_;
    const double whole = std::floor(wanted);
    carried_ = wanted - whole;
    const auto candidates = static_cast<std::uint64_t>(whole);
    const HandTally t = hand_collide(v_.data(), n_, omega_max_, candidates, rng_, step_, c_);
    candidates_ += candidates;
    collisions_ += t.collisions;
    twice_energy_ -= t.twice_energy_loss;
    ++step_;
    if (twice_energy_ < reference_ / rescale_factor) rescale();
  }

  [[nodiscard]] std::uint64_t particles() const noexcept { return n_; }
  [[nodiscard]] double omega_max() const noexcept { return omega_max_; }
  [[nodiscard]] double log_u() const noexcept { return log_u_; }
  [[nodiscard]] std::uint64_t steps() const noexcept { return step_; }
  [[nodiscard]] std::uint64_t candidates() const noexcept { return candidates_; }
  [[nodiscard]] std::uint64_t collisions() const noexcept { return collisions_; }
  [[nodiscard]] std::uint64_t rescales() const noexcept { return rescales_; }

 private:
  void rescale() noexcept {
    double sx = 0.0, sy = 0.0, sz = 0.0, s2 = 0.0;
    for (std::uint64_t k = 0; k < n_; ++k) {
      const HandRecord& r = v_[k];
      sx += r.x;
      sy += r.y;
      sz += r.z;
      s2 += r.x * r.x + r.y * r.y + r.z * r.z;
    }
    const double nd = static_cast<double>(n_);
    const double cx = sx / nd, cy = sy / nd, cz = sz / nd;
    const double s = std::sqrt(3.0 * nd / (s2 - (sx * sx + sy * sy + sz * sz) / nd));
    for (std::uint64_t k = 0; k < n_; ++k) {
      HandRecord& r = v_[k];
      r.x = s * (r.x - cx);
      r.y = s * (r.y - cy);
      r.z = s * (r.z - cz);
    }
    log_u_ -= std::log(s);
    twice_energy_ = reference_ = 3.0 * nd;
    ++rescales_;
  }

  AlignedBuffer<HandRecord> v_;
  std::uint64_t n_;
  HandConstants c_;
  RandomStream rng_;
  double log_u_;
  double omega_max_ = 0.0;
  double carried_ = 0.0;
  double twice_energy_ = 0.0;
  double reference_ = 0.0;
  std::uint64_t step_ = 0;
  std::uint64_t candidates_ = 0;
  std::uint64_t collisions_ = 0;
  std::uint64_t rescales_ = 0;
};

}  // namespace granmc::perf
