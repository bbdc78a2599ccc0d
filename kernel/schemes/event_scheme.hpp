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
// Disks (Kernel::dimension = 2): the same in the plane z = 0, with |S^1| = 2 pi in place of |S^2| = 4 pi
// (pi_hat = pi rate (n - 1) U_max^lambda), xi in the plane, and e uniform on the circle; hard disks instead
// collide through an impact direction and 000's rule (collide/rate_form_scattering.hpp).
//
// The majorant, and what this code does differently from the paper's listing (docs/methods/physics.md):
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
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <span>
#include <stdexcept>
#include <tuple>
#include <type_traits>
#include <utility>

#include "kernel/collide/collision_kernel.hpp"
#include "kernel/collide/pair_coefficients.hpp"
#include "kernel/collide/rate_form_scattering.hpp"
#include "kernel/core/batch_variates.hpp"
#include "kernel/core/philox_stream.hpp"
#include "kernel/core/sampling.hpp"
#include "kernel/core/scene.hpp"
#include "kernel/core/simd.hpp"
#include "kernel/schemes/event_tallies.hpp"
#include "kernel/schemes/gas_state.hpp"
#include "kernel/schemes/initial_state.hpp"
#include "kernel/schemes/replica_in_flight.hpp"

namespace granmc {

enum class Thinning { fictitious, real, violation };

/// 001 step 2.8 for a candidate with |v_i - v_j|^2 = g2, drawn with the majorant U_max (squared: U_max2):
/// real iff threshold < ratio = |v_i - v_j| / U_max, a violation (and real) if ratio > 1. Decided on the
/// squares where the margin makes the outcome certain, so the square root and the division, whose latency
/// a mispredicted branch waited for, are computed only inside it: every outcome is the one the rounded
/// ratio gives (tests/test_event_scheme.cpp, near the boundaries).
inline Thinning thinning(double g2, double threshold, double majorant, double majorant2) noexcept {
  const double accept = threshold * majorant, accept2 = accept * accept;
  if (g2 < accept2 * (1.0 - rounding_margin)) return Thinning::fictitious;
  if (g2 > accept2 * (1.0 + rounding_margin) && g2 < majorant2 * (1.0 - rounding_margin)) return Thinning::real;
  const double ratio = std::sqrt(g2) / majorant;
  if (ratio > 1.0) return Thinning::violation;
  return threshold < ratio ? Thinning::real : Thinning::fictitious;
}

/// Real is the storage precision of the particles (run.storage; core/species_store.hpp). With
/// in_registers = false every candidate goes through `candidate`, one after the other: the reference the
/// tests hold candidates_in_simd to, bit for bit.
template <class Real, EventKernel Kernel, bool in_registers = true>
class BasicEventScheme {
  using Store = BasicSpeciesStore<Real>;
  using State = BasicGasState<Real>;
  static constexpr bool disks = Kernel::dimension == 2;

 public:
  /// From the scene's initial Maxwellian, drawn on `threads` threads (the same bits for any number).
  BasicEventScheme(const Scene& scene, std::uint64_t replica, Kernel kernel, int threads = 1)
      : BasicEventScheme(scene, replica, kernel,
                         maxwellian_state<Real>(scene, RandomStream(scene.run.seed, replica), threads)) {}

  /// From a given initial state (one species, all last-update times 0, state.time = 0).
  BasicEventScheme(const Scene& scene, std::uint64_t replica, Kernel kernel, State initial)
      : kernel_(kernel),
        rng_(scene.run.seed, replica),
        state_(std::move(initial)),
        alpha_(scene.collision.restitution[0][0]),
        pair_(pair_coefficients(scene).at(0)),
        particles_(state_.species.at(0).size()) {
    if (particles_ < 2) throw std::invalid_argument("the event scheme needs at least two particles");
    const double u = state_.scale.u();
    noise_ = 2.0 * scene.thermostat.beta / (u * u);  // 2 beta in stored units per unit time
    // pi_hat = |S^(d-1)| / 2 rate (n - 1) (u U_max)^lambda: 2 pi for spheres (001 eq. 25; U_max here in
    // stored units), pi for disks
    rate_prefactor_ = 0.5 * unit_sphere_area(Kernel::dimension) * scene.collision.rate *
                      static_cast<double>(particles_ - 1) * std::pow(u, kernel_.lambda);
    candidate_rate_ = rate_prefactor_;  // Maxwell: U_max^0 = 1, and no majorant is kept
    reset_majorant();
    prepare(batches_[0], 0);
    prepare(batches_[1], batch_size);
    for (std::size_t k = 0; k < batch_size; ++k) prefetch_pair(batches_[0], k);
  }

