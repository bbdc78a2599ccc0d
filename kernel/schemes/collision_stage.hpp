#pragma once
// The collision stage of one step of the time-stepped ESMC/DSMC scheme (000 sec. 3). For each ordered
// species pair (i, j) a given number of candidate pairs {k, l} (k of species i, l of species j, l != k
// when i = j) chosen with equiprobability, each accepted with probability omega / omega_max^(ij), and the
// post-collision rule of 000 eqs. (14-15) for the accepted ones (rough particles: collide/rough_rule.hpp, with
// the spins the store keeps beside the records). When omega exceeds the majorant, the
// collision is accepted and omega_max^(ij) := omega (000 sec. 3). Two forms of the acceptance, the same
// law:
//  - With a collision shift (the Enskog gas under shear), the paper's: a direction sigma-hat uniform on the
//    sphere (the circle for disks) first, omega = omega_kl(sigma-hat) = prefactor rate(g.sigma, |g|^2), zero when
//    g.sigma <= 0.
//  - Otherwise the direction after the acceptance: omega = prefactor mean_rate(|g|^2), the mean of
//    omega_kl over sigma-hat (collide/hard_sphere.hpp), then sigma-hat from its conditional law given the
//    collision, density proportional to Theta(g.sigma) (g.sigma) (collide/impact_direction.hpp). The
//    pair collides at the same rate with the same law of sigma-hat, but a majorant of the mean is about
//    a quarter of a majorant of omega_kl, so a step needs about four times fewer candidates for the same
//    collisions (Maxwell: every candidate collides). The shift makes g depend on sigma-hat, so there the
//    mean has no closed form and the paper's form stays.
//
// The candidates of the different pairs are interleaved in a uniformly random order (each next
// candidate belongs to pair q with probability remaining_q / remaining), not run pair after pair as the
// paper's text lists them: running all (1,1) candidates before all (1,2) ones is a splitting whose error
// grows with dt (at nu dt = 0.16 it moved the temperature ratio of a mixture by 0.01, eight times its CI,
// docs/methods/physics.md). The number of candidates of each pair per step is the paper's.
//
// Velocities are in stored units (V = u c); omega_max and omega_kl are in units of u (their physical
// values are u times these), which leaves the acceptance ratio unchanged.
//
// `Shift` is the relative velocity at contact: NoCollisionShift (V_k - V_l) or, for shear in the Enskog
// gas, collide/enskog_shear_shift.hpp, which also tallies the shear work and the collisional transfer.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

#include "kernel/collide/enskog_shear_shift.hpp"
#include "kernel/collide/hard_sphere.hpp"
#include "kernel/collide/impact_direction.hpp"
#include "kernel/collide/inelastic_rule.hpp"
#include "kernel/collide/pair_coefficients.hpp"
#include "kernel/collide/rough_rule.hpp"
#include "kernel/core/address_filter.hpp"
#include "kernel/core/batch_variates.hpp"
#include "kernel/core/bounded_list.hpp"
#include "kernel/core/philox_stream.hpp"
#include "kernel/core/sampling.hpp"
#include "kernel/core/sym_tensor.hpp"
#include "kernel/schemes/gas_state.hpp"

namespace granmc {

struct CollisionTally {
  std::uint64_t candidates = 0;
  std::uint64_t collisions = 0;
  std::uint64_t majorant_updates = 0;
  double twice_energy_loss = 0.0;  // sum over collisions of 2 x (kinetic energy lost), stored units
  // With an active Shift only (stored units, masses in scene units):
  double twice_energy_shear_work = 0.0;  // 2 x the energy the shift put in: -2 J s per collision
  SymTensor transfer;                    // sum over collisions of J sigma_ij sigma-hat sigma-hat (000 eq. 18)
};

/// One collision's terms of the tally sums, for candidate `candidate` of pair `q`: the stage adds them to
/// the pair's tally as the collision happens, or, in a concurrent round (schemes/concurrent_rounds.hpp),
/// keeps them, and the round adds them in candidate order.
struct ShiftTerms {
  double twice_energy_shear_work = 0.0;  // subtracted: -2 J s
  SymTensor transfer;
};
struct NoShiftTerms {};
template <bool shifted>
struct CollisionOutcome {
  std::uint64_t candidate;
  std::size_t q;
  double twice_energy_loss;
  [[no_unique_address]] std::conditional_t<shifted, ShiftTerms, NoShiftTerms> shift;
};
template <bool shifted>
void add(CollisionTally& tally, const CollisionOutcome<shifted>& o) noexcept {
  ++tally.collisions;
  tally.twice_energy_loss += o.twice_energy_loss;
  if constexpr (shifted) {
    tally.twice_energy_shear_work -= o.shift.twice_energy_shear_work;
    tally.transfer += o.shift.transfer;
  }
}

/// The initial majorant omega_max^(ij) for relative speeds up to U (stored units), in the form of the
/// acceptance collide_step uses with this Shift: a bound on omega_kl with a shift, on its mean over
/// sigma-hat without.
template <class Shift, class Kernel>
double majorant_bound(const Kernel& kernel, const PairCoefficients& p, double relative_speed) noexcept {
  if constexpr (Shift::active)
    return p.rate_prefactor * kernel.bound(relative_speed);
  else
    return p.rate_prefactor * kernel.mean_bound(relative_speed);
}

namespace detail {

/// The batched stage of one step (collide_step below), split into its named parts: draw (a batch's random
/// words, pairs and particles), screen (the candidates a batch cannot reject with certainty), impact
/// directions (sigma-hat and g.sigma of the screened candidates, a register at a time), and apply (the
/// acceptance and the collision, candidate by candidate in order). With the number of ordered pairs known at
/// compile time when it is one (`one_pair`), the pair's constants, majorant and tally live in one slot and no
/// candidate looks them up. The arithmetic and its order are the same in both forms, so the results are the
/// same bits.
///
/// `in_round`: the stage is a follower's chunk of a concurrent round (schemes/concurrent_rounds.hpp). It draws
/// the round's candidates before its chunk and notes their particles, then holds back (defers) the candidates
/// of its chunk that meet one of them, runs the others, and keeps, instead of summing them, each collision's
/// terms, the velocities it overwrote and whether it raised a majorant; the round then replays the deferred
/// candidates, adds the terms in candidate order, or undoes the followers' chunks.
template <class Kernel, class Shift, bool one_pair, std::uint64_t batch, class Real, bool in_round = false>
class BatchedStage {
  static_assert(batch > 0);
  static constexpr std::size_t max_pairs = 4;  // ordered pairs of at most two species (the scene's limit)
  // The per-pair state the candidates update, one slot per pair: with one pair a single slot, and the pair's
  // constants copied, so that the compiler keeps them in registers (the velocity stores could alias a
  // PairCoefficients in memory) and the one-pair loop matches a hand-written one.
  static constexpr std::size_t slots = one_pair ? 1 : max_pairs;
  using Store = BasicSpeciesStore<Real>;
  // Whether a batch's candidates are screened before they act: for a kernel whose rate varies. With the
  // acceptance on the mean only the candidates that pass the screen need a direction.
  static constexpr bool screened = Kernel::screen_candidates;
  static constexpr bool directions_for_all = !screened || Shift::active;
  static constexpr int dimension = Kernel::dimension;  // 3 spheres, 2 disks (collide/impact_direction.hpp)
  static constexpr bool rough = rough_kernel<Kernel>;  // the particles spin (collide/rough_rule.hpp)
  // A batch's values in whole SIMD registers.
  static constexpr std::size_t lanes = (batch + SimdDouble::size - 1) / SimdDouble::size * SimdDouble::size;
  using Lanes = std::array<double, lanes>;
  static_assert(!screened || batch <= 64, "the screen keeps a batch's outcomes in one 64-bit mask");
  static constexpr std::size_t slots_log2 = 14;  // of `seen_`

