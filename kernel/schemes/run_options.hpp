#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <variant>

#include "kernel/core/ranks.hpp"
#include "kernel/observe/gas_series.hpp"
#include "kernel/schemes/replica_in_flight.hpp"

namespace granmc {

/// A run stopped on request (RunOptions::interrupted, or thrown by on_sample to stop a replica in flight): the
/// replicas that finished were handed to RunOptions::on_replica; the others did not run.
class RunInterrupted : public std::runtime_error {
 public:
  RunInterrupted() : std::runtime_error("the run was interrupted") {}
};

struct RunOptions {
  int threads = 0;  // OpenMP threads for the replicas; 0: the OpenMP default
  // At most this many of them inside one replica, where the scheme can use them (concurrent collision rounds,
  // schemes/concurrent_rounds.hpp and schemes/event_rounds.hpp): the same bits for any number. 0: the threads the
  // replicas leave over go inside replicas large enough for the rounds to be faster than one thread
  // (schemes/replica_runner.hpp, share_threads).
  int threads_per_replica = 0;
  std::function<void()> on_sample;  // called after each observation of each replica, from any thread
  // This process runs the replicas r with r % replica_stride == replica_offset (MPI ranks,
  // docs/developer-guide/scaling.md); the others stay default-constructed in RunResult::replicas for the caller to
  // fill. The defaults run all replicas.
  int replica_offset = 0;
  int replica_stride = 1;
  // Not null: every replica is one system spread over these ranks (schemes/rank_wave_backend.hpp), the replicas
  // one after another; replica_offset and replica_stride are not read, and every rank returns every replica.
  const Ranks* spread = nullptr;
  // Checkpoints (io/checkpoint.hpp, drivers/run_checkpoints.hpp), for the replicas run by run_replicas: not null,
  // `restored(r)` is replica r's series from an earlier run (then it is not run again), or null; `on_replica(r,
  // series)` is called from replica r's thread when it has finished; `interrupted()` true: no further replica
  // starts, and run_replicas ends with RunInterrupted once the replicas in flight have ended (on_sample may throw
  // RunInterrupted to end one at its next observation; its work is lost).
  std::function<const ReplicaSeries*(std::uint64_t)> restored;
  std::function<void(std::uint64_t, const ReplicaSeries&)> on_replica;
  std::function<bool()> interrupted;
  // Replicas in flight, for a scheme that can stop at a sample and go on (the time-stepped and time-step-free
  // ones, schemes/replica_in_flight.hpp): after each observation but the last, when `in_flight_wanted(r)`, it
  // hands replica r's state to `on_in_flight` (before on_sample, which may then stop it);
  // `restored_in_flight(r)` is such a state from an earlier run to go on from, or null.
  std::function<bool(std::uint64_t)> in_flight_wanted;
  std::function<void(std::uint64_t, ReplicaInFlight&&)> on_in_flight;
  std::function<const ReplicaInFlight*(std::uint64_t)> restored_in_flight;
};

/// Replica `replica`'s state from an earlier run to go on from (RunOptions::restored_in_flight), or null.
inline const ReplicaInFlight* restored_in_flight(const RunOptions& options, std::uint64_t replica) {
  return options.restored_in_flight ? options.restored_in_flight(replica) : nullptr;
}

/// Replica `replica` goes on from the state options.restored_in_flight gives, if there is one: `sim` put back
/// in it (Scheme::restore of a Snapshot) and `series` the observations so far; returns the index of the next
/// sample time (0 without such a state).
template <class Snapshot, class Scheme>
std::size_t resume_in_flight(const RunOptions& options, std::uint64_t replica, Scheme& sim, ReplicaSeries& series) {
  const ReplicaInFlight* earlier = restored_in_flight(options, replica);
  if (earlier == nullptr) return 0;
  sim.restore(std::get<Snapshot>(earlier->state));
  series = earlier->series;
  return static_cast<std::size_t>(earlier->samples_taken);
}

/// Whether replica `replica` hands its state to options.on_in_flight after observation k of `sample_times`
/// (never after the last: the replica is then finished).
inline bool in_flight_wanted(const RunOptions& options, std::uint64_t replica, std::size_t k,
                             std::size_t sample_times) {
  return k + 1 < sample_times && options.in_flight_wanted && options.in_flight_wanted(replica);
}

}  // namespace granmc