  [[nodiscard]] const State& state() const noexcept { return state_; }
  [[nodiscard]] const EventTally& tally() const noexcept { return tally_; }

  /// The state at a sample time (after advance_to), for a checkpoint (schemes/replica_in_flight.hpp).
  [[nodiscard]] EventSnapshot snapshot() const {
    EventSnapshot s;
    const Store& store = state_.species[0];
    s.velocities.reserve(3 * particles_);
    for (std::size_t k = 0; k < particles_; ++k) {
      const Vec3 c = store.velocity(k);
      s.velocities.insert(s.velocities.end(), {c.x, c.y, c.z});
    }
    s.time = state_.time, s.draws = draws_, s.syncs = syncs_, s.tally = tally_;
    return s;
  }

  /// Puts the replica back in the state `s` of a replica of the same scene at a sample time: there every
  /// particle was brought to the time (with noise; without, the last-update times are never read), U_max
  /// was reset from the state, and the draw batches hold the draws from the counter on.
  void restore(const EventSnapshot& s) {
    Store& store = state_.species[0];
    if (s.velocities.size() != 3 * particles_) throw std::runtime_error("a snapshot of another scene");
    const std::vector<double>& v = s.velocities;
    for (std::size_t k = 0; k < particles_; ++k) store.set_velocity(k, {v[3 * k], v[3 * k + 1], v[3 * k + 2]});
    state_.time = s.time;
    if (noise_ != 0.0) {
      for (std::size_t k = 0; k < particles_; ++k) store.set_last_update(k, s.time);
      store.restart_clock(s.time);
    }
    syncs_ = s.syncs, tally_ = s.tally;
    draw_from(s.draws);
    reset_majorant();
  }
  /// Current majorant U_max in scene velocity units.
  [[nodiscard]] double majorant() const noexcept { return majorant_ * state_.scale.u(); }

  /// Processes every candidate before t, then brings all particles to t (001 Remark 2 and step 3).
  void advance_to(double t) {
    run_candidates(t, RandomStream::counter_limit);
    end_interval(t);
  }

 private:
  template <class Scheme>
  friend class EventRounds;  // schemes/event_rounds.hpp: the candidates on several threads

  /// The candidates before t in order, up to draw `end` (excluded); whether they ended because the next one's
  /// time reached t.
  bool run_candidates(double t, std::uint64_t end) {
    Store& store = state_.species[0];
    while (draws_ < end) {
      const DrawBatch& batch = batches_[current_];
      // A register of candidates at once where the batch has one left, else one candidate. Only for a
      // kernel with fictitious candidates under noise: with Maxwell's every candidate collides, in order,
      // and the register only added work (Example 7 at 10^5: 0.95-1.01 -> 1.08-1.14 s).
      if constexpr (registers) {
        if (noise_ != 0.0 && slot_ + lanes <= batch_size) {
          const std::size_t done = candidates_in_simd(store, batch, slot_, t, end - draws_, batches_[current_ ^ 1u]);
          for (std::size_t k = 0; k < done; ++k) next_slot();
          if (done != 0) continue;
        }
      }
      const double next = state_.time + batch.wait[slot_] / candidate_rate_;  // 001 step 2.1
      if (!(next < t)) return true;
      state_.time = next;
      candidate(store, batch, slot_, next);
      next_draw();
    }
    return false;
  }

