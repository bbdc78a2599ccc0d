#pragma once
// The collision stage of one step on several threads, with the same bits as the stage on one
// (schemes/collision_stage.hpp): concurrent rounds. docs/developer-guide/scaling.md gives the argument in full; in
// short:
//
// The candidates of a step, their pairs, particles and uniforms, depend on the counters only, never on a
// velocity. A round of T threads splits its candidates into a leader's chunk (thread 0) and T - 1 followers'
// chunks after it, in candidate order:
//  1. the leader runs its chunk as the one-thread stage does, on the step's own stage and tallies;
//  2. at the same time follower t draws the round's candidates before its chunk (it reads no record) and puts
//     their particles in a filter of its own, then runs its chunk: it defers each candidate that may name a
//     particle of the filter, or names one of a deferred candidate before it, and runs the others in order,
//     records prefetched a batch ahead as on one thread, keeping their terms and the velocities they overwrote;
//  3. the last follower, whose chunk ends when the others are done (below), replays the followers' deferred
//     candidates in candidate order, then adds the followers' collisions' terms to the tallies in candidate
//     order (the terms it adds are mostly its own, still in its cache).
// A candidate that runs in step 2 names no particle that an earlier candidate of the round, in another
// chunk, names: every particle sees the updates of the serial order, in that order. The filter may answer
// "maybe" for a particle no earlier chunk names; that defers a candidate needlessly and changes nothing else.
// What the chunks share is the majorant, which a collision raises when omega exceeds it (000 sec. 3): the
// followers test against its value at the round's start, which is the serial value unless a candidate before
// theirs raises it. If the leader or a follower raises it, the followers' velocities (and the spins of rough
// particles, beside the records under the same index) are restored from the overwritten values kept in steps
// 2 and 3, and their chunks run again in order after the leader's. Raises are rare (a few per run).
// The last follower's chunk ends with the batch it is running when every other thread has finished its chunk:
// the candidates of a chunk up to a batch's end are a chunk, and the next round starts after them. So no thread
// waits for it, whatever the machine's load. With more than two threads the leader's chunk grows or shrinks a
// batch per round so that it takes as long as the slowest of the other followers' (whose note of the earlier
// candidates it does not pay). Where a chunk ends changes which candidates are deferred, never a result.
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "kernel/collide/enskog_shear_shift.hpp"
#include "kernel/collide/pair_coefficients.hpp"
#include "kernel/core/philox_stream.hpp"
#include "kernel/core/pinned_thread.hpp"
#include "kernel/core/spin_barrier.hpp"
#include "kernel/observe/gas_series.hpp"
#include "kernel/schemes/collision_stage.hpp"
#include "kernel/schemes/gas_state.hpp"

