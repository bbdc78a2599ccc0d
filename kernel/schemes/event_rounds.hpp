#pragma once
// The event scheme's candidates (schemes/event_scheme.hpp) on several threads with the same bits as on one:
// concurrent rounds, as for the time-stepped collision stage (schemes/concurrent_rounds.hpp). The argument in
// full: docs/developer-guide/scaling.md, "The event scheme's rounds". In short:
//
// A candidate's pair, waiting-time word, threshold, scattering draw and Brownian normals depend on its counter
// (draw) only. A round from draw D at time t_D hands the leader (thread 0) the draws [D, D + L) and follower t
// the B draws after the chunks before it:
//  1. the leader runs its chunk as the one-thread scheme does, raising U_max as it goes;
//  2. at the same time follower t draws the pairs and waiting words of the draws before its chunk, adds their
//     times t_(d+1) = t_d + w_d / pi_hat in order as the one-thread loop does (001 step 2.1), and notes their
//     particles in a filter of its own; then it runs its chunk at those times, and defers each candidate that may
//     name a noted particle or one of a deferred candidate before it. It keeps the records (velocity and
//     last-update time) that its candidates overwrite, tests against the U_max of the round's start, and stops
//     at a candidate that would raise that U_max or exceed it (001 steps 2.7, 2.8, 2.10);
//  3. the last follower, whose chunk ends when the others are done, replays the followers' deferred candidates
//     in draw order at their times, and adds the followers' counts (integers: their order does not matter).
// A candidate that runs in step 2 names no particle that an earlier candidate of the round names, so each
// particle's Brownian updates and collisions come in the one-thread order. The times are the one-thread times
// as long as pi_hat stays, that is, while no candidate of the round raises U_max: if the leader raised it, or a
// follower stopped, the followers' records are put back in reverse and their chunks run in order after the
// leader's. Raises are a few tens per run. A round ends where the one-thread loop ends the interval: at the first
// candidate whose time reaches the sample time.
#include <omp.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "kernel/core/address_filter.hpp"
#include "kernel/core/pinned_thread.hpp"
#include "kernel/core/spin_barrier.hpp"
#include "kernel/observe/gas_series.hpp"
#include "kernel/schemes/concurrent_rounds.hpp"
#include "kernel/schemes/event_scheme.hpp"

namespace granmc {

/// A replica's threads for the event scheme's candidates, and what its rounds did.
template <class Scheme>
class EventRounds {
 public:
  explicit EventRounds(int threads) : threads_(threads) {}

  /// scheme.advance_to(t) on the threads: every candidate before t, then every particle brought to t.
  void advance_to(Scheme& scheme, double t);
  [[nodiscard]] const CollisionRoundCounts& counts() const noexcept { return counts_; }

 private:
  using Store = typename Scheme::Store;
  using DrawBatch = typename Scheme::DrawBatch;
  static constexpr std::uint64_t batch = Scheme::batch_size;

  /// Where a round starts: its first draw and time, and pi_hat, U_max, U_max^2 and V there.
  struct RoundStart {
    std::uint64_t first = 0;
    double time = 0.0, rate = 0.0, majorant = 0.0, majorant2 = 0.0;
    Vec3 reference;
    std::uint64_t raises = 0;  // the scheme's majorant_updates
  };
  /// A deferred candidate's time and draws (slot k of its batch; the normals as `candidate` reads them).
  struct Deferred {
    double time;
    std::size_t i, j;
    double threshold, ex, ey, ez;
    std::array<double, 6> normals;
  };
  /// What a follower's chunk did in the round, and the U_max it tests against (read by Scheme::candidate).
  struct Follower {
    double rate = 0.0, majorant = 0.0, majorant2 = 0.0;
    Vec3 reference;
    EventTally tally;
    AddressFilter earlier;
    std::vector<typename Store::KeptRecord> kept;  // in the order written: the chunk's, then the replay's
    std::size_t replayed_from = 0;
    std::vector<Deferred> deferred;
    double now = 0.0;       // the time of the last draw it passed
    std::uint64_t end = 0;  // the draw after its chunk: where the round ends if it is the last
    bool crossed = false;   // the draw `end` reached the sample time
    bool in_order = false;  // a candidate would raise or exceed the round's U_max: the round runs in order
    std::array<DrawBatch, 2> batches{};
    DrawBatch replay{};  // slot 0: the deferred candidate being replayed