  /// After the candidates before t: the draw that reached t is discarded (the process is memoryless and restarts
  /// at t), every particle is brought to t, and U_max is set from the state.
  void end_interval(double t) {
    next_draw();
    if (!(draws_ < RandomStream::counter_limit)) throw std::runtime_error("event scheme: random counter exhausted");
    state_.time = t;
    if (noise_ != 0.0) bring_all_to(state_.species[0], t);
    ++syncs_;
    reset_majorant();
  }

  /// U_max := value, and with it pi_hat = rate_prefactor U_max^lambda (001 eq. 25): computed where U_max
  /// changes, not at every draw (a pow per candidate was a tenth of a VHS candidate's time).
  void set_majorant(double value) noexcept {
    majorant_ = value;
    majorant2_ = value * value;
    candidate_rate_ = rate_prefactor_ * std::pow(majorant_, kernel_.lambda);
  }

  /// The state-independent part of `batch_size` consecutive draws. Draw d depends only on the counter d:
  /// block 0 gives the waiting time, i and the acceptance uniform, block 1 gives j and e, blocks 2-3 the six
  /// normals of the two Brownian increments (three Box-Muller pairs). A batch is prepared while the one
  /// before it is consumed, so the pairs' records can be prefetched batch_size draws ahead of their use
  /// (prefetch_pair), and the logs and polynomials run in SIMD (core/batch_variates.hpp). The candidates
  /// still act one after the other, in draw order. With pairs_only, only i, j and wait (what a note of
  /// the candidates in a concurrent round needs, schemes/event_rounds.hpp).
  static constexpr std::size_t batch_size = 32;
  struct DrawBatch {
    std::array<std::size_t, batch_size> i{}, j{};
    std::array<double, batch_size> wait{};            // -log u of step 2.1: the waiting time is wait / rate
    std::array<double, batch_size> threshold{};       // step 2.8: real iff threshold < |v_i - v_j| / U_max
    std::array<double, batch_size> ex{}, ey{}, ez{};  // step 2.9's draw: e, or hard disks' impact variate n
    // Draw k's normals: pairs k, batch_size + k and 2 batch_size + k, so that the same component of
    // consecutive draws is contiguous (candidates_in_simd loads them a register at a time)
    std::array<double, 3 * batch_size> normal1{}, normal2{};
  };