  /// The draws of a batch: its candidates' pairs, particles, acceptance uniforms and the uniforms of their
  /// directions n; the directions themselves where every candidate needs one (with the acceptance on the
  /// mean and the screen, only the candidates that pass it get theirs).
  struct Drawn {
    std::uint64_t first;  // the candidate of lane 0
    typename Store::Particle pk[batch], pl[batch];
    std::uint8_t qs[batch];
    Lanes accept;
    Lanes dir1, dir2, sx, sy, sz;
  };

 public:
  using Outcome = CollisionOutcome<Shift::active>;
  /// The state of the pair choice: candidates left in pairs 0..k (draw).
  using PairDeck = std::array<std::int64_t, max_pairs - 1>;

  BatchedStage(BasicGasState<Real>& state, std::span<const PairCoefficients> pairs, std::span<const double> omega_max,
               std::span<const std::uint64_t> candidates, const RandomStream& rng,
               std::span<const CollisionTally> tallies, const Kernel& kernel, const Shift& shift) noexcept
      : pairs_(pairs),
        rng_(rng),
        kernel_(kernel),
        shift_(shift),
        n_pairs_(one_pair ? 1 : pairs.size()),
        only_pair_(one_pair ? pairs[0] : PairCoefficients{}) {
    // The pair choice: cumulative_[k] = candidates left in pairs 0..k (below 2^53, so exact as doubles);
    // past the last pair the largest value, so no candidate is assigned beyond it. Integers, so that the
    // update in draw compiles to arithmetic, not to branches.
    for (std::size_t q = 0; q < n_pairs_; ++q) {
      total_ += candidates[q];
      if (q + 1 < max_pairs) cumulative_[q] = static_cast<std::int64_t>(total_);
      majorant_[q] = omega_max[q];
      tally_[q] = tallies[q];
      tally_[q].candidates += candidates[q];
    }
    for (std::size_t k = n_pairs_ == 0 ? 0 : n_pairs_ - 1; k + 1 < max_pairs; ++k)
      cumulative_[k] = std::numeric_limits<std::int64_t>::max();
    // Per pair, once per step: the two stores and the ranges the indices are drawn from (N_j - 1 within a
    // species). Each candidate then finds its two particles as it is drawn, and the collision loop reads
    // them without going through the pair and the store again (for a mixture that chain of loads stood in
    // front of every velocity load: docs/developer-guide/performance.md, effects).
    for (std::size_t q = 0; q < n_pairs_; ++q) {
      store_k_[q] = &state.species[pairs[q].i];
      store_l_[q] = &state.species[pairs[q].j];
      same_species_[q] = pairs[q].i == pairs[q].j;
      range_k_[q] = store_k_[q]->size();
      range_l_[q] = same_species_[q] ? range_k_[q] - 1 : store_l_[q]->size();
    }
    steps_.fill(state.step);
    // The candidates' particle indices from their ranges lane by lane (uniform_indices) when every range is
    // below 2^32, else one by one (uniform_index): the same values.
    for (std::size_t q = 0; q < n_pairs_; ++q)
      narrow_ = narrow_ && std::max(range_k_[q], range_l_[q]) < (std::uint64_t{1} << 32);
    if (one_pair && narrow_) {
      ranges_k_.fill(static_cast<std::uint32_t>(range_k_[0]));
      ranges_l_.fill(static_cast<std::uint32_t>(range_l_[0]));
    }
  }

