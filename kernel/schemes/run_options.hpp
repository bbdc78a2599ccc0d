#pragma once
#include <functional>

#include "kernel/core/ranks.hpp"

namespace granmc {

struct RunOptions {
  int threads = 0;  // OpenMP threads for the replicas; 0: the OpenMP default
  // At most this many of them inside one replica, where the scheme can use them (the time-stepped scheme's
  // concurrent collision rounds, schemes/concurrent_rounds.hpp): the same bits, but on the machines measured
  // so far not faster than one thread per replica (docs/scaling.md), hence 1 unless asked for.
  int threads_per_replica = 1;
  std::function<void()> on_sample;  // called after each observation of each replica, from any thread
  // This process runs the replicas r with r % replica_stride == replica_offset (MPI ranks,
  // docs/scaling.md); the others stay default-constructed in RunResult::replicas for the caller to fill.
  // The defaults run all replicas.
  int replica_offset = 0;
  int replica_stride = 1;
  // Not null: every replica is one system spread over these ranks (schemes/rank_wave_backend.hpp), the replicas
  // one after another; replica_offset and replica_stride are not read, and every rank returns every replica.
  const Ranks* spread = nullptr;
};

}  // namespace granmc
