#pragma once
// The collision backend of one system spread over several ranks (`--spread particles`; docs/developer-guide/scaling.md,
// "The spread stage"): for a system larger than one machine's memory. The time stepper
// (schemes/dsmc.hpp) is the same as in one process; this backend holds the particles, the collision stage
// and the sums over particles. One species, smooth or rough (the spins of a partner held elsewhere travel with
// its velocity); the effects that act on particles act on this rank's part.
//
// Rank r holds the particles of chunks [C r / R, C (r + 1) / R) of `chunk` consecutive global indices.
// Every rank draws the whole step's candidate list from the counter-based stream, the same words as the
// one-process stage (schemes/collision_stage.hpp: indices from block 2s, direction and acceptance from
// block 2s + 1), and sorts the candidates into waves: a candidate's wave is one more than the latest wave
// of an earlier candidate that shares a particle with it. Candidates of one wave share no particle, so
// they commute; every particle sees its candidates in list order, as in the one-process loop. In a wave
// the owner of k does the candidate; a partner l held elsewhere comes in one exchange and goes back in a
// second.
//
// What differs from the batched backend (schemes/batched_backend.hpp), and why the law is the same:
//  - The majorant is the step's: a candidate above it collides (the paper's rule, 000 sec. 3) and the
//    raise takes effect at the next step instead of the next candidate. Without a raise (the rule
//    thereafter; `make stability`) the chain is the one-process chain; at a raise both are the paper's
//    approximation, counted in majorant_updates.
//  - Sums over particles are compensated per chunk and then over the chunks in order; the energy loss of
//    a step is summed over the candidates in list order. Both are the same bits for any number of ranks
//    (tests/test_mpi.cpp), but not the bits of the batched backend, which sums over all particles at once.
//    The velocities then differ in their last bits only, so both stages make the same collisions unless
//    a rounding flips an acceptance (tests/test_spread.cpp: the same collisions over a 25-fold cooling).
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

#include "kernel/collide/impact_direction.hpp"
#include "kernel/collide/inelastic_rule.hpp"
#include "kernel/collide/pair_coefficients.hpp"
#include "kernel/collide/rough_rule.hpp"
#include "kernel/core/philox_stream.hpp"
#include "kernel/core/ranks.hpp"
#include "kernel/core/sampling.hpp"
#include "kernel/core/scene.hpp"
#include "kernel/core/species_store.hpp"
#include "kernel/effects/step_context.hpp"
#include "kernel/observe/compensated_sum.hpp"
#include "kernel/observe/gas_observation.hpp"
#include "kernel/observe/speed_histogram.hpp"
#include "kernel/schemes/collision_stage.hpp"
#include "kernel/schemes/gas_state.hpp"
#include "kernel/schemes/initial_state.hpp"

namespace granmc {

/// Candidates drawn and ordered at a time: a step is done segment after segment, so a rank's memory for
/// the candidate list stays about spread_candidate_bytes x spread_segment (31 MB) whatever N and R
/// (indices, owners, waves and losses 36 bytes, the queue up to 32, the table of latest waves 48).
inline constexpr std::size_t spread_segment = std::size_t{1} << 18;
inline constexpr std::size_t spread_candidate_bytes = 120;

class RankWaveBackend {
 public:
  /// Particles per partial sum; a multiple of every batch of the stream (64).
  static constexpr std::size_t chunk = 4096;
  static constexpr std::size_t segment = spread_segment;

  RankWaveBackend(const Scene& scene, const Ranks& ranks)
      : ranks_(ranks),
        me_(ranks.rank()),
        size_(ranks.size()),
        n_(static_cast<std::size_t>(scene.species.at(0).particles)),
        mass_(scene.species[0].mass) {
    if (scene.species.size() != 1) throw std::invalid_argument("a system spread over ranks has one species");
    if (n_ < 2) throw std::invalid_argument("a system spread over ranks needs at least two particles");
    chunks_ = (n_ + chunk - 1) / chunk;
    const auto r = static_cast<std::size_t>(me_), size = static_cast<std::size_t>(size_);
    first_chunk_ = chunks_ * r / size;
    lo_ = std::min(n_, first_chunk_ * chunk);
    hi_ = std::min(n_, chunks_ * (r + 1) / size * chunk);
  }