  /// Every candidate of the step in order (run_range).
  void run() noexcept { run_range(0, total_); }

  /// Candidates first .. end - 1 in order, drawn a batch ahead, from the pair choice's present state (deck).
  void run_range(std::uint64_t first, std::uint64_t end) noexcept {
    run_batches(
        first, end,
        [this](std::uint64_t i, std::uint64_t s0, std::uint64_t m) -> const Drawn& {
          draw(drawn_[i & 1u], s0, m);
          return drawn_[i & 1u];
        },
        [] { return false; });
  }

  [[nodiscard]] std::uint64_t total() const noexcept { return total_; }
  [[nodiscard]] PairDeck deck() const noexcept {
    PairDeck d;
    std::copy(std::begin(cumulative_), std::end(cumulative_), d.begin());
    return d;
  }
  void set_deck(const PairDeck& d) noexcept { std::copy(d.begin(), d.end(), std::begin(cumulative_)); }

  /// The running majorants, per pair.
  [[nodiscard]] std::span<const double> majorants() const noexcept { return {majorant_, n_pairs_}; }
  /// Adds a collision's terms to its pair's tally.
  void add_outcome(const Outcome& o) noexcept { add(tally_[one_pair ? 0 : o.q], o); }

  // A follower's chunk of a concurrent round (in_round only), in the order the round calls them.

  /// Starts a round from the pair choice `deck` and the majorants at its first candidate.
  void begin_round(const PairDeck& deck, std::span<const double> majorants) noexcept {
    static_assert(in_round);
    set_deck(deck);
    std::copy(majorants.begin(), majorants.end(), majorant_);
    raised_ = false;
    earlier_.clear();
  }

  /// Draws the candidates first .. end - 1 that the round runs before this chunk, on other threads, and puts
  /// their particles' keys in this thread's filter (core/address_filter.hpp). It reads no record; it moves the
  /// pair choice on to the chunk's first candidate.
  void note_earlier(std::uint64_t first, std::uint64_t end) noexcept {
    for (std::uint64_t s0 = first; s0 < end; s0 += batch) {
      const std::uint64_t m = std::min(batch, end - s0);
      draw<true>(drawn_[0], s0, m);
      for (std::uint64_t b = 0; b < m; ++b) {
        earlier_.insert(AddressFilter::key(drawn_[0].pk[b].address()));
        earlier_.insert(AddressFilter::key(drawn_[0].pl[b].address()));
      }
    }
  }

  /// The chunk's candidates from `first` in order, drawn a batch ahead as on one thread, each batch's
  /// candidates deferred as it is drawn when they may meet a particle of the earlier candidates (note_earlier)
  /// or meet one of a deferred candidate before them; the others run, and keep their terms, the velocities they
  /// overwrote and whether they raised a majorant. It ends at `end`, or earlier at the end of the first batch
  /// before which `stop()` holds; returns where it ended. Any prefix of a chunk whole batches long is a chunk.
  template <class Stop>
  std::uint64_t run_chunk(std::uint64_t first, std::uint64_t end, Stop&& stop) {
    outcomes_.reset(end - first), undo_.reset(2 * (end - first)), spin_undo_.reset(rough ? 2 * (end - first) : 0);
    deferred_.clear();
    const std::uint64_t ended = run_batches(
        first, end,
        [&](std::uint64_t i, std::uint64_t s0, std::uint64_t m) -> const Drawn& {
          Drawn& d = drawn_[i & 1u];
          draw(d, s0, m);
          skip_[i & 1u] = 0;
          for (std::uint64_t b = 0; b < m; ++b) {
            if (earlier_.may_contain(d.pk[b].address()) || earlier_.may_contain(d.pl[b].address())) {
              skip_[i & 1u] |= std::uint64_t{1} << b;
              // A deferred candidate's particles join the filter: a later candidate of the chunk that names one is
              // deferred too, and replays after it.
              earlier_.insert(AddressFilter::key(d.pk[b].address()));
              earlier_.insert(AddressFilter::key(d.pl[b].address()));
              deferred_.push_back(
                  {s0 + b, d.pk[b], d.pl[b], d.qs[b], d.accept[b], d.dir1[b], d.dir2[b], d.sx[b], d.sy[b], d.sz[b]});
            }
          }
          return d;
        },
        stop);
    replayed_from_ = outcomes_.size();
    undo_replayed_from_ = undo_.size();
    return ended;
  }

  /// The deferred candidates, in order, each in full (after every earlier chunk of the round has run).
  void replay_deferred() noexcept {
    Drawn& d = drawn_[0];  // lane 0 holds the deferred candidate
    // Their records prefetched a few candidates ahead: one at a time, each would wait a memory latency.
    constexpr std::size_t ahead = 16;
    for (std::size_t a = 0; a < std::min(ahead, deferred_.size()); ++a)
      deferred_[a].pk.prefetch(), deferred_[a].pl.prefetch();
    for (std::size_t i = 0; i < deferred_.size(); ++i) {
      const DeferredCandidate& c = deferred_[i];
      if (i + ahead < deferred_.size()) deferred_[i + ahead].pk.prefetch(), deferred_[i + ahead].pl.prefetch();
      d.first = c.candidate, d.pk[0] = c.pk, d.pl[0] = c.pl, d.qs[0] = c.q, d.accept[0] = c.accept;
      // n as the batch would have had it: the same bits as the SIMD impact_variates
      const Vec3 n =
          directions_for_all ? Vec3{c.sx, c.sy, c.sz} : impact_variate<dimension, Kernel::impact_law>(c.dir1, c.dir2);
      nx_[0] = n.x, ny_[0] = n.y, nz_[0] = n.z;
      test_and_apply(d, 0, nx_, ny_, nz_, 0);
    }
  }

