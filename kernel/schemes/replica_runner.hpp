#pragma once
// Runs the replicas of a scene in parallel (OpenMP), each from its own random stream, and collects
// their series in replica order: the result is the same for any thread count, and the same when some replicas
// come from a checkpoint (RunOptions::restored). Threads beyond the replicas go
// inside them where the scheme can use them and RunOptions::threads_per_replica allows (share_threads). With
// RunOptions'
// replica_offset and replica_stride it runs only its share (MPI ranks) and leaves the rest empty.
#include <omp.h>

#include <algorithm>
#include <cstdint>
#include <exception>
#include <limits>
#include <utility>
#include <vector>

#include "kernel/core/scene.hpp"
#include "kernel/observe/gas_series.hpp"
#include "kernel/schemes/run_options.hpp"
#include "kernel/schemes/sample_times.hpp"

namespace granmc {

/// How a run's threads are shared: `concurrent` replicas at a time, each with `inside` threads of its own (the
/// time-stepped scheme's concurrent collision rounds, schemes/concurrent_rounds.hpp).
struct ThreadShare {
  int concurrent = 1;
  int inside = 1;
};

/// The replicas this process runs: offset, offset + stride, ... below run.replicas (run_options.hpp).
inline int own_replicas(const Scene& scene, const RunOptions& options) noexcept {
  const int n = scene.run.replicas, stride = options.replica_stride;
  return n > options.replica_offset ? (n - options.replica_offset + stride - 1) / stride : 0;
}

/// The threads a scheme's replica can take: at most `most`, and, unless RunOptions::threads_per_replica says
/// otherwise, more than one only for a replica of at least `least_particles` particles (all species), the size
/// from which its concurrent rounds were measured faster than one thread.
struct ThreadsInside {
  int most = 1;
  std::uint64_t least_particles = 0;
};
/// A scheme that runs a replica on one thread.
inline constexpr ThreadsInside one_thread_inside{};
/// The time-stepped scheme's concurrent rounds (schemes/concurrent_rounds.hpp): on two threads 1.6x one at 10^6
/// and 10^7 particles in every run, 0.8x to 1.8x from run to run between 2 10^5 and 4 10^5, 0.9x at 10^5
/// (docs/developer-guide/scaling.md, "Concurrent collision rounds").
inline constexpr ThreadsInside stepped_rounds_inside{std::numeric_limits<int>::max(), 1'000'000};
/// The event scheme's rounds (schemes/event_rounds.hpp): 1.5x at 10^7, 1.4x at 10^6, 1.2-1.3x at 10^5; smaller
/// replicas not measured (docs/developer-guide/scaling.md, "The event scheme's rounds").
inline constexpr ThreadsInside event_rounds_inside{std::numeric_limits<int>::max(), 100'000};

/// The particles of one replica of the scene.
inline std::uint64_t replica_particles(const Scene& scene) noexcept {
  std::uint64_t n = 0;
  for (const SpeciesConfig& s : scene.species) n += static_cast<std::uint64_t>(s.particles);
  return n;
}

/// The threads first to replicas, one each; the threads left over to the replicas, up to `inside.most` each and
/// up to RunOptions::threads_per_replica, or by default (0) to replicas of at least `inside.least_particles`.
inline ThreadShare share_threads(const Scene& scene, const RunOptions& options, const ThreadsInside& inside) {
  const int threads = options.threads > 0 ? options.threads : omp_get_max_threads();
  ThreadShare share;
  share.concurrent = std::max(1, std::min(threads, own_replicas(scene, options)));
  const int asked = options.threads_per_replica > 0                      ? options.threads_per_replica
                    : replica_particles(scene) >= inside.least_particles ? inside.most
                                                                         : 1;
  share.inside = std::max(1, std::min({inside.most, asked, threads / share.concurrent}));
  return share;
}

/// run_one(replica, times) -> ReplicaSeries, share.concurrent replicas at a time.
template <class RunOne>
RunResult run_replicas(const Scene& scene, const RunOptions& options, const ThreadShare& share, RunOne&& run_one) {
  RunResult result;
  result.times = sample_times(scene.run);
  for (const SpeciesConfig& s : scene.species) result.species_names.push_back(s.name);
  const int n = scene.run.replicas;
  result.replicas.resize(static_cast<std::size_t>(n));
  result.threads = share.concurrent * share.inside;
  result.threads_per_replica = share.inside;
  if (share.inside > 1) omp_set_max_active_levels(2);  // the replicas' own teams inside the replicas' team
  std::exception_ptr failure;
  bool stopped = false;
  const int stride = options.replica_stride;
  const int own = own_replicas(scene, options);
#pragma omp parallel for schedule(dynamic, 1) num_threads(share.concurrent)
  for (int k = 0; k < own; ++k) {
    const int r = options.replica_offset + k * stride;
    ReplicaSeries& series = result.replicas[static_cast<std::size_t>(r)];
    const ReplicaSeries* earlier = options.restored ? options.restored(static_cast<std::uint64_t>(r)) : nullptr;
    if (earlier != nullptr) {
      series = *earlier;  // from a checkpoint: the series this replica's run gives, bit for bit
      continue;
    }
    try {
      if (options.interrupted && options.interrupted()) throw RunInterrupted();
      series = run_one(static_cast<std::uint64_t>(r), result.times);
      if (options.on_replica) options.on_replica(static_cast<std::uint64_t>(r), series);
    } catch (const RunInterrupted&) {
#pragma omp atomic write
      stopped = true;
    } catch (...) {
#pragma omp critical(granmc_replica_failure)
      if (!failure) failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
  if (stopped) throw RunInterrupted();
  return result;
}

}  // namespace granmc