    void keep(const Store& store, std::size_t i, std::size_t j) {
      kept.push_back(store.kept(i));
      kept.push_back(store.kept(j));
    }
    void begin(const RoundStart& start) {
      rate = start.rate, majorant = start.majorant, majorant2 = start.majorant2, reference = start.reference;
      tally = {};
      earlier.clear();
      kept.clear();
      deferred.clear();
      now = start.time;
      crossed = in_order = false;
    }
  };

  void note(Scheme& scheme, Follower& f, const RoundStart& start, std::uint64_t own, double t_end) const;
  template <class Stop>
  void run_chunk(Scheme& scheme, Follower& f, const RoundStart& start, std::uint64_t end, double t_end,
                 Stop&& stop) const;
  void replay_deferred(Scheme& scheme, Follower& f) const;
  /// Slot k's candidate, deferred at its time.
  static Deferred deferred(const DrawBatch& drawn, std::uint64_t k, double time) {
    constexpr std::size_t b = batch;
    const auto& z1 = drawn.normal1;
    const auto& z2 = drawn.normal2;
    return {time,        drawn.i[k],  drawn.j[k],  drawn.threshold[k],
            drawn.ex[k], drawn.ey[k], drawn.ez[k], {z1[k], z2[k], z1[b + k], z2[b + k], z1[2 * b + k], z2[2 * b + k]}};
  }
  /// Whether a candidate of slots k .. k + lanes - 1 may name a particle of f's filter.
  static bool may_meet_earlier(Store& store, const Follower& f, const DrawBatch& drawn, std::uint64_t k) {
    bool maybe = false;
    for (std::uint64_t l = k; l < k + Scheme::lanes; ++l)
      maybe = maybe || f.earlier.may_contain(store.particle(drawn.i[l]).address()) ||
              f.earlier.may_contain(store.particle(drawn.j[l]).address());
    return maybe;
  }
  static void put_back(Scheme& scheme, const Follower& f, std::size_t from, std::size_t to) {
    Store& store = scheme.state_.species[0];
    for (std::size_t a = to; a-- > from;) store.put_back(f.kept[a]);
  }