  template <bool pairs_only = false>
  void prepare(DrawBatch& batch, std::uint64_t first) const noexcept {
    constexpr std::size_t b = batch_size;
    std::array<double, b> e1, e2;
    std::array<double, 3 * b> u1, u2;
    // Blocks 0 and 1 of draw first + k are lanes k and b + k (blocks 2 and 3 likewise in `normals`): each
    // kind of word in consecutive lanes, so that its conversions run in SIMD.
    std::array<std::uint64_t, 2 * b> step, index;
    for (std::size_t k = 0; k < 2 * b; ++k) {
      step[k] = first + k % b;
      index[k] = k / b;
    }
    const RandomBlocks<2 * b> blocks = rng_.blocks(RngPurpose::event_candidate, 0, step, index);
    const auto& w = blocks.word;
    auto words = [&](std::size_t word, std::size_t block) {
      return std::span<const std::uint32_t, b>(&w[word][block * b], b);
    };
    // Steps 2.3-2.4: i uniform, j uniform on the n - 1 others; lane by lane (uniform_indices) while
    // n < 2^32, the same values as uniform_index
    std::array<std::uint64_t, b> is, js;
    if (particles_ < (std::uint64_t{1} << 32)) {
      std::array<std::uint32_t, b> n, n_others;
      n.fill(static_cast<std::uint32_t>(particles_));
      n_others.fill(static_cast<std::uint32_t>(particles_ - 1));
      uniform_indices(words(1, 0), words(2, 0), n, is);
      uniform_indices(words(0, 1), words(1, 1), n_others, js);
    } else {
      for (std::size_t k = 0; k < b; ++k) {
        is[k] = uniform_index(w[1][k], w[2][k], particles_);
        js[k] = uniform_index(w[0][b + k], w[1][b + k], particles_ - 1);
      }
    }
    for (std::size_t k = 0; k < b; ++k) {
      batch.i[k] = is[k];
      batch.j[k] = js[k] + (js[k] >= is[k] ? 1 : 0);  // step 2.4: uniform on j != i
      batch.wait[k] = uniform_open(w[0][k]);
    }
    negative_log_in_place(std::span(batch.wait));
    if constexpr (pairs_only) return;
    for (std::size_t k = 0; k < b; ++k) {
      batch.threshold[k] = uniform_open(w[3][k]);
      e1[k] = uniform_open(w[2][b + k]);
      e2[k] = uniform_open(w[3][b + k]);
    }
    if (noise_ != 0.0) {
      for (std::size_t k = 0; k < 2 * b; ++k) index[k] = 2 + k / b;
      const RandomBlocks<2 * b> normals = rng_.blocks(RngPurpose::event_candidate, 0, step, index);
      const auto& z = normals.word;
      for (std::size_t k = 0; k < b; ++k) {  // pairs (z2[0], z2[1]), (z2[2], z2[3]), (z3[0], z3[1])
        u1[k] = uniform_open(z[0][k]);
        u2[k] = uniform_open(z[1][k]);
        u1[b + k] = uniform_open(z[2][k]);
        u2[b + k] = uniform_open(z[3][k]);
        u1[2 * b + k] = uniform_open(z[0][b + k]);
        u2[2 * b + k] = uniform_open(z[1][b + k]);
      }
    }
    kernel_.acceptance_thresholds(std::span(batch.threshold));
    scattering_variates<Kernel>(std::span<const double, b>(e1), std::span<const double, b>(e2), std::span(batch.ex),
                                std::span(batch.ey), std::span(batch.ez));
    if (noise_ != 0.0) {
      standard_normal_pairs(std::span<const double, 3 * batch_size>(u1), std::span<const double, 3 * batch_size>(u2),
                            std::span(batch.normal1), std::span(batch.normal2));
      if constexpr (disks) {  // no kick along z: the z normals of i and j (see `candidate`) are 0
        std::fill_n(&batch.normal1[b], b, 0.0);
        std::fill_n(&batch.normal2[2 * b], b, 0.0);
      }
    }
  }

  /// The records of the pair of slot k of a prepared batch, into the cache before they are needed. Each
  /// draw prefetches the pair batch_size draws ahead of it (slot k of the other batch), so the misses are
  /// spread evenly: issued for a whole batch of 16 at once, the 32 prefetches outnumber the core's
  /// outstanding misses and the last ones wait a memory latency (docs/developer-guide/performance.md,
  /// "Event scheme").
  void prefetch_pair(const DrawBatch& batch, std::size_t k) const noexcept {
    const Store& store = state_.species[0];
    store.prefetch(batch.i[k]);
    store.prefetch(batch.j[k]);
  }

  /// Moves to the next draw; when a batch is used up, the other one (already prepared) takes over and the
  /// used one is refilled with the draws after it.
  void next_draw() noexcept {
    prefetch_pair(batches_[current_ ^ 1u], slot_);
    next_slot();
  }
  /// The draws from d on: draws_ = d, with the batches prepared from there (next_slot's invariant).
  void draw_from(std::uint64_t d) noexcept {
    draws_ = d;
    slot_ = static_cast<std::size_t>(d % batch_size);
    current_ = static_cast<unsigned>((d / batch_size) % 2);
    prepare(batches_[current_], d - slot_);
    prepare(batches_[current_ ^ 1u], d - slot_ + batch_size);
  }
  /// next_draw without the prefetch (candidates_in_simd issues its own).
  void next_slot() noexcept {
    ++draws_;
    if (++slot_ < batch_size) return;
    prepare(batches_[current_], draws_ + batch_size);
    current_ ^= 1u;
    slot_ = 0;
  }

  /// 001 eq. (23) for particle k up to time t with the standard normal vector xi: v += sqrt(2 beta s) xi.
  void brownian_update(Store& store, std::size_t k, double t, const Vec3& xi) const noexcept {
    const double s = t - store.last_update(k);
    store.set_last_update(k, t);
    if (s > 0.0) store.set_velocity(k, store.velocity(k) + std::sqrt(noise_ * s) * xi);
  }

