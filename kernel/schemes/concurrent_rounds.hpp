#pragma once
// The collision stage of one step on several threads, with the same bits as the stage on one
// (schemes/collision_stage.hpp): concurrent rounds. docs/scaling.md gives the argument in full; in short:
//
// The candidates of a step, their pairs, particles and uniforms, depend on the counters only, never on a
// velocity. A round hands thread t the chunk of candidates [R + t B, R + (t + 1) B):
//  1. each thread draws its chunk and lists its particles' keys (core/address_filter.hpp); it reads no record;
//  2. after a barrier, each thread puts the keys of the earlier chunks of the round into a filter of its own,
//     defers the candidates of its chunk that may name a particle of an earlier chunk, or that name one of a
//     deferred candidate before them, and runs the others in order, records prefetched a batch ahead as on
//     one thread;
//  3. one thread replays the deferred candidates in candidate order, then adds the collisions' terms to the
//     tallies in candidate order.
// A candidate that runs in step 2 names no particle that an earlier candidate of the round, in another
// chunk, names: every particle sees the updates of the serial order, in that order. The filter may answer
// "maybe" for a particle no earlier chunk names; that defers a candidate needlessly and changes nothing else.
// What the chunks share is the majorant, which a collision raises when omega exceeds it (000 sec. 3): all
// chunks test against its value at the round's start, which is the serial value unless a candidate raises
// it. If one does, the round's velocities (and the spins of rough particles, beside the records under the
// same index) are restored from the overwritten values kept in step 2 and 3, and the round runs again in
// order on one thread. Raises are rare (a few per run); a candidate of chunk t is deferred with probability
// about 4 B t / N for a shared particle (0.08 % at N = 10^7, B = 2048, t = 1) and about 0.2 % for the filter's
// "maybe". On the 2-core host measured, two threads in rounds are about as fast as one at N = 10^7
// (docs/scaling.md), so they run only when asked for (RunOptions::threads_per_replica).
#include <omp.h>

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "kernel/collide/enskog_shear_shift.hpp"
#include "kernel/collide/pair_coefficients.hpp"
#include "kernel/core/philox_stream.hpp"
#include "kernel/observe/gas_series.hpp"
#include "kernel/schemes/collision_stage.hpp"
#include "kernel/schemes/gas_state.hpp"