  int threads_;
  CollisionRoundCounts counts_;
  std::vector<std::unique_ptr<Follower>> followers_;  // [t] for follower t (none for the leader)
};

/// Follower f's note: the draws from the round's first to `own` (excluded), their times in order and their
/// particles in its filter. It reads no record. It stops at a draw whose time reaches t_end.
template <class Scheme>
void EventRounds<Scheme>::note(Scheme& scheme, Follower& f, const RoundStart& start, std::uint64_t own,
                               double t_end) const {
  Store& store = scheme.state_.species[0];
  DrawBatch& drawn = f.batches[0];
  for (std::uint64_t d0 = start.first; d0 < own; d0 += batch) {
    scheme.template prepare<true>(drawn, d0);
    const std::uint64_t m = std::min(batch, own - d0);
    for (std::uint64_t k = 0; k < m; ++k) {
      const double time = f.now + drawn.wait[k] / start.rate;  // 001 step 2.1, as Scheme::run_candidates adds it
      if (!(time < t_end)) {
        f.crossed = true, f.end = d0 + k;
        return;
      }
      f.now = time;
      f.earlier.insert(AddressFilter::key(store.particle(drawn.i[k]).address()));
      f.earlier.insert(AddressFilter::key(store.particle(drawn.j[k]).address()));
    }
  }
  f.end = own;
}

/// Follower f's chunk from f.end on, up to `end` or to the end of the first batch after which `stop()` holds:
/// each batch prepared a batch ahead, its pairs prefetched a batch ahead of their use, as on one thread.
template <class Scheme>
template <class Stop>
void EventRounds<Scheme>::run_chunk(Scheme& scheme, Follower& f, const RoundStart& start, std::uint64_t end,
                                    double t_end, Stop&& stop) const {
  Store& store = scheme.state_.species[0];
  DrawBatch* current = &f.batches[0];
  DrawBatch* next = &f.batches[1];
  std::uint64_t d0 = f.end;  // below `end`: the chunk has a candidate
  scheme.prepare(*current, d0);
  for (std::uint64_t k = 0; k < std::min(batch, end - d0); ++k)
    store.prefetch(current->i[k]), store.prefetch(current->j[k]);
  for (; d0 < end; d0 += batch) {
    const std::uint64_t m = std::min(batch, end - d0);
    const std::uint64_t ahead = d0 + batch < end ? std::min(batch, end - d0 - batch) : 0;
    if (ahead != 0) scheme.prepare(*next, d0 + batch);
    for (std::uint64_t k = 0; k < m;) {
      // A register of candidates at once where none may meet a noted particle, as on one thread
      // (Scheme::candidates_in_simd); the others one by one.
      if constexpr (Scheme::registers) {
        if (scheme.noise_ != 0.0 && k + Scheme::lanes <= batch && !may_meet_earlier(store, f, *current, k)) {
          const std::size_t done = scheme.candidates_in_simd(store, *current, k, t_end, m - k, *next, &f);
          k += done;
          if (f.in_order) {
            f.end = d0 + k;
            return;
          }
          if (done != 0) continue;
        }
      }
      if (k < ahead) store.prefetch(next->i[k]), store.prefetch(next->j[k]);
      const double time = f.now + current->wait[k] / start.rate;  // 001 step 2.1
      if (!(time < t_end)) {
        f.crossed = true, f.end = d0 + k;
        return;
      }
      f.now = time;
      const void* pi = store.particle(current->i[k]).address();
      const void* pj = store.particle(current->j[k]).address();
      if (f.earlier.may_contain(pi) || f.earlier.may_contain(pj)) {
        // Its particles join the filter: a later candidate of the chunk that names one is deferred too.
        f.earlier.insert(AddressFilter::key(pi));
        f.earlier.insert(AddressFilter::key(pj));
        f.deferred.push_back(deferred(*current, k, time));
      } else if (!scheme.candidate(store, *current, k, time, &f)) {
        f.in_order = true, f.end = d0 + k + 1;
        return;
      }
      ++k;
    }
    f.end = d0 + m;
    std::swap(current, next);
    if (stop()) return;
  }
}

/// Follower f's deferred candidates in draw order, each at its time (after every earlier chunk of the round).
template <class Scheme>
void EventRounds<Scheme>::replay_deferred(Scheme& scheme, Follower& f) const {
  Store& store = scheme.state_.species[0];
  DrawBatch& slot = f.replay;
  constexpr std::size_t b = batch;
  // Their records prefetched a few candidates ahead: one at a time, each would wait a memory latency.
  constexpr std::size_t ahead = 16;
  for (std::size_t a = 0; a < std::min(ahead, f.deferred.size()); ++a)
    store.prefetch(f.deferred[a].i), store.prefetch(f.deferred[a].j);
  for (std::size_t a = 0; a < f.deferred.size(); ++a) {
    if (a + ahead < f.deferred.size()) store.prefetch(f.deferred[a + ahead].i), store.prefetch(f.deferred[a + ahead].j);
    const Deferred& c = f.deferred[a];
    slot.i[0] = c.i, slot.j[0] = c.j, slot.threshold[0] = c.threshold;
    slot.ex[0] = c.ex, slot.ey[0] = c.ey, slot.ez[0] = c.ez;
    slot.normal1[0] = c.normals[0], slot.normal2[0] = c.normals[1], slot.normal1[b] = c.normals[2];
    slot.normal2[b] = c.normals[3], slot.normal1[2 * b] = c.normals[4], slot.normal2[2 * b] = c.normals[5];
    if (!scheme.candidate(store, slot, 0, c.time, &f)) {
      f.in_order = true;
      return;
    }
  }
}

template <class Scheme>
void EventRounds<Scheme>::advance_to(Scheme& scheme, double t) {
  const std::uint64_t chunk = round_chunk(scheme.particles_);
  // The leader's chunk: four followers' chunks, as in the time-stepped rounds; the last follower's chunk ends
  // when the others are done, at most eight.
  const std::uint64_t lead = 4 * chunk, longest_last = 8 * chunk;
  if (threads_ < 2) {
    scheme.advance_to(t);
    return;
  }
  followers_.resize(static_cast<std::size_t>(threads_));
  RoundStart start;
  bool crossed = false, leader_crossed = false;
  const auto begin_round = [&] {
    start = {scheme.draws_,     scheme.state_.time, scheme.candidate_rate_,        scheme.majorant_,
             scheme.majorant2_, scheme.reference_,  scheme.tally_.majorant_updates};
  };
  std::optional<SpinBarrier> barrier;
#pragma omp parallel num_threads(threads_)
  {
    const auto team = static_cast<std::uint64_t>(omp_get_num_threads());
    const auto u = static_cast<std::uint64_t>(omp_get_thread_num());
    const PinnedThread pinned(PinnedThread::replica_thread_index(static_cast<int>(team)));
    if (u > 0 && !followers_[u]) followers_[u] = std::make_unique<Follower>();
#pragma omp single
    {
      barrier.emplace(static_cast<int>(team));
      begin_round();
    }
    while (!crossed) {
      if (u == 0) {
        leader_crossed = scheme.run_candidates(t, start.first + lead);
      } else {
        Follower& f = *followers_[u];
        const std::uint64_t own = start.first + lead + (u - 1) * chunk;
        f.begin(start);
        note(scheme, f, start, own, t);
        if (!f.crossed) {
          if (u + 1 < team) {
            run_chunk(scheme, f, start, own + chunk, t, [] { return false; });
          } else {
            run_chunk(scheme, f, start, own + longest_last, t,
                      [&] { return barrier->waiting() + 1 == static_cast<int>(team); });
          }
        }
        f.replayed_from = f.kept.size();
      }
      barrier->arrive_and_wait();
      if (u + 1 == team) {  // the last thread: the round's serial part
        if (team == 1) {
          crossed = leader_crossed;
        } else {
          const Follower& last = *followers_[team - 1];
          bool in_order = scheme.tally_.majorant_updates != start.raises;
          for (std::uint64_t w = 1; w < team; ++w) {
            in_order = in_order || followers_[w]->in_order;
            counts_.deferred += followers_[w]->deferred.size();
          }
          for (std::uint64_t w = 1; w < team && !in_order && !leader_crossed; ++w) {
            replay_deferred(scheme, *followers_[w]);
            in_order = followers_[w]->in_order;
          }
          if (leader_crossed || in_order) {  // put the followers' records back; their chunks in order
            for (std::uint64_t w = team; w-- > 1;)
              put_back(scheme, *followers_[w], followers_[w]->replayed_from, followers_[w]->kept.size());
            for (std::uint64_t w = 1; w < team; ++w) put_back(scheme, *followers_[w], 0, followers_[w]->replayed_from);
            if (in_order) ++counts_.in_order;
            crossed = leader_crossed || scheme.run_candidates(t, last.end);
          } else {
            for (std::uint64_t w = 1; w < team; ++w) {
              scheme.tally_.candidates += followers_[w]->tally.candidates;
              scheme.tally_.collisions += followers_[w]->tally.collisions;
            }
            scheme.state_.time = last.now;
            scheme.draw_from(last.end);
            crossed = last.crossed;
          }
          ++counts_.rounds;
        }
        if (!crossed) begin_round();
      }
      barrier->arrive_and_wait();
    }
  }
  scheme.end_interval(t);
}

}  // namespace granmc
