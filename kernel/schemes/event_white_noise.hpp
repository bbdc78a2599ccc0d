#pragma once
// The time-step-free scheme for the uniformly heated inelastic Boltzmann equation (001 sec. 4), one
// replica of one species:  df/dt - beta Lap_v f = gamma Q_alpha(f)  (001 eq. 1), with B = rate |u|^lambda.
//
// Particles are (v_j, t_j): t_j is the time of the last lazy update (SpeciesStore::last_update), so white
// noise costs nothing between a particle's collisions. Candidates come at the constant majorant rate
//   pi_hat = 2 pi rate (n - 1) U_max^lambda                                        (001 eq. 25)
// with exponential waiting times; a candidate is an ordered pair i != j chosen uniformly; both partners are
// first brought to the candidate time by Brownian motion, v += sqrt(2 beta (t - t_j)) xi (001 eq. 23);
// the candidate is real with probability (|v_i - v_j| / U_max)^lambda (001 eq. 26) and then collides by
// 001 eq. (4). At each sample time every particle is brought to that time (001 Remark 2).
//
// The majorant, and what this code does differently from the paper's listing (docs/physics.md):
//  - U_max bounds |v_i - v_j| by |v_i - V| + |v_j - V| for a fixed reference velocity V, so the raise of
//    steps 2.7 and 2.10 is U_max = max(U_max, 2 |v_i - V|, 2 |v_j - V|); the printed listing omits the 2.
//  - A candidate is accepted against the U_max its waiting time was drawn with (thinning is exact only
//    then); the raise applies from the next waiting time. The listing tests against the raised value,
//    which lowers the collision rate of that candidate.
//  - Brownian motion is unbounded, so a relative speed above that U_max is possible in principle; such a
//    candidate collides (probability 1) and is counted as a majorant violation, which the summary reports.
//  - At each sample time, with all particles current, V := the bulk velocity and U_max := 2 max |v_j - V|
//    (a function of the present state, so exact): the majorant follows a cooling gas down.
// Velocities are stored in units of u = sqrt(T(0)) (GasState::scale, fixed here).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>
#include <utility>

#include "kernel/collide/isotropic_scattering.hpp"
#include "kernel/core/philox_stream.hpp"
#include "kernel/core/sampling.hpp"
#include "kernel/core/scene.hpp"
#include "kernel/schemes/gas_state.hpp"
#include "kernel/schemes/initial_state.hpp"

namespace granmc {

struct EventTally {
  std::uint64_t candidates = 0;          // candidate pairs (real + fictitious collisions)
  std::uint64_t collisions = 0;          // real collisions
  std::uint64_t majorant_updates = 0;    // raises of U_max at steps 2.7 and 2.10
  std::uint64_t majorant_violations = 0; // candidates with |v_i - v_j| above the U_max they were drawn with
};

template <class Kernel>
class EventWhiteNoise {
 public:
  /// From the scene's initial Maxwellian.
  EventWhiteNoise(const Scene& scene, std::uint64_t replica, Kernel kernel)
      : EventWhiteNoise(scene, replica, kernel, maxwellian_state(scene, RandomStream(scene.run.seed, replica))) {}

  /// From a given initial state (one species, all last-update times 0, state.time = 0).
  EventWhiteNoise(const Scene& scene, std::uint64_t replica, Kernel kernel, GasState initial)
      : kernel_(kernel),
        rng_(scene.run.seed, replica),
        state_(std::move(initial)),
        alpha_(scene.collision.restitution[0][0]),
        particles_(state_.species.at(0).size()) {
    if (particles_ < 2) throw std::invalid_argument("the event scheme needs at least two particles");
    const double u = state_.scale.u();
    noise_ = 2.0 * scene.thermostat.beta / (u * u);  // 2 beta in stored units per unit time
    // pi_hat = 2 pi rate (n - 1) (u U_max)^lambda  (001 eq. 25; U_max here in stored units)
    rate_prefactor_ = 2.0 * std::numbers::pi * scene.collision.rate * static_cast<double>(particles_ - 1) *
                      std::pow(u, kernel_.lambda());
    reset_majorant();
  }

  [[nodiscard]] const GasState& state() const noexcept { return state_; }
  [[nodiscard]] const EventTally& tally() const noexcept { return tally_; }
  /// Current majorant U_max in scene velocity units.
  [[nodiscard]] double majorant() const noexcept { return majorant_ * state_.scale.u(); }

  /// Processes every candidate before t, then brings all particles to t (001 Remark 2 and step 3).
  void advance_to(double t) {
    SpeciesStore& store = state_.species[0];
    // The pair of draw d depends only on the counter d, so the pairs of the next `lookahead` draws are
    // computed ahead and their records prefetched: the candidates still act one after the other, in order,
    // and the result is the same as without the look-ahead; only the memory loads overlap.
    for (std::uint64_t d = draws_; d < draws_ + lookahead; ++d) prepare(d);
    for (;;) {
      const Draw& draw = ahead_[draws_ % lookahead];
      const double next = state_.time - std::log(uniform_open(draw.b0[0])) / candidate_rate();  // 001 step 2.1
      if (!(next < t)) break;  // memoryless: the draw is discarded and the process restarts at t
      state_.time = next;
      candidate(store, draw);
      prepare(draws_ + lookahead);  // reuses this draw's slot
      ++draws_;
    }
    ++draws_;
    if (!(draws_ < RandomStream::counter_limit)) throw std::runtime_error("event scheme: random counter exhausted");
    state_.time = t;
    if (noise_ != 0.0)
      for (std::size_t k = 0; k < particles_; ++k)
        brownian_update(store, k, t, normal_vector(rng_.block(RngPurpose::brownian_sync, 0, syncs_, k)));
    ++syncs_;
    reset_majorant();
  }