  /// Waves of the steps so far (the sequential depth of the collision stage over ranks).
  [[nodiscard]] std::uint64_t waves() const noexcept { return waves_; }

  /// This rank's part of the Maxwellian start of schemes/initial_state.cpp, particle k from the same block
  /// (000 eq. 13), with the mean of all particles removed unless initial.zero_momentum is false.
  template <class Real>
  BasicGasState<Real> initial_state(const Scene& scene, const RandomStream& rng) const {
    BasicGasState<Real> state;
    state.species.emplace_back(hi_ - lo_);
    state.scale.log_u = 0.5 * std::log(scene.initial_temperature);
    maxwellian_velocities(state.species[0], rng, 0, lo_, 1.0 / std::sqrt(mass_), scene.run.dimension);
    if (scene.initial_zero_momentum) {
      const Vec3 mean = (1.0 / static_cast<double>(n_)) * moments_about(state.species[0], {}).sum_c;
      state.species[0].for_each_velocity([&](Vec3& c) { c -= mean; });
    }
    if (rough(scene.collision)) maxwellian_spins(state.species[0], rng, 0, lo_, scene, mass_);
    return state;
  }

  /// The moments of all particles about the origin, summed over the ranks.
  template <class Real>
  std::vector<SpeciesMoments> moments(const BasicGasState<Real>& state) const {
    return {moments_about(state.species[0], {})};
  }

  /// The largest |c|^2 over all ranks.
  template <class Store>
  double largest_speed2(const Store& store) const {
    double max2 = 0.0;
    store.for_each_velocity([&](const Vec3& c) { max2 = std::max(max2, norm2(c)); });
    return ranks_.max(max2);
  }

  /// The step's candidates of the one pair, segment after segment, against the majorant omega_max[0] of the
  /// step; the raise to the largest omega above it takes effect at the next step.
  template <class Kernel, class Shift, class Real>
  void collide(BasicGasState<Real>& state, std::span<const PairCoefficients> pairs, std::span<double> omega_max,
               std::span<const std::uint64_t> candidates, const RandomStream& rng, std::span<CollisionTally> tallies,
               const Kernel& kernel, const Shift&) {
    static_assert(!Shift::active, "no shear over ranks (setup/run_plan.hpp, spread_refusal)");
    const std::size_t count = candidates[0];
    double counts[2] = {0.0, 0.0};  // collisions, candidates above the majorant (this rank's)
    double above = 0.0;             // the largest omega above the majorant
    std::uint32_t waves = 0;
    CollisionTally& tally = tallies[0];
    for (std::size_t first = 0; first < count; first += segment)
      waves += collide_segment(state.species[0], state.step, rng, kernel, pairs[0], omega_max[0], first,
                               std::min(segment, count - first), tally.twice_energy_loss, counts, above);
    ranks_.sum(counts);
    tally.candidates = count;
    tally.collisions = static_cast<std::uint64_t>(counts[0]);
    tally.majorant_updates = static_cast<std::uint64_t>(counts[1]);
    omega_max[0] = std::max(omega_max[0], ranks_.max(above));
    waves_ += waves;
  }

  /// An effect over the step: one that acts on particles acts on this rank's part chunk by chunk
  /// (apply_range, the same random words per global particle index), its energy change summed per chunk,
  /// then over the chunks in order; the others (the Gaussian thermostat moves the velocity scale) as they are.
  template <class Effect, class Real>
  double apply(const Effect& effect, BasicGasState<Real>& state, const StepContext& step) const {
    if constexpr (!Effect::acts_on_particles) {
      return effect.apply(state, step);
    } else {
      static_assert(chunk % Effect::batch == 0, "a chunk is whole batches of the effect's random words");
      return sum_over_chunks<1>([&](std::size_t from, std::size_t to) {
        CompensatedSum change;
        effect.apply_range(state.species[0], from, to, lo_, 0, state, step, change);
        return std::array<double, 1>{change.value()};
      })[0];
    }
  }