  [[nodiscard]] std::uint64_t deferred_count() const noexcept { return deferred_.size(); }
  /// Whether a candidate of the chunk raised a majorant (then the round runs again in order).
  [[nodiscard]] bool raised() const noexcept { return raised_; }
  /// The collisions' terms: those of run_chunk, then those of replay_deferred, each in candidate order.
  [[nodiscard]] std::span<const Outcome> chunk_outcomes() const noexcept {
    return outcomes_.items().first(replayed_from_);
  }
  [[nodiscard]] std::span<const Outcome> replayed_outcomes() const noexcept {
    return outcomes_.items().subspan(replayed_from_);
  }
  /// Restores the velocities (and spins) that replay_deferred overwrote, then those that run_chunk overwrote.
  void undo_replayed() noexcept { undo(undo_replayed_from_, undo_.size()); }
  void undo_chunk() noexcept { undo(0, undo_replayed_from_); }

  /// The raised majorants and the step's tallies, per pair.
  void finish(std::span<double> omega_max, std::span<CollisionTally> tallies) const noexcept {
    for (std::size_t q = 0; q < n_pairs_; ++q) {
      omega_max[q] = majorant_[q];
      tallies[q] = tally_[q];
    }
  }

 private:
  /// Candidates first .. end - 1 in order, with two batches in flight: batch_at(i, s0, m) readies batch i of the
  /// range (candidates s0 .. s0 + m - 1) and returns it, and is called for the next batch before the current
  /// one collides; candidate b of the current batch prefetches the records of candidate b of the next, a batch
  /// ahead of their use. The prefetches are spread over the batch: issued a batch's 128 at once, more than the
  /// core's outstanding misses, the last ones waited a memory latency (as in the event scheme,
  /// docs/developer-guide/performance.md). In a round the deferred candidates of a batch are skipped. When `stop()`
  /// holds before a batch is drawn, the range ends with the batch before it. Returns where the range ended.
  template <class BatchAt, class Stop>
  std::uint64_t run_batches(std::uint64_t first, std::uint64_t end, BatchAt&& batch_at, Stop&& stop) noexcept {
    if (first >= end) return first;
    const Drawn* current = &batch_at(0, first, std::min(batch, end - first));
    for (std::uint64_t b = 0; b < std::min(batch, end - first); ++b) {
      current->pk[b].prefetch();
      current->pl[b].prefetch();
    }
    for (std::uint64_t i = 0, s0 = first; s0 < end; ++i, s0 += batch) {
      const std::uint64_t m = std::min(batch, end - s0);
      const std::uint64_t m_next = s0 + m < end && !stop() ? std::min(batch, end - s0 - m) : 0;
      const Drawn& d = *current;
      const Drawn& next = m_next > 0 ? batch_at(i + 1, s0 + m, m_next) : d;
      const std::uint64_t skip = in_round ? skip_[i & 1u] : 0;
      if constexpr (screened && Shift::active) {
        for (std::uint64_t full_test = screen(d, m, next, m_next, skip) & ~skip; full_test != 0;
             full_test &= full_test - 1) {
          const auto b = static_cast<std::uint64_t>(std::countr_zero(full_test));
          test_and_apply(d, b, d.sx, d.sy, d.sz, b);
        }
      } else if constexpr (screened) {
        apply_screened(d, impact_directions(d, screen(d, m, next, m_next, skip) & ~skip));
      } else {
        for (std::uint64_t b = 0; b < m; ++b) {
          if (b < m_next) {
            next.pk[b].prefetch();
            next.pl[b].prefetch();
          }
          if (((skip >> b) & 1u) == 0) test_and_apply(d, b, d.sx, d.sy, d.sz, b);
        }
      }
      if (m_next == 0) return s0 + m;
      current = &next;
    }
    return end;
  }

  /// The pair of candidate s, given its uniform word, without replacement: a uniformly random interleaving of
  /// the pairs' candidates. Moves the pair choice on.
  std::size_t choose_pair(std::uint32_t word, std::uint64_t s) noexcept {
    const double r = uniform_open(word) * static_cast<double>(total_ - s);
    // q = the number of cumulative counts <= r, without branches (a loop here mispredicted 0.86 times
    // per candidate, callgrind, docs/developer-guide/performance.md). r < total - s = candidates left, so q is a pair
    // with candidates left. The same q as subtracting the counts from r one by one: r < 2^53, so r minus
    // an integer below it is exact.
    std::size_t q = 0;
    for (std::size_t k = 0; k + 1 < max_pairs; ++k)
      q += static_cast<std::size_t>(r >= static_cast<double>(cumulative_[k]));
    for (std::size_t k = 0; k + 1 < max_pairs; ++k) cumulative_[k] -= static_cast<std::int64_t>(k >= q);
    return q;
  }