namespace granmc {

/// A replica's threads for its collision stage, and what its rounds did.
struct ConcurrentRounds {
  int threads = 1;
  CollisionRoundCounts counts;
  std::uint64_t leader_chunk = 0;  // candidates of the leader's chunk, kept from step to step (0: not yet set)
};

/// Candidates of a follower's chunk for N particles: about N / 4096 (a multiple of the batch), at least 512 and
/// at most 2048 (a larger chunk defers more candidates; docs/developer-guide/scaling.md).
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
  using Follower = BatchedStage<Kernel, Shift, one_pair, batch, Real, true>;
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
  // The leader's chunk: four followers' chunks to start with; longer rounds pay the round's fixed costs (two
  // barriers, the pipelines' restarts) less often and defer more (docs/developer-guide/scaling.md).
  if (rounds.leader_chunk == 0) rounds.leader_chunk = 4 * chunk;
  const std::uint64_t least_lead = chunk / 4, most_lead = 8 * chunk;
  const std::uint64_t longest_last = 8 * chunk;  // the last follower's chunk, which ends when the others are done
  std::uint64_t round_end = 0;                   // where the last follower's chunk ended
  // The next round's start, shared: its first candidate, and the pair choice and majorants there.
  std::uint64_t round_first = 0;
  typename Serial::PairDeck round_deck{};
  std::vector<double> round_majorants(pairs.size());
  std::vector<Follower*> followers(threads, nullptr);
  std::vector<double> seconds(threads, 0.0);
  std::optional<SpinBarrier> barrier;
#pragma omp parallel num_threads(static_cast <int>(threads))
  {
    const auto team = static_cast<std::uint64_t>(omp_get_num_threads());
    const auto t = static_cast<std::uint64_t>(omp_get_thread_num());
    const PinnedThread pinned(PinnedThread::replica_thread_index(static_cast<int>(team)));
#pragma omp single
    barrier.emplace(static_cast<int>(team));
    std::optional<Follower> stage;
    if (t > 0) stage.emplace(state, pairs, omega_max, candidates, rng, tallies, kernel, shift);
    followers[t] = stage ? &*stage : nullptr;
    // Called by one thread: the round from candidate `from`, or, when fewer candidates are left than a round
    // holds, the rest in order.
    const auto start_round = [&](std::uint64_t from) {
      round_first = from;
      if (total - from < rounds.leader_chunk + (team - 1) * chunk) {
        serial.run_range(from, total);
        round_first = total;
      }
      round_deck = serial.deck();
      std::ranges::copy(serial.majorants(), round_majorants.begin());
    };
    if (t == 0) start_round(0);
    barrier->arrive_and_wait();
    while (round_first < total) {
      const std::uint64_t first = round_first, lead_end = first + rounds.leader_chunk;
      const auto clock = std::chrono::steady_clock::now();
      if (t == 0) {
        serial.run_range(first, lead_end);
      } else {
        const std::uint64_t own = lead_end + (t - 1) * chunk;
        stage->begin_round(round_deck, round_majorants);
        stage->note_earlier(first, own);
        if (t + 1 < team) {
          stage->run_chunk(own, own + chunk, [] { return false; });
        } else {
          round_end = stage->run_chunk(own, std::min(total, own + longest_last),
                                       [&] { return barrier->waiting() + 1 == static_cast<int>(team); });
        }
      }
      seconds[t] = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock).count();
      barrier->arrive_and_wait();
      if (t + 1 == team) {  // the last follower, whose collisions' terms are in its own cache
        bool raised = !std::ranges::equal(serial.majorants(), round_majorants);
        for (std::uint64_t u = 1; u < team; ++u) {
          raised = raised || followers[u]->raised();
          rounds.counts.deferred += followers[u]->deferred_count();
        }
        for (std::uint64_t u = 1; u < team && !raised; ++u) {
          followers[u]->replay_deferred();
          raised = followers[u]->raised();
        }
        if (raised) {  // undo the followers' chunks and run them in order after the leader's
          for (std::uint64_t u = team; u-- > 1;) followers[u]->undo_replayed();
          for (std::uint64_t u = 1; u < team; ++u) followers[u]->undo_chunk();
          serial.run_range(lead_end, round_end);
          ++rounds.counts.in_order;
        } else {  // the collisions' terms in candidate order: per chunk, a merge of the two ordered runs
          for (std::uint64_t u = 1; u < team; ++u) {
            const auto ran = followers[u]->chunk_outcomes();
            const auto replayed = followers[u]->replayed_outcomes();
            std::size_t a = 0, b = 0;
            while (a < ran.size() || b < replayed.size()) {
              const bool from_ran =
                  b == replayed.size() || (a < ran.size() && ran[a].candidate < replayed[b].candidate);
              serial.add_outcome(from_ran ? ran[a++] : replayed[b++]);
            }
          }
          serial.set_deck(followers[team - 1]->deck());
        }
        ++rounds.counts.rounds;
        if (team > 2) {
          double slowest = 0.0;
          for (std::uint64_t u = 1; u + 1 < team; ++u) slowest = std::max(slowest, seconds[u]);
          const std::uint64_t lead = rounds.leader_chunk;
          rounds.leader_chunk = slowest > seconds[0] ? std::min(most_lead, lead + batch)
                                                     : std::max(least_lead, lead - std::min(lead, batch));
        }
        start_round(round_end);
      }
      barrier->arrive_and_wait();
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