  /// Appends one observation (every rank gets the same series); returns the totals it summed.
  template <class Real>
  GasTotals observe(const Scene& scene, const BasicGasState<Real>& state, ReplicaSeries& series, bool histogram) const {
    const SpeciesMoments origin = moments_about(state.species[0], {});
    const Vec3 flow = (1.0 / static_cast<double>(n_)) * origin.sum_c;
    const SpeciesMoments about_flow = moments_about(state.species[0], flow);
    const Observed o = record_observation(scene, state.scale, {origin}, {about_flow}, series);
    if (rough(scene.collision))  // not has_spins(): a rank may hold no particle, and the sums are collective
      record_spin_observation(scene, state.scale, 0, spin_moments_about(state.species[0], flow), about_flow.mean_c2(),
                              series.species[0]);
    if (histogram) {
      std::vector<double> counts(static_cast<std::size_t>(scene.histogram.shells), 0.0);
      add_speeds(state.species[0], histogram_speed_unit(scene, state.scale, o.theta_mixture), scene.histogram.radius,
                 counts);
      ranks_.sum(counts);  // whole numbers: exact in any order
      std::vector<double>& total = series.species[0].speed_counts;
      total.resize(counts.size(), 0.0);
      for (std::size_t s = 0; s < counts.size(); ++s) total[s] += counts[s];
      ++series.histogram_samples;
    }
    return o.totals;
  }

 private:
  /// A candidate in wave order: its particles, their ranks, and j, its position in the segment's list.
  struct Queued {
    std::uint64_t k, l;
    int rk, rl;
    std::size_t j;
  };

  [[nodiscard]] int owner(std::uint64_t k) const noexcept {
    // the rank whose chunks hold k: the largest r with floor(chunks r / R) <= k / chunk
    const std::uint64_t c = k / chunk, size = static_cast<std::uint64_t>(size_);
    std::uint64_t r = (c * size) / chunks_;
    while (r + 1 < size && chunks_ * (r + 1) / size <= c) ++r;
    while (chunks_ * r / size > c) --r;
    return static_cast<int>(r);
  }

  /// Values of this rank's chunks (per_chunk(from, to) over its particles [from, to) of a chunk), summed over the
  /// ranks and then over all chunks in order, compensated: the same bits for any number of ranks.
  template <std::size_t fields, class PerChunk>
  std::array<double, fields> sum_over_chunks(const PerChunk& per_chunk) const {
    std::vector<double> parts(fields * chunks_, 0.0);
    for (std::size_t c = first_chunk_; c * chunk < hi_; ++c) {
      const std::array<double, fields> v = per_chunk(c * chunk - lo_, std::min(hi_, (c + 1) * chunk) - lo_);
      std::copy(v.begin(), v.end(), parts.begin() + static_cast<std::ptrdiff_t>(fields * c));
    }
    ranks_.sum(parts);
    CompensatedSum total[fields];
    for (std::size_t c = 0; c < chunks_; ++c)
      for (std::size_t f = 0; f < fields; ++f) total[f].add(parts[fields * c + f]);
    std::array<double, fields> values;
    for (std::size_t f = 0; f < fields; ++f) values[f] = total[f].value();
    return values;
  }

  /// Moments of all particles about `centre`.
  template <class Store>
  SpeciesMoments moments_about(const Store& store, const Vec3& centre) const {
    const std::array<double, 6> t = sum_over_chunks<6>([&](std::size_t from, std::size_t to) {
      const SpeciesMoments m = species_moments(store, centre, from, to);
      return std::array<double, 6>{m.sum_c2, m.sum_c4, m.sum_c6, m.sum_c.x, m.sum_c.y, m.sum_c.z};
    });
    SpeciesMoments m;
    m.particles = n_;
    m.sum_c2 = t[0];
    m.sum_c4 = t[1];
    m.sum_c6 = t[2];
    m.sum_c = {t[3], t[4], t[5]};
    return m;
  }

  /// Spin moments of all particles (rough particles), the velocities about `centre`.
  template <class Store>
  SpinMoments spin_moments_about(const Store& store, const Vec3& centre) const {
    const std::array<double, 3> t = sum_over_chunks<3>([&](std::size_t from, std::size_t to) {
      const SpinMoments m = spin_moments(store, centre, from, to);
      return std::array<double, 3>{m.sum_s2, m.sum_s4, m.sum_c2_s2};
    });
    return {n_, t[0], t[1], t[2]};
  }

