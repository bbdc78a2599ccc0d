#pragma once
// Runs the replicas of a scene in parallel (OpenMP), each from its own random stream, and collects
// their series in replica order: the result is the same for any thread count. With RunOptions'
// replica_offset and replica_stride it runs only its share (MPI ranks) and leaves the rest empty.
#include <omp.h>

#include <cstdint>
#include <exception>
#include <vector>

#include "kernel/core/scene.hpp"
#include "kernel/observe/gas_series.hpp"
#include "kernel/schemes/run_options.hpp"
#include "kernel/schemes/sample_times.hpp"

namespace granmc {

/// run_one(replica, times) -> ReplicaSeries.
template <class RunOne>
RunResult run_replicas(const Scene& scene, const RunOptions& options, RunOne&& run_one) {
  RunResult result;
  result.times = sample_times(scene.run);
  for (const SpeciesConfig& s : scene.species) result.species_names.push_back(s.name);
  const int n = scene.run.replicas;
  result.replicas.resize(static_cast<std::size_t>(n));
  const int threads = options.threads > 0 ? options.threads : omp_get_max_threads();
  result.threads = threads;
  std::exception_ptr failure;
  const int stride = options.replica_stride;  // own replicas: offset, offset + stride, ... (run_options.hpp)
  const int own = n > options.replica_offset ? (n - options.replica_offset + stride - 1) / stride : 0;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (int k = 0; k < own; ++k) {
    const int r = options.replica_offset + k * stride;
    try {
      result.replicas[static_cast<std::size_t>(r)] = run_one(static_cast<std::uint64_t>(r), result.times);
    } catch (...) {
#pragma omp critical(granmc_replica_failure)
      if (!failure) failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
  return result;
}

}  // namespace granmc