namespace granmc {

/// A replica's threads for its collision stage, and what its rounds did.
struct ConcurrentRounds {
  int threads = 1;
  CollisionRoundCounts counts;
};

/// Candidates per thread and round for N particles: about N / 4096 (a multiple of the batch), at least
/// 512 and at most 2048 (a chunk's draws stay within the core's cache, and a larger chunk defers more
/// candidates: at N = 10^7, chunks of 8192 ran as fast as 2048 and deferred 6 times as many, 32768 were
/// slower, docs/scaling.md).
inline std::uint64_t round_chunk(std::uint64_t particles) noexcept {
  return std::clamp<std::uint64_t>(particles / 4096 / 64 * 64, 512, 2048);
}

namespace detail {

template <class Kernel, class Shift, bool one_pair, std::uint64_t batch, class Real>
void collide_in_rounds(BasicGasState<Real>& state, std::span<const PairCoefficients> pairs, std::span<double> omega_max,
                       std::span<const std::uint64_t> candidates, const RandomStream& rng,
                       std::span<CollisionTally> tallies, const Kernel& kernel, const Shift& shift,
                       ConcurrentRounds& rounds) {
  using Serial = BatchedStage<Kernel, Shift, one_pair, batch, Real>;
  using Round = BatchedStage<Kernel, Shift, one_pair, batch, Real, true>;
  Serial serial(state, pairs, omega_max, candidates, rng, tallies, kernel, shift);
  std::uint64_t particles = 0;
  for (const auto& store : state.species) particles += store.size();
  const std::uint64_t chunk = round_chunk(particles);
  const std::uint64_t total = serial.total();
  const auto threads = static_cast<std::uint64_t>(rounds.threads);
  if (threads < 2 || total < 2 * threads * chunk) {  // fewer candidates than two rounds: in order
    serial.run();
    serial.finish(omega_max, tallies);
    return;
  }
  // The pair choice at each chunk's first candidate (a mixture's pairs are drawn in order).
  const std::uint64_t chunks = (total + chunk - 1) / chunk;
  std::vector<typename Serial::PairDeck> decks(one_pair ? 1 : chunks);
  if constexpr (!one_pair) {
    const typename Serial::PairDeck start = serial.deck();
    for (std::uint64_t c = 0; c < chunks; ++c) {
      decks[c] = serial.deck();
      for (std::uint64_t s0 = c * chunk; s0 < std::min(total, (c + 1) * chunk); s0 += batch)
        serial.advance_pairs(s0, std::min(batch, total - s0));
    }
    serial.set_deck(start);
  }
  const auto deck = [&](std::uint64_t c) -> const typename Serial::PairDeck& { return decks[one_pair ? 0 : c]; };
  std::vector<Round*> stages(threads, nullptr);
  std::vector<std::span<const std::uint32_t>> chunk_keys(threads);
#pragma omp parallel num_threads(static_cast <int>(threads))
  {
    const auto team = static_cast<std::uint64_t>(omp_get_num_threads());
    const auto t = static_cast<std::uint64_t>(omp_get_thread_num());
    Round stage(state, pairs, omega_max, candidates, rng, tallies, kernel, shift);
    stages[t] = &stage;
    for (std::uint64_t r = 0; r < (chunks + team - 1) / team; ++r) {
      const std::uint64_t c = r * team + t;
      const std::uint64_t first = std::min(total, c * chunk), end = std::min(total, first + chunk);
      stage.begin_chunk(first, end, deck(std::min(c, chunks - 1)), serial.majorants());
      stage.draw_chunk();
      chunk_keys[t] = stage.chunk_keys();
#pragma omp barrier
      stage.defer(std::span<const std::span<const std::uint32_t>>(chunk_keys).first(t));
      stage.run_chunk();
#pragma omp barrier
#pragma omp single
      {
        bool raised = false;
        for (std::uint64_t u = 0; u < team; ++u) {
          raised = raised || stages[u]->raised();
          rounds.counts.deferred += stages[u]->deferred_count();
        }
        for (std::uint64_t u = 1; u < team && !raised; ++u) {
          stages[u]->replay_deferred();
          raised = stages[u]->raised();
        }
        const std::uint64_t round_first = std::min(total, r * team * chunk);
        const std::uint64_t round_end = std::min(total, (r + 1) * team * chunk);
        if (raised) {  // undo the round and run it in order
          for (std::uint64_t u = team; u-- > 0;) stages[u]->undo_replayed();
          for (std::uint64_t u = 0; u < team; ++u) stages[u]->undo_chunk();
          serial.set_deck(deck(r * team));
          serial.run_range(round_first, round_end);
          ++rounds.counts.in_order;
        } else {  // the collisions' terms in candidate order: per chunk, a merge of the two ordered runs
          for (std::uint64_t u = 0; u < team; ++u) {
            const auto ran = stages[u]->chunk_outcomes();
            const auto replayed = stages[u]->replayed_outcomes();
            std::size_t a = 0, b = 0;
            while (a < ran.size() || b < replayed.size()) {
              const bool from_ran =
                  b == replayed.size() || (a < ran.size() && ran[a].candidate < replayed[b].candidate);
              serial.add_outcome(from_ran ? ran[a++] : replayed[b++]);
            }
          }
        }
        ++rounds.counts.rounds;
      }
    }
  }
  serial.finish(omega_max, tallies);
}

}  // namespace detail

/// collide_step (schemes/collision_stage.hpp) on rounds.threads threads, the same bits.
template <class Kernel, std::uint64_t batch = 64, class Shift = NoCollisionShift, class Real = double>
void collide_step_in_rounds(BasicGasState<Real>& state, std::span<const PairCoefficients> pairs,
                            std::span<double> omega_max, std::span<const std::uint64_t> candidates,
                            const RandomStream& rng, std::span<CollisionTally> tallies, ConcurrentRounds& rounds,
                            const Kernel& kernel = {}, const Shift& shift = {}) {
  if (pairs.size() == 1) {
    detail::collide_in_rounds<Kernel, Shift, true, batch>(state, pairs, omega_max, candidates, rng, tallies, kernel,
                                                          shift, rounds);
  } else {
    detail::collide_in_rounds<Kernel, Shift, false, batch>(state, pairs, omega_max, candidates, rng, tallies, kernel,
                                                           shift, rounds);
  }
}

}  // namespace granmc