  /// Candidates [first, first + m) of the step drawn (the same words on every rank), given their owners and
  /// waves, and those that touch this rank's particles put in queue_ in wave order (list order within a wave).
  /// Returns where each wave w = 1..W starts in queue_ (start[W + 1] is its end), W + 2 values.
  std::vector<std::size_t> order_into_waves(std::uint64_t step, const RandomStream& rng, std::size_t first,
                                            std::size_t m) {
    k_.resize(m);
    l_.resize(m);
    rk_.resize(m);
    rl_.resize(m);
    wave_.resize(m);
    latest_.reset(2 * m);
    std::uint32_t waves = 0;
    constexpr std::size_t batch = 64;
    std::array<std::uint64_t, batch> steps, index;
    steps.fill(step);
    for (std::size_t j0 = 0; j0 < m; j0 += batch) {
      for (std::size_t b = 0; b < batch; ++b) index[b] = 2 * (first + j0 + b);  // block 2s (past the end: unused)
      const RandomBlocks<batch> w = rng.blocks(RngPurpose::collision_pair, 0, steps, index);
      const std::size_t in_batch = std::min(batch, m - j0);
      for (std::size_t b = 0; b < in_batch; ++b) {
        const std::size_t j = j0 + b;
        k_[j] = uniform_index(w.word[0][b], w.word[1][b], n_);
        l_[j] = uniform_index(w.word[2][b], w.word[3][b], n_ - 1);
        l_[j] += static_cast<std::uint64_t>(l_[j] >= k_[j]);
        rk_[j] = owner(k_[j]);
        rl_[j] = owner(l_[j]);
        latest_.prefetch(k_[j]);  // the table is random access: its loads of a batch overlap
        latest_.prefetch(l_[j]);
      }
      for (std::size_t j = j0; j < j0 + in_batch; ++j) {
        std::uint32_t& wk = latest_[k_[j]];
        std::uint32_t& wl = latest_[l_[j]];
        wave_[j] = std::max(wk, wl) + 1;
        wk = wl = wave_[j];
        waves = std::max(waves, wave_[j]);
      }
    }
    // The candidates that touch this rank's particles (about 2/R of them; the waves needed all), sorted by
    // wave (list order within a wave) into one array that the passes below read front to back.
    auto here = [&](std::size_t j) { return rk_[j] == me_ || rl_[j] == me_; };
    std::vector<std::size_t> start(waves + 2, 0);
    for (std::size_t j = 0; j < m; ++j) start[wave_[j] + 1] += here(j) ? 1 : 0;
    for (std::uint32_t w = 1; w <= waves; ++w) start[w + 1] += start[w];
    queue_.resize(start[waves + 1]);
    for (std::size_t j = 0; j < m; ++j)
      if (here(j)) queue_[start[wave_[j]]++] = {k_[j], l_[j], rk_[j], rl_[j], j};
    for (std::uint32_t w = waves; w >= 1; --w) start[w] = start[w - 1];  // back to the first of each wave
    return start;
  }