  /// Draws candidates s0 .. s0 + m - 1 into d. They depend on the counters and the pair counts only, never
  /// on a velocity, so a batch can be drawn before the one in front of it has collided. `particles_only`: their
  /// pairs and particles alone (a follower's note of the earlier candidates of its round), which for one pair
  /// needs the blocks 2s only.
  template <bool particles_only = false>
  void draw(Drawn& d, std::uint64_t s0, std::uint64_t m) noexcept {
    // Blocks 2s (lane b) and 2s + 1 (lane batch + b) of the batch's candidates s = s0 + b, all at once,
    // each kind in consecutive lanes so that its words convert in SIMD (past the end of the step in the
    // last batch, unused).
    constexpr std::size_t kinds = particles_only && one_pair ? 1 : 2;
    const RandomBlocks<kinds* batch> blocks = [&] {
      if constexpr (kinds == 2) {
        for (std::uint64_t b = 0; b < batch; ++b) {
          index_[b] = 2 * (s0 + b);
          index_[batch + b] = 2 * (s0 + b) + 1;
        }
        return rng_.blocks(RngPurpose::collision_pair, 0, steps_, index_);
      } else {
        std::array<std::uint64_t, batch> steps, index;
        steps.fill(steps_[0]);
        for (std::uint64_t b = 0; b < batch; ++b) index[b] = 2 * (s0 + b);
        return rng_.blocks(RngPurpose::collision_pair, 0, steps, index);
      }
    }();
    const auto& w = blocks.word;
    auto pick = [&](std::size_t word) { return std::span<const std::uint32_t, batch>(w[word].data(), batch); };
    const auto draw = [](std::uint64_t b) { return batch + b; };
    d.first = s0;
    if constexpr (!one_pair) {
      for (std::uint64_t b = 0; b < m; ++b) {
        const std::size_t q = choose_pair(w[3][draw(b)], s0 + b);
        d.qs[b] = static_cast<std::uint8_t>(q);
        ranges_k_[b] = static_cast<std::uint32_t>(range_k_[q]);  // used only when narrow
        ranges_l_[b] = static_cast<std::uint32_t>(range_l_[q]);
      }
    }
    if (narrow_) {
      uniform_indices(pick(0), pick(1), ranges_k_, ks_);
      uniform_indices(pick(2), pick(3), ranges_l_, ls_);
    } else {
      for (std::uint64_t b = 0; b < m; ++b) {
        const std::size_t q = one_pair ? 0 : d.qs[b];
        ks_[b] = uniform_index(w[0][b], w[1][b], range_k_[q]);
        ls_[b] = uniform_index(w[2][b], w[3][b], range_l_[q]);
      }
    }
    for (std::uint64_t b = 0; b < m; ++b) {
      const std::size_t q = one_pair ? 0 : d.qs[b];
      // Uniform over the other N_i - 1 particles; branch-free: a branch here is taken half the time at
      // random, and its mispredictions discard the overlapped work of the next candidates.
      const std::uint64_t l = ls_[b] + static_cast<std::uint64_t>((one_pair || same_species_[q]) & (ls_[b] >= ks_[b]));
      d.pk[b] = store_k_[q]->particle(ks_[b]);
      d.pl[b] = store_l_[q]->particle(l);
    }
    if constexpr (particles_only) return;
    for (std::uint64_t b = 0; b < batch; ++b) {
      d.dir1[b] = uniform_open(w[0][draw(b)]);
      d.dir2[b] = uniform_open(w[1][draw(b)]);
      d.accept[b] = uniform_open(w[2][draw(b)]);
    }
    // sigma-hat of the paper's form, uniform on the sphere (the circle for disks), or the variates n of the impact
    // direction (the same bits as their scalar forms, in SIMD)
    if constexpr (directions_for_all && Shift::active && dimension == 3) {
      unit_vectors(std::span<const double, lanes>(d.dir1), std::span<const double, lanes>(d.dir2), std::span(d.sx),
                   std::span(d.sy), std::span(d.sz));
    } else if constexpr (directions_for_all && Shift::active) {  // disks: uniform on the circle
      unit_circle_vectors(std::span<const double, lanes>(d.dir1), std::span(d.sx), std::span(d.sy), std::span(d.sz));
    } else if constexpr (directions_for_all)
      impact_variates<dimension, Kernel::impact_law>(std::span<const double, lanes>(d.dir1),
                                                     std::span<const double, lanes>(d.dir2), std::span(d.sx),
                                                     std::span(d.sy), std::span(d.sz));
  }

  /// The acceptance of a candidate of pair q with rate omega and uniform u (000 sec. 3, step 2): when
  /// omega exceeds the majorant, accepted and omega_max^(ij) := omega.
  bool accepted(std::size_t q, double omega, double u) noexcept {
    if (omega > majorant_[q]) {
      majorant_[q] = omega;
      ++tally_[q].majorant_updates;
      if constexpr (in_round) raised_ = true;
      return true;
    }
    return !(u * majorant_[q] > omega);
  }

  /// The collision of candidate b of batch d along sigma-hat (000 sec. 3, step 3; eqs. 14-15; rough particles
  /// collide/rough_rule.hpp).
  void apply(const Drawn& d, std::uint64_t b, Vec3 vk, Vec3 vl, const Vec3& sigma, double g_sigma) noexcept {
    const std::size_t q = one_pair ? 0 : d.qs[b];
    const PairCoefficients& p = one_pair ? only_pair_ : pairs_[q];
    if constexpr (in_round) {
      undo_.push_back({d.pk[b], vk});
      undo_.push_back({d.pl[b], vl});
    }
    double twice_energy_loss;
    if constexpr (rough) {  // collide/rough_rule.hpp, with the spins beside the records
      Store& store_k = *store_k_[q];
      Store& store_l = *store_l_[q];
      const std::size_t k = store_k.index(d.pk[b]), l = store_l.index(d.pl[b]);
      Vec3 sk = store_k.spin(k), sl = store_l.spin(l);
      if constexpr (in_round) {  // the spins before the collision, entry by entry beside undo_
        spin_undo_.push_back({&store_k, k, sk});
        spin_undo_.push_back({&store_l, l, sl});
      }
      twice_energy_loss = rough_collision(vk, vl, sk, sl, sigma, g_sigma, p);
      store_k.set_spin(k, sk);
      store_l.set_spin(l, sl);
    } else {
      inelastic_collision(vk, vl, sigma, g_sigma, p);
      twice_energy_loss = 2.0 * p.energy_loss * g_sigma * g_sigma;
    }
    d.pk[b].set_velocity(vk);
    d.pl[b].set_velocity(vl);
    Outcome o{d.first + b, q, twice_energy_loss, {}};
    if constexpr (Shift::active) {  // collide/enskog_shear_shift.hpp
      const double impulse = p.one_plus_alpha * p.reduced_mass * g_sigma;
      o.shift.twice_energy_shear_work = 2.0 * impulse * p.diameter * shift_.rate * sigma.x * sigma.y;
      o.shift.transfer = weighted_dyad(impulse * p.diameter, sigma);
    }
    if constexpr (in_round)
      outcomes_.push_back(o);
    else
      add(tally_[q], o);
  }