  /// Every particle to time t (001 Remark 2 and step 3). Particle k's three normals come from the block
  /// (brownian_sync, syncs_, k): two Box-Muller pairs, one value unused; computed 64 particles at a
  /// time (the last batch computes normals past the end and drops them).
  void bring_all_to(Store& store, double t) const noexcept {
    for_each_particle_normal<64>(rng_, RngPurpose::brownian_sync, 0, syncs_, 0, particles_,
                                 [&](std::size_t k, const Vec3& xi) {
                                   brownian_update(store, k, t, disks ? Vec3{xi.x, xi.y, 0.0} : xi);
                                 });
    store.restart_clock(t);
  }

  /// The candidates of slots k, k + 1, ... of the batch, as `candidate` does them one after the other, a
  /// register of them (`lanes`) at a time: the times of step 2.1, the Brownian updates of steps 2.5-2.6
  /// and the tests of steps 2.7-2.8 in SIMD, then in order the stores and, for the real candidates, steps
  /// 2.9-2.10. This holds while the candidates share no particle and U_max stays: the register is done
  /// up to the first candidate (excluded) whose particles could raise U_max at step 2.7 or whose test
  /// lies within the rounding margin (both left to `candidate`), or up to a raise at step 2.10 (included:
  /// the later times depend on the new pi_hat), or up to t_end (excluded), and at most `most`. Returns how many
  /// were done; none when the register's particles are not all different or the first is left to `candidate`.
  /// The same operations on the same values as `candidate`: the same bits (tests/test_event_scheme.cpp). The
  /// pairs of the batch `next` are prefetched a batch ahead. A follower's register in a concurrent round
  /// (schemes/event_rounds.hpp) starts at its time, keeps the records it overwrites, counts in its tally and tests
  /// against the round's U_max; where step 2.10 would raise that, it ends and sets follower->in_order.
  static constexpr std::size_t lanes = SimdDouble::size;
  static constexpr bool registers = in_registers && !Kernel::constant_rate;
  template <class Follower = void>
  std::size_t candidates_in_simd(Store& store, const DrawBatch& batch, std::size_t k, double t_end, std::uint64_t most,
                                 const DrawBatch& next, Follower* follower = nullptr) {
    static_assert(!Kernel::constant_rate, "with Maxwell's kernel the candidates go one by one (advance_to)");
    constexpr bool in_round = !std::is_void_v<Follower>;
    // Where the register starts and the U_max it tests against: the scheme's, or the follower's (the round's
    // start; the leader changes the scheme's meanwhile)
    const auto [start, rate, majorant, majorant2, reference] = [&] {
      if constexpr (in_round) {
        return std::tuple{follower->now, follower->rate, follower->majorant, follower->majorant2, follower->reference};
      } else {
        return std::tuple{state_.time, candidate_rate_, majorant_, majorant2_, reference_};
      }
    }();
    using Indices = xsimd::batch<std::uint64_t, SimdDouble::arch_type>;
    static_assert(Indices::size == lanes && sizeof(std::size_t) == sizeof(std::uint64_t));
    if (!all_different(Indices::load_unaligned(reinterpret_cast<const std::uint64_t*>(&batch.i[k])),
                       Indices::load_unaligned(reinterpret_cast<const std::uint64_t*>(&batch.j[k]))))
      return 0;
    // Step 2.1: the candidate times, added in order as `advance_to` does
    alignas(64) std::array<double, lanes> time;
    (SimdDouble::load_unaligned(&batch.wait[k]) / rate).store_aligned(time.data());
    std::size_t active = 0;
    for (double now = start; active < std::min<std::uint64_t>(lanes, most); ++active) {
      now += time[active];
      if (!(now < t_end)) break;
      time[active] = now;
    }
    if (active == 0) return 0;
    // The pairs a batch ahead, half now and half below, so that the misses do not come all at once (a
    // register stopped early prefetches some of its slots twice)
    for (std::size_t l = 0; l < lanes / 2; ++l) prefetch_pair(next, k + l);
    SimdDouble xi, yi, zi, ti, xj, yj, zj, tj;
    store.load_lanes(&batch.i[k], xi, yi, zi, ti);
    store.load_lanes(&batch.j[k], xj, yj, zj, tj);
    // Steps 2.5-2.6: v += sqrt(2 beta s) xi where s > 0 (001 eq. 23), rounded as the store rounds
    const SimdDouble t = SimdDouble::load_aligned(time.data());
    constexpr std::size_t b = batch_size;
    const auto& z1 = batch.normal1;
    const auto& z2 = batch.normal2;
    auto brownian = [&](const SimdDouble& last, SimdDouble& x, SimdDouble& y, SimdDouble& z, const double* nx,
                        const double* ny, const double* nz) {
      const SimdDouble s = t - last;
      const auto moved = s > SimdDouble(0.0);
      const SimdDouble width = xsimd::sqrt(noise_ * s);
      x = xsimd::select(moved, rounded_to<Real>(x + width * SimdDouble::load_unaligned(nx)), x);
      y = xsimd::select(moved, rounded_to<Real>(y + width * SimdDouble::load_unaligned(ny)), y);
      z = xsimd::select(moved, rounded_to<Real>(z + width * SimdDouble::load_unaligned(nz)), z);
    };
    brownian(ti, xi, yi, zi, &z1[k], &z2[k], &z1[b + k]);
    brownian(tj, xj, yj, zj, &z2[b + k], &z1[2 * b + k], &z2[2 * b + k]);
    // Steps 2.7-2.8 as bits: real, and left to `candidate` (the register stops before it)
    const SimdDouble rx(reference.x), ry(reference.y), rz(reference.z);
    auto far2 = [&](const SimdDouble& x, const SimdDouble& y, const SimdDouble& z) {
      const SimdDouble dx = x - rx, dy = y - ry, dz = z - rz;
      return dx * dx + dy * dy + dz * dz;
    };
    const SimdDouble below(raise_below(majorant2));
    const SimdDouble dx = xi - xj, dy = yi - yj, dz = zi - zj;
    const SimdDouble g2 = dx * dx + dy * dy + dz * dz;
    const SimdDouble accept = SimdDouble::load_unaligned(&batch.threshold[k]) * majorant, accept2 = accept * accept;
    const auto fictitious = g2 < accept2 * (1.0 - rounding_margin);
    const auto certain =
        (g2 > accept2 * (1.0 + rounding_margin)) & (g2 < SimdDouble(majorant2 * (1.0 - rounding_margin)));
    const std::uint64_t real = lane_bits(certain);
    const std::uint64_t stop = (std::uint64_t{1} << active) | ~lane_bits(fictitious | certain) |
                               ~lane_bits((far2(xi, yi, zi) < below) & (far2(xj, yj, zj) < below));
    for (std::size_t l = lanes / 2; l < lanes; ++l) prefetch_pair(next, k + l);
    EventTally& tally = tally_of(follower);
    std::size_t done = static_cast<std::size_t>(std::countr_zero(stop));
    // Steps 2.9-2.10 in order for the real candidates before the stop; a raise at 2.10 ends the register
    if (std::uint64_t collide = real & ((std::uint64_t{1} << done) - 1); collide != 0) {
      alignas(64) std::array<double, lanes> ax, ay, az, bx, by, bz;
      xi.store_aligned(ax.data()), yi.store_aligned(ay.data()), zi.store_aligned(az.data());
      xj.store_aligned(bx.data()), yj.store_aligned(by.data()), zj.store_aligned(bz.data());
      for (; collide != 0; collide &= collide - 1) {
        const std::size_t l = static_cast<std::size_t>(std::countr_zero(collide));
        Vec3 vi{ax[l], ay[l], az[l]}, vj{bx[l], by[l], bz[l]};
        scatter(vi, vj, batch, k + l);  // step 2.9
        vi = Store::as_stored(vi);
        vj = Store::as_stored(vj);
        ax[l] = vi.x, ay[l] = vi.y, az[l] = vi.z;
        bx[l] = vj.x, by[l] = vj.y, bz[l] = vj.z;
        ++tally.collisions;
        if constexpr (in_round) {  // step 2.10 against the round's U_max
          if (raised_majorant(vi, vj, reference, majorant, majorant2) != 0.0) {
            follower->in_order = true;
            done = l + 1;
            break;
          }
        } else if (raise_majorant(vi, vj)) {  // step 2.10
          done = l + 1;
          break;
        }
      }
      xi = SimdDouble::load_aligned(ax.data()), yi = SimdDouble::load_aligned(ay.data()),
      zi = SimdDouble::load_aligned(az.data());
      xj = SimdDouble::load_aligned(bx.data()), yj = SimdDouble::load_aligned(by.data()),
      zj = SimdDouble::load_aligned(bz.data());
    }
    if constexpr (in_round) {
      for (std::size_t l = 0; l < done; ++l) follower->keep(store, batch.i[k + l], batch.j[k + l]);
    }
    store.store_lanes(&batch.i[k], done, xi, yi, zi, t);
    store.store_lanes(&batch.j[k], done, xj, yj, zj, t);
    tally.candidates += done;
    if (done != 0) {
      if constexpr (in_round) {
        follower->now = time[done - 1];
      } else {
        state_.time = time[done - 1];
      }
    }
    return done;
  }