  /// Candidates [first, first + m) of the step: drawn, given their owners and waves (the same on every rank),
  /// then done wave by wave. Adds their energy losses to `loss_sum` in list order (as the one-process stage
  /// sums them); returns the number of waves.
  template <class Kernel, class Store>
  std::uint32_t collide_segment(Store& store, std::uint64_t step, const RandomStream& rng, const Kernel& kernel,
                                const PairCoefficients& pair, double omega_max, std::size_t first, std::size_t m,
                                double& loss_sum, double (&counts)[2], double& above) {
    const std::vector<std::size_t> start = order_into_waves(step, rng, first, m);
    const auto waves = static_cast<std::uint32_t>(start.size() - 2);
    constexpr bool spins = rough_kernel<Kernel>;  // a partner's spin travels with its velocity
    constexpr std::size_t width = spins ? 6 : 3;  // doubles per partner in an exchange

    std::vector<double> loss(m, 0.0);  // 2 (energy loss) of each candidate, filled by the owner of k
    const int me = me_;
    const auto R = static_cast<std::size_t>(size_);
    std::vector<std::vector<double>> out(R), in(R);
    std::vector<std::size_t> read(R);
    std::vector<std::size_t> own;    // this rank's candidates of the wave (positions in queue_)
    std::vector<RandomBlock> words;  // their blocks 2s + 1
    auto expect = [&](std::size_t from, std::size_t to, bool doing_k) {  // sizes both sides know
      for (auto& b : in) b.clear();
      for (std::size_t i = from; i < to; ++i) {
        const Queued& c = queue_[i];
        if (doing_k && c.rk == me && c.rl != me)
          in[static_cast<std::size_t>(c.rl)].resize(in[static_cast<std::size_t>(c.rl)].size() + width);
        if (!doing_k && c.rl == me && c.rk != me)
          in[static_cast<std::size_t>(c.rk)].resize(in[static_cast<std::size_t>(c.rk)].size() + width);
      }
      std::fill(read.begin(), read.end(), 0);
    };
    for (std::uint32_t w = 1; w <= waves; ++w) {
      const std::size_t from = start[w], to = start[w + 1];
      for (auto& b : out) b.clear();
      own.clear();
      for (std::size_t i = from; i < to; ++i) {  // partners held here for candidates done elsewhere
        const Queued& c = queue_[i];
        if (c.rl == me && c.rk != me) {
          push(out[static_cast<std::size_t>(c.rk)], store.velocity(c.l - lo_));
          if constexpr (spins) push(out[static_cast<std::size_t>(c.rk)], store.spin(c.l - lo_));
        }
        if (c.rk == me) own.push_back(i);
      }
      expect(from, to, true);
      ranks_.exchange(out, in);
      for (auto& b : out) b.clear();
      second_blocks(rng, step, first, own, words);
      constexpr std::size_t ahead = 16;  // records prefetched this many candidates ahead
      for (std::size_t o = 0; o < std::min(ahead, own.size()); ++o) prefetch(store, queue_[own[o]]);
      for (std::size_t o = 0; o < own.size(); ++o) {
        if (o + ahead < own.size()) prefetch(store, queue_[own[o + ahead]]);
        const Queued& c = queue_[own[o]];
        const bool local = c.rl == me;
        const auto from = static_cast<std::size_t>(c.rl);
        Vec3 vk = store.velocity(c.k - lo_), sk, sl;
        Vec3 vl = local ? store.velocity(c.l - lo_) : pull(in[from], read[from]);
        if constexpr (spins) {
          sk = store.spin(c.k - lo_);
          sl = local ? store.spin(c.l - lo_) : pull(in[from], read[from]);
        }
        loss[c.j] = collide_candidate(words[o], vk, vl, sk, sl, kernel, pair, omega_max, counts, above);
        store.set_velocity(c.k - lo_, vk);
        if constexpr (spins) store.set_spin(c.k - lo_, sk);
        if (local) {
          store.set_velocity(c.l - lo_, vl);
          if constexpr (spins) store.set_spin(c.l - lo_, sl);
        } else {
          push(out[from], vl);
          if constexpr (spins) push(out[from], sl);
        }
      }
      expect(from, to, false);
      ranks_.exchange(out, in);
      for (std::size_t i = from; i < to; ++i) {
        const Queued& c = queue_[i];
        if (c.rl == me && c.rk != me) {
          const auto from = static_cast<std::size_t>(c.rk);
          store.set_velocity(c.l - lo_, pull(in[from], read[from]));
          if constexpr (spins) store.set_spin(c.l - lo_, pull(in[from], read[from]));
        }
      }
    }
    ranks_.sum(loss);  // one nonzero per candidate: the owner's
    for (const double x : loss) loss_sum += x;
    return waves;
  }

  /// Block 2s + 1 (direction and acceptance) of each of the candidates `own` of the segment starting at
  /// candidate `first`, 64 at a time in SIMD (the same words as one at a time).
  void second_blocks(const RandomStream& rng, std::uint64_t step, std::size_t first,
                     const std::vector<std::size_t>& own, std::vector<RandomBlock>& words) const {
    constexpr std::size_t batch = 64;
    words.resize(own.size());
    std::array<std::uint64_t, batch> steps, index;
    steps.fill(step);
    for (std::size_t o0 = 0; o0 < own.size(); o0 += batch) {
      const std::size_t n = std::min(batch, own.size() - o0);
      for (std::size_t b = 0; b < batch; ++b) index[b] = 2 * (first + queue_[own[o0 + std::min(b, n - 1)]].j) + 1;
      const RandomBlocks<batch> w = rng.blocks(RngPurpose::collision_pair, 0, steps, index);
      for (std::size_t b = 0; b < n; ++b) words[o0 + b] = {w.word[0][b], w.word[1][b], w.word[2][b], w.word[3][b]};
    }
  }