  /// Candidate b of batch d in full: the acceptance, then the collision. Its direction n is (nx, ny, nz)[e].
  void test_and_apply(const Drawn& d, std::uint64_t b, const Lanes& nx, const Lanes& ny, const Lanes& nz,
                      std::size_t e) noexcept {
    const std::size_t q = one_pair ? 0 : d.qs[b];
    const PairCoefficients& p = one_pair ? only_pair_ : pairs_[q];
    const Vec3 vk = d.pk[b].velocity();
    const Vec3 vl = d.pl[b].velocity();
    // n (sigma-hat itself with a shift) is read where it is used: read before the acceptance it
    // holds registers the one-pair loop needs (callgrind, docs/developer-guide/performance.md).
    Vec3 sigma;
    double g_sigma;
    if constexpr (Shift::active) {  // the paper's form: sigma-hat = n first
      sigma = {nx[e], ny[e], nz[e]};
      const Vec3 g = shift_.relative_velocity(vk, vl, sigma, p);
      g_sigma = dot(g, sigma);
      if (g_sigma <= 0.0) return;  // Theta(g.sigma): the pair is separating along sigma-hat
      if (!accepted(q, p.rate_prefactor * kernel_.rate(g_sigma, norm2(g)), d.accept[b])) return;
    } else {  // the mean over sigma-hat first, then sigma-hat given the collision
      const Vec3 g = vk - vl;
      const double g2 = norm2(g);
      // Maxwell: omega = omega_max (majorant_bound), so every candidate passes the test (u < 1).
      if (!accepted(q, p.rate_prefactor * kernel_.mean_rate(g2), d.accept[b])) return;
      const ImpactDirection id = impact_direction<dimension>(g, std::sqrt(g2), {nx[e], ny[e], nz[e]});
      if (!(id.g_sigma > 0.0)) return;  // g + |g| n = 0 (or g = 0): probability zero, no impulse
      sigma = id.sigma;
      g_sigma = id.g_sigma;
    }
    apply(d, b, vk, vl, sigma, g_sigma);
  }