  /// One candidate at its time t: 001 steps 2.5-2.10, with slot k of the batch. On its own (no follower) it
  /// raises U_max at steps 2.7 and 2.10 and counts in tally_. As a follower's candidate in a concurrent round
  /// (schemes/event_rounds.hpp) it keeps the two records before it writes them, counts in the follower's tally
  /// and tests against the U_max of the round's start; where it would raise that U_max or exceed it, it stops
  /// and returns false (the round then runs in order).
  template <class Follower = void>
  bool candidate(Store& store, const DrawBatch& batch, std::size_t k, double t, Follower* follower = nullptr) {
    constexpr bool in_round = !std::is_void_v<Follower>;
    const std::size_t i = batch.i[k], j = batch.j[k];
    if constexpr (in_round) follower->keep(store, i, j);
    if (noise_ != 0.0) {  // steps 2.5-2.6
      const auto& z1 = batch.normal1;
      const auto& z2 = batch.normal2;
      constexpr std::size_t b = batch_size;
      brownian_update(store, i, t, {z1[k], z2[k], z1[b + k]});
      brownian_update(store, j, t, {z2[b + k], z1[2 * b + k], z2[2 * b + k]});
    }
    EventTally& tally = tally_of(follower);
    ++tally.candidates;
    Vec3 vi = store.velocity(i), vj = store.velocity(j);
    if constexpr (!Kernel::constant_rate) {
      const auto [drawn_with, drawn_with2] = [&] {
        if constexpr (in_round) {
          return std::pair{follower->majorant, follower->majorant2};
        } else {
          return std::pair{majorant_, majorant2_};
        }
      }();
      if (!raise_majorant(vi, vj, follower)) return false;                              // step 2.7
      switch (thinning(norm2(vi - vj), batch.threshold[k], drawn_with, drawn_with2)) {  // step 2.8
        case Thinning::fictitious:
          return true;
        case Thinning::violation:
          if constexpr (in_round) return false;
          ++tally_.majorant_violations;
          break;
        case Thinning::real:
          break;
      }
    }
    scatter(vi, vj, batch, k);  // step 2.9
    store.set_velocity(i, vi);
    store.set_velocity(j, vj);
    ++tally.collisions;
    // step 2.10, on the velocities as stored (rounded, with float storage), which later candidates read
    if constexpr (!Kernel::constant_rate) return raise_majorant(store.velocity(i), store.velocity(j), follower);
    return true;
  }