  /// A candidate on its two velocities (and spins, rough particles) with its block 2s + 1 `w`:
  /// schemes/collision_stage.hpp's acceptance on the mean over sigma-hat, then sigma-hat given the collision,
  /// against the step's majorant. Returns 2 (energy loss), 0 without a collision.
  template <class Kernel>
  static double collide_candidate(const RandomBlock& w, Vec3& vk, Vec3& vl, Vec3& sk, Vec3& sl, const Kernel& kernel,
                                  const PairCoefficients& pair, double omega_max, double (&counts)[2], double& above) {
    const Vec3 g = vk - vl;
    const double g2 = norm2(g);
    const double omega = pair.rate_prefactor * kernel.mean_rate(g2);
    if (omega > omega_max) {
      above = std::max(above, omega);
      counts[1] += 1.0;
    } else if (uniform_open(w[2]) * omega_max > omega) {
      return 0.0;
    }
    constexpr int dim = Kernel::dimension;
    const ImpactDirection d = impact_direction<dim>(
        g, std::sqrt(g2), impact_variate<dim, Kernel::impact_law>(uniform_open(w[0]), uniform_open(w[1])));
    if (!(d.g_sigma > 0.0)) return 0.0;
    counts[0] += 1.0;
    if constexpr (rough_kernel<Kernel>) {  // collide/rough_rule.hpp
      return rough_collision(vk, vl, sk, sl, d.sigma, d.g_sigma, pair);
    } else {
      inelastic_collision(vk, vl, d.sigma, d.g_sigma, pair);
      return 2.0 * pair.energy_loss * d.g_sigma * d.g_sigma;
    }
  }

  /// Hint that a candidate's records held here will be read soon.
  template <class Store>
  void prefetch(const Store& store, const Queued& c) const noexcept {
    store.prefetch(c.k - lo_);
    if (c.rl == me_) store.prefetch(c.l - lo_);
    if (store.has_spins()) {
      store.prefetch_spin(c.k - lo_);
      if (c.rl == me_) store.prefetch_spin(c.l - lo_);
    }
  }

  static void push(std::vector<double>& b, const Vec3& v) { b.insert(b.end(), {v.x, v.y, v.z}); }
  static Vec3 pull(const std::vector<double>& b, std::size_t& at) {
    const Vec3 v{b[at], b[at + 1], b[at + 2]};
    at += 3;
    return v;
  }

  /// The latest wave of each particle of the step's candidates: open addressing over the particle index,
  /// at most half full, cleared every step (a std::unordered_map here took most of the stage's time).
  class LatestWave {
   public:
    void reset(std::size_t keys) {
      std::size_t slots = 16;
      while (slots < 2 * keys) slots *= 2;
      shift_ = 64 - static_cast<unsigned>(std::countr_zero(slots));
      key_.assign(slots, empty);
      wave_.assign(slots, 0);
    }
    void prefetch(std::uint64_t k) const noexcept {
      __builtin_prefetch(&key_[home(k)], 1, 3);
      __builtin_prefetch(&wave_[home(k)], 1, 3);
    }
    /// The slot of particle k (0 if new).
    std::uint32_t& operator[](std::uint64_t k) noexcept {
      std::size_t at = home(k);
      while (key_[at] != k && key_[at] != empty) at = (at + 1) & (key_.size() - 1);
      key_[at] = k;
      return wave_[at];
    }

   private:
    [[nodiscard]] std::size_t home(std::uint64_t k) const noexcept {
      return static_cast<std::size_t>((k * 0x9E3779B97F4A7C15ull) >> shift_);
    }
    static constexpr std::uint64_t empty = ~std::uint64_t{0};
    std::vector<std::uint64_t> key_;
    std::vector<std::uint32_t> wave_;
    unsigned shift_ = 60;
  };

  const Ranks& ranks_;
  int me_, size_;  // this rank and the number of ranks
  std::size_t n_;  // particles of the whole system
  double mass_;
  std::size_t chunks_ = 0, first_chunk_ = 0;
  std::size_t lo_ = 0, hi_ = 0;  // this rank's particles: global indices [lo_, hi_)
  std::uint64_t waves_ = 0;
  // A segment's candidates (kept to reuse their memory): particles, owners, waves, in list order; then
  // in wave order, with j the position in the list.
  std::vector<std::uint64_t> k_, l_;
  std::vector<int> rk_, rl_;
  std::vector<std::uint32_t> wave_;
  std::vector<Queued> queue_;
  LatestWave latest_;
};

}  // namespace granmc