  /// The screen (a kernel whose rate varies): before batch d's candidates act, all of them are tested at
  /// once on the velocities as they are then, and only those it cannot reject go through
  /// test_and_apply, in order. A candidate is left out only if it is rejected with certainty,
  /// u omega_max > omega_hi, and neither of its particles belongs to an earlier candidate of the batch
  /// (whose collision could have changed it). omega_hi is an upper bound of the omega test_and_apply
  /// computes: with the acceptance on the mean omega (1 + rounding_margin), omega computed in SIMD (a few
  /// ulp from the scalar omega); with the Enskog shift (hard spheres, omega = prefactor g.sigma, zero
  /// when g.sigma <= 0) prefactor (g.sigma + rounding_margin sum_c |g_c sigma_c|) (1 + rounding_margin),
  /// which covers another rounding of the dot product. omega_max only grows within a batch, which keeps a
  /// rejection a rejection. So every candidate does what it did in sequence, the same bits
  /// (tests/test_collision_stage.cpp), and the branches on the acceptance (and on the sign of g.sigma),
  /// taken at random and mispredicted, are gone.
  /// `seen_` finds the particles of earlier candidates: a table of batch stamps indexed by record address
  /// (two particles can share a slot: a needless full test, never a missed one). Bit b of the result is set
  /// when candidate b of d needs test_and_apply; bit b of shared_ when it shares a particle (or a slot of
  /// `seen_`) with an earlier candidate of its batch. Candidate b prefetches candidate b of the next batch (m_next
  /// of them), as run does without the screen.
  std::uint64_t screen(const Drawn& d, std::uint64_t m, const Drawn& next, std::uint64_t m_next,
                       std::uint64_t skip) noexcept {
    if (++stamp_ == 0) {  // 255 batches since the table was cleared
      seen_.fill(0);
      stamp_ = 1;
    }
    shared_ = 0;
    std::uint64_t full_test = 0;
    if constexpr (screened) {  // else not called, and kernel.mean_rate need not take a batch
      for (std::uint64_t b = 0; b < m; ++b) {
        if (b < m_next) {
          next.pk[b].prefetch();
          next.pl[b].prefetch();
        }
        if constexpr (in_round) {
          if ((skip >> b) & 1u) continue;  // deferred: its particles may be another thread's now
        }
        const std::size_t q = one_pair ? 0 : d.qs[b];
        const PairCoefficients& p = one_pair ? only_pair_ : pairs_[q];
        if constexpr (!one_pair) threshold_[b] = d.accept[b] * majorant_[q];
        if constexpr (Shift::active) {
          static_assert(std::is_same_v<Kernel, HardCore<dimension>>,
                        "the Enskog shift runs with hard spheres (setup/run_plan.hpp)");
          const Vec3 sigma{d.sx[b], d.sy[b], d.sz[b]};
          const Vec3 g = shift_.relative_velocity(d.pk[b].velocity(), d.pl[b].velocity(), sigma, p);
          const double terms = std::abs(g.x * sigma.x) + std::abs(g.y * sigma.y) + std::abs(g.z * sigma.z);
          omega_[b] = p.rate_prefactor * (dot(g, sigma) + rounding_margin * terms) * (1.0 + rounding_margin);
        } else {
          g2_[b] = norm2(d.pk[b].velocity() - d.pl[b].velocity());
          if constexpr (!one_pair) prefactor_[b] = p.rate_prefactor;
        }
        const std::size_t sk = slot(d.pk[b]), sl = slot(d.pl[b]);
        shared_ |= static_cast<std::uint64_t>((seen_[sk] == stamp_) | (seen_[sl] == stamp_)) << b;
        seen_[sk] = stamp_;
        seen_[sl] = stamp_;
      }
      // Threshold and omega_hi lane by lane, and the lanes not rejected with certainty as bits (one
      // pair: the threshold from the acceptance uniforms and the pair's majorant, here in SIMD).
      std::uint64_t passes = 0;
      for (std::size_t k = 0; k < lanes; k += SimdDouble::size) {
        const SimdDouble thr = one_pair ? SimdDouble::load_unaligned(&d.accept[k]) * majorant_[0]
                                        : SimdDouble::load_unaligned(&threshold_[k]);
        SimdDouble om;
        if constexpr (Shift::active) {
          om = SimdDouble::load_unaligned(&omega_[k]);
        } else {
          const SimdDouble pre =
              one_pair ? SimdDouble(only_pair_.rate_prefactor) : SimdDouble::load_unaligned(&prefactor_[k]);
          om = pre * kernel_.mean_rate(SimdDouble::load_unaligned(&g2_[k])) * (1.0 + rounding_margin);
        }
        passes |= not_greater_bits(thr, om) << k;
      }
      full_test = shared_ | (passes & (m >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << m) - 1));
    }
    if constexpr (rough) {  // the spins of the candidates that may collide, while their directions are computed
      for (std::uint64_t bits = full_test; bits != 0; bits &= bits - 1) {
        const auto b = static_cast<std::uint64_t>(std::countr_zero(bits));
        const std::size_t q = one_pair ? 0 : d.qs[b];
        store_k_[q]->prefetch_spin(store_k_[q]->index(d.pk[b]));
        store_l_[q]->prefetch_spin(store_l_[q]->index(d.pl[b]));
      }
    }
    return full_test;
  }

  /// The candidates of d that passed the screen (`full_test`), in order, and their directions n. One that
  /// shares no particle with an earlier candidate of the batch has, when its turn comes, the velocities the
  /// screen read: its sigma-hat and g.sigma are computed here, before the batch collides, a register at a time
  /// (the same bits as impact_direction, so the square roots and divisions of successive collisions no longer
  /// wait on each other), and only its acceptance is left for its turn. Returns how many passed.
  std::size_t impact_directions(const Drawn& d, std::uint64_t full_test) noexcept {
    const std::size_t passed = selected_directions(full_test, d.dir1, d.dir2, which_, nx_, ny_, nz_,
                                                   [](auto u1, auto u2, auto x, auto y, auto z) {
                                                     impact_variates<dimension, Kernel::impact_law>(u1, u2, x, y, z);
                                                   });
    for (std::size_t e = 0; e < passed; ++e) {
      const Vec3 g = d.pk[which_[e]].velocity() - d.pl[which_[e]].velocity();
      gx_[e] = g.x, gy_[e] = g.y, gz_[e] = g.z, g_square_[e] = g2_[which_[e]];
    }
    for (std::size_t e = passed; e % SimdDouble::size != 0; ++e)
      gx_[e] = gy_[e] = gz_[e] = g_square_[e] = 1.0;  // unused
    for (std::size_t e = 0; e < passed; e += SimdDouble::size) {
      const auto at = [e](const Lanes& a) { return SimdDouble::load_unaligned(&a[e]); };
      SimdDouble x, y, z, gs;
      impact_direction_components<dimension>(at(gx_), at(gy_), at(gz_), sqrt(at(g_square_)), at(nx_), at(ny_), at(nz_),
                                             x, y, z, gs);
      x.store_unaligned(&sigma_x_[e]), y.store_unaligned(&sigma_y_[e]), z.store_unaligned(&sigma_z_[e]);
      gs.store_unaligned(&g_sigma_[e]);
    }
    return passed;
  }

  /// The `passed` candidates of d that passed the screen, in order: those that share a particle with an
  /// earlier candidate of the batch tested in full at their turn, the others accepted on the mean and
  /// collided along the sigma-hat impact_directions computed.
  void apply_screened(const Drawn& d, std::size_t passed) noexcept {
    for (std::size_t e = 0; e < passed; ++e) {
      const std::uint64_t b = which_[e];
      if ((shared_ >> b) & 1u) {
        test_and_apply(d, b, nx_, ny_, nz_, e);
        continue;
      }
      const std::size_t q = one_pair ? 0 : d.qs[b];
      const PairCoefficients& p = one_pair ? only_pair_ : pairs_[q];
      if (!accepted(q, p.rate_prefactor * kernel_.mean_rate(g2_[b]), d.accept[b])) continue;
      if (!(g_sigma_[e] > 0.0)) continue;  // as in test_and_apply
      apply(d, b, d.pk[b].velocity(), d.pl[b].velocity(), {sigma_x_[e], sigma_y_[e], sigma_z_[e]}, g_sigma_[e]);
    }
  }