  /// Where a candidate counts: tally_, or a follower's own tally in a concurrent round.
  template <class Follower>
  EventTally& tally_of(Follower* follower) noexcept {
    if constexpr (std::is_void_v<Follower>) {
      return tally_;
    } else {
      return follower->tally;
    }
  }

  /// Step 2.9 with slot k's draw (collide/rate_form_scattering.hpp).
  void scatter(Vec3& vi, Vec3& vj, const DrawBatch& batch, std::size_t k) const noexcept {
    rate_form_scattering<Kernel>(vi, vj, {batch.ex[k], batch.ey[k], batch.ez[k]}, alpha_, pair_);
  }

  /// Steps 2.7 and 2.10: U_max := max(U_max, 2 |v_i - V|, 2 |v_j - V|); whether it rose.
  bool raise_majorant(const Vec3& vi, const Vec3& vj) noexcept {
    const double bound = raised_majorant(vi, vj, reference_, majorant_, majorant2_);
    if (bound == 0.0) return false;
    set_majorant(bound);
    ++tally_.majorant_updates;
    return true;
  }
  /// Steps 2.7 and 2.10 in `candidate`: on its own, raise_majorant, and go on (true); a follower's candidate goes
  /// on only if it leaves the round's U_max as it is.
  template <class Follower>
  bool raise_majorant(const Vec3& vi, const Vec3& vj, Follower* follower) noexcept {
    if constexpr (std::is_void_v<Follower>) {
      raise_majorant(vi, vj);
      return true;
    } else {
      return raised_majorant(vi, vj, follower->reference, follower->majorant, follower->majorant2) == 0.0;
    }
  }
  /// 2 max(|v_i - V|, |v_j - V|) where it exceeds U_max = majorant (majorant2 its square), else 0. The square
  /// root is taken only when the squares are within the rounding margin of (U_max / 2)^2 or above it.
  static double raised_majorant(const Vec3& vi, const Vec3& vj, const Vec3& reference, double majorant,
                                double majorant2) noexcept {
    const double far2 = std::max(norm2(vi - reference), norm2(vj - reference));
    if (far2 < raise_below(majorant2)) return 0.0;
    const double bound = 2.0 * std::sqrt(far2);
    return bound > majorant ? bound : 0.0;
  }
  /// |v - V|^2 below this cannot raise the U_max whose square is majorant2.
  static double raise_below(double majorant2) noexcept { return 0.25 * majorant2 * (1.0 - rounding_margin); }