 private:
  double candidate_rate() const noexcept {
    if constexpr (Kernel::constant_rate) return rate_prefactor_;
    else return rate_prefactor_ * std::pow(majorant_, kernel_.lambda());
  }

  /// Draw d: block 0 gives the waiting time, i and the acceptance uniform, block 1 gives j and e.
  struct Draw {
    RandomBlock b0, b1;
    std::size_t i = 0, j = 0;
  };
  static constexpr std::uint64_t lookahead = 16;

  void prepare(std::uint64_t d) noexcept {
    Draw& draw = ahead_[d % lookahead];
    draw.b0 = rng_.block(RngPurpose::event_candidate, 0, d, 0);
    draw.b1 = rng_.block(RngPurpose::event_candidate, 0, d, 1);
    draw.i = uniform_index(draw.b0[1], draw.b0[2], particles_);              // step 2.3
    const std::size_t j = uniform_index(draw.b1[0], draw.b1[1], particles_ - 1);
    draw.j = j + (j >= draw.i ? 1 : 0);                                      // step 2.4: uniform on j != i
    state_.species[0].prefetch(draw.i);
    state_.species[0].prefetch(draw.j);
  }

  /// 001 eq. (23) for particle k up to time t with the standard normal vector xi: v += sqrt(2 beta s) xi.
  void brownian_update(SpeciesStore& store, std::size_t k, double t, const Vec3& xi) const noexcept {
    const double s = t - store.last_update(k);
    store.set_last_update(k, t);
    if (s > 0.0) store.set_velocity(k, store.velocity(k) + std::sqrt(noise_ * s) * xi);
  }

  /// Three standard normals from the four words of a block (two Box-Muller pairs, one value unused).
  static Vec3 normal_vector(const RandomBlock& z) noexcept {
    double x, y, w, unused;
    standard_normal_pair(uniform_open(z[0]), uniform_open(z[1]), x, y);
    standard_normal_pair(uniform_open(z[2]), uniform_open(z[3]), w, unused);
    return {x, y, w};
  }

  /// One candidate at state_.time: 001 steps 2.5-2.10. Blocks 2-3 of the draw give the six normals of the
  /// two Brownian increments (three Box-Muller pairs).
  void candidate(SpeciesStore& store, const Draw& draw) {
    const std::size_t i = draw.i, j = draw.j;
    const RandomBlock& b0 = draw.b0;
    const RandomBlock& b1 = draw.b1;
    const double t = state_.time;
    if (noise_ != 0.0) {  // steps 2.5-2.6
      const RandomBlock z0 = rng_.block(RngPurpose::event_candidate, 0, draws_, 2);
      const RandomBlock z1 = rng_.block(RngPurpose::event_candidate, 0, draws_, 3);
      double n[6];
      standard_normal_pair(uniform_open(z0[0]), uniform_open(z0[1]), n[0], n[1]);
      standard_normal_pair(uniform_open(z0[2]), uniform_open(z0[3]), n[2], n[3]);
      standard_normal_pair(uniform_open(z1[0]), uniform_open(z1[1]), n[4], n[5]);
      brownian_update(store, i, t, {n[0], n[1], n[2]});
      brownian_update(store, j, t, {n[3], n[4], n[5]});
    }
    ++tally_.candidates;
    Vec3 vi = store.velocity(i), vj = store.velocity(j);
    if constexpr (!Kernel::constant_rate) {
      const double drawn_with = majorant_;
      raise_majorant(vi, vj);                                                 // step 2.7
      const double ratio = norm(vi - vj) / drawn_with;
      if (ratio > 1.0) ++tally_.majorant_violations;
      else if (!(uniform_open(b0[3]) < kernel_.acceptance(ratio))) return;  // step 2.8: fictitious
    }
    isotropic_scattering(vi, vj, unit_vector(uniform_open(b1[2]), uniform_open(b1[3])), alpha_);  // step 2.9
    store.set_velocity(i, vi);
    store.set_velocity(j, vj);
    ++tally_.collisions;
    if constexpr (!Kernel::constant_rate) raise_majorant(vi, vj);            // step 2.10
  }

  void raise_majorant(const Vec3& vi, const Vec3& vj) noexcept {
    const double bound = 2.0 * std::sqrt(std::max(norm2(vi - reference_), norm2(vj - reference_)));
    if (bound > majorant_) {
      majorant_ = bound;
      ++tally_.majorant_updates;
    }
  }

  /// V := bulk velocity, U_max := 2 max_j |v_j - V| (001 steps 1.3-1.4), with every particle current.
  void reset_majorant() noexcept {
    if constexpr (Kernel::constant_rate) return;
    const SpeciesStore& store = state_.species[0];
    Vec3 sum;
    store.for_each_velocity([&](const Vec3& c) { sum += c; });
    reference_ = (1.0 / static_cast<double>(particles_)) * sum;
    double max2 = 0.0;
    store.for_each_velocity([&](const Vec3& c) { max2 = std::max(max2, norm2(c - reference_)); });
    majorant_ = 2.0 * std::sqrt(max2);
  }

  Kernel kernel_;
  RandomStream rng_;
  GasState state_;
  double alpha_;
  std::size_t particles_;
  double noise_ = 0.0;           // 2 beta / u^2
  double rate_prefactor_ = 0.0;  // pi_hat / U_max^lambda
  double majorant_ = 0.0;        // U_max, stored units
  Vec3 reference_;               // V of the majorant, stored units
  std::uint64_t draws_ = 0;      // waiting-time draws so far (the random counter)
  std::uint64_t syncs_ = 0;      // sample-time updates so far
  Draw ahead_[lookahead];        // the next draws' random blocks and pairs
  EventTally tally_;
};

}  // namespace granmc