  void undo(std::size_t from, std::size_t to) noexcept {
    for (std::size_t e = to; e > from; --e) {
      undo_[e - 1].first.set_velocity(undo_[e - 1].second);
      if constexpr (rough) spin_undo_[e - 1].store->set_spin(spin_undo_[e - 1].index, spin_undo_[e - 1].spin);
    }
  }

  static std::uintptr_t slot(const typename Store::Particle& p) noexcept {
    return (reinterpret_cast<std::uintptr_t>(p.address()) >> 4) & ((std::uintptr_t{1} << slots_log2) - 1);
  }

  std::span<const PairCoefficients> pairs_;
  const RandomStream& rng_;
  const Kernel& kernel_;
  const Shift& shift_;
  const std::size_t n_pairs_;
  const PairCoefficients only_pair_;
  std::uint64_t total_ = 0;
  std::int64_t cumulative_[max_pairs - 1];
  double majorant_[slots];
  CollisionTally tally_[slots];
  Store* store_k_[max_pairs];
  Store* store_l_[max_pairs];
  std::uint64_t range_k_[max_pairs], range_l_[max_pairs];
  bool same_species_[max_pairs];
  bool narrow_ = true;
  std::array<std::uint64_t, 2 * batch> steps_, index_;
  std::array<std::uint32_t, batch> ranges_k_{}, ranges_l_{};
  std::array<std::uint64_t, batch> ks_, ls_;
  std::array<std::uint8_t, screened ? std::size_t{1} << slots_log2 : 1> seen_{};
  std::uint8_t stamp_ = 0;
  Lanes g2_{}, threshold_{}, prefactor_{}, omega_{};  // initialised: lanes past a partial batch
  std::uint64_t shared_ = 0;
  std::array<Drawn, 2> drawn_{};  // initialised: a last, partial batch converts all lanes
  std::array<std::uint8_t, lanes> which_;
  Lanes nx_, ny_, nz_;  // the directions n of the candidates that passed the screen
  Lanes gx_, gy_, gz_, g_square_, sigma_x_, sigma_y_, sigma_z_,
      g_sigma_;  // and, for those, g and |g|^2, then sigma-hat and g.sigma
  // In a round: the deferred candidates, the particles they hold back, and what the chunk did.
  std::array<std::uint64_t, 2> skip_{};  // the deferred candidates of drawn_[0] and drawn_[1], a bit per lane
  struct DeferredCandidate {             // a deferred candidate's draws
    std::uint64_t candidate;
    typename Store::Particle pk, pl;
    std::uint8_t q;
    double accept, dir1, dir2, sx, sy, sz;
  };
  std::vector<DeferredCandidate> deferred_;
  // The round's filter, absent from a stage outside a round (it is 128 KB, and a stage is made per step).
  struct NotInRound {};
  template <class T>
  using RoundOnly = std::conditional_t<in_round, T, NotInRound>;
  [[no_unique_address]] RoundOnly<AddressFilter> earlier_;
  BoundedList<Outcome> outcomes_;
  BoundedList<std::pair<typename Store::Particle, Vec3>> undo_;  // particle, velocity before a collision
  struct SpinBefore {
    Store* store;
    std::size_t index;
    Vec3 spin;
  };
  BoundedList<SpinBefore> spin_undo_;  // rough particles: entry e the spin of undo_[e]'s particle before it
  std::size_t replayed_from_ = 0, undo_replayed_from_ = 0;
  bool raised_ = false;
};

}  // namespace detail

/// Random words per candidate s of the step: block 2s gives the two particle indices (64 bits each),
/// block 2s + 1 the direction n (two 32-bit uniforms), the acceptance uniform and the pair choice.
/// omega_max is in the form of majorant_bound<Shift>.
///
/// Candidates are drawn in batches of `batch`: the random blocks, pairs and indices of a batch first, a
/// batch ahead of their use, with the two velocity records of each candidate prefetched while the batch
/// before it collides; then the candidates one by one in order (with the acceptance on the mean, only
/// those a SIMD screen of the batch cannot reject with certainty, and the impact directions of those that
/// share no particle with an earlier one computed in SIMD beforehand). Two candidates that share a particle
/// therefore still act in sequence, and the result is the same for every batch size and with or without
/// the screen (tests/test_collision_stage.cpp); the batches only let the memory loads of different
/// candidates overlap and the acceptance run in SIMD (perf/bench_collisions.cpp, docs/developer-guide/performance.md).
template <class Kernel, std::uint64_t batch = 64, class Shift = NoCollisionShift, class Real = double>
void collide_step(BasicGasState<Real>& state, std::span<const PairCoefficients> pairs, std::span<double> omega_max,
                  std::span<const std::uint64_t> candidates, const RandomStream& rng, std::span<CollisionTally> tallies,
                  const Kernel& kernel = {}, const Shift& shift = {}) noexcept {
  if (pairs.size() == 1) {
    detail::BatchedStage<Kernel, Shift, true, batch, Real> stage(state, pairs, omega_max, candidates, rng, tallies,
                                                                 kernel, shift);
    stage.run();
    stage.finish(omega_max, tallies);
  } else {
    detail::BatchedStage<Kernel, Shift, false, batch, Real> stage(state, pairs, omega_max, candidates, rng, tallies,
                                                                  kernel, shift);
    stage.run();
    stage.finish(omega_max, tallies);
  }
}

}  // namespace granmc