  /// V := bulk velocity, U_max := 2 max_j |v_j - V| (001 steps 1.3-1.4), with every particle current.
  void reset_majorant() noexcept {
    if constexpr (Kernel::constant_rate) return;
    const Store& store = state_.species[0];
    Vec3 sum;
    store.for_each_velocity([&](const Vec3& c) { sum += c; });
    reference_ = (1.0 / static_cast<double>(particles_)) * sum;
    double max2 = 0.0;
    store.for_each_velocity([&](const Vec3& c) { max2 = std::max(max2, norm2(c - reference_)); });
    set_majorant(2.0 * std::sqrt(max2));
  }

  Kernel kernel_;
  RandomStream rng_;
  State state_;
  double alpha_;
  PairCoefficients pair_;  // hard disks: 000's rule for two unit masses
  std::size_t particles_;
  double noise_ = 0.0;                // 2 beta / u^2
  double rate_prefactor_ = 0.0;       // pi_hat / U_max^lambda
  double majorant_ = 0.0;             // U_max, stored units
  double majorant2_ = 0.0;            // U_max^2
  double candidate_rate_ = 0.0;       // pi_hat, per unit time
  Vec3 reference_;                    // V of the majorant, stored units
  std::uint64_t draws_ = 0;           // waiting-time draws so far (the random counter)
  std::uint64_t syncs_ = 0;           // sample-time updates so far
  std::array<DrawBatch, 2> batches_;  // the draws from draws_ on: slot_ of batches_[current_], then the other
  unsigned current_ = 0;
  std::size_t slot_ = 0;
  EventTally tally_;
};

/// Double storage, the default.
template <class Kernel>
using EventScheme = BasicEventScheme<double, Kernel>;

}  // namespace granmc
