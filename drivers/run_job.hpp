#pragma once
// One scene run as `granmc run` runs it, shared by `granmc run` and `granmc sweep`: the replicas spread over
// the MPI ranks (replica r on rank r mod R, docs/developer-guide/scaling.md), gathered byte-exact to rank 0, which
// alone makes the report and writes the HDF5 file and the JSON summary (temporary name, then rename). Without MPI
// (GRANMC_MPI=OFF) there is one process, rank 0 of 1, and nothing here is collective.
#include <exception>
#include <string>

#include "drivers/run_checkpoints.hpp"
#include "kernel/core/scene.hpp"
#include "kernel/setup/run_plan.hpp"

namespace granmc {

/// This process among the MPI ranks: it runs the replicas r with r % size == rank, and rank 0 alone prints
/// and writes.
struct Place {
  int rank = 0;
  int size = 1;
};

Place place();

/// How many of `replicas` replicas this process runs.
int own_replicas(int replicas, Place at);

/// Collective: true on every rank when `ok_here` is true on every rank, so that no rank goes on into a
/// collective the others have left. A rank that is not ok prints `message` (stderr) when it is rank 0 or
/// rank 0 was ok, so the message appears once, from rank 0 if it has one.
bool all_ranks_ok(bool ok_here, const std::string& message);

/// Collective: rank 0's `value` on every rank (decisions only rank 0 can take, e.g. from the files it wrote).
bool rank0_value(bool value);

struct JobOutputs {
  std::string hdf5;
  std::string summary;  // empty: no summary
};

struct JobResult {
  double wall_seconds = 0.0;  // rank 0's, from the start of its replicas to the end of the gather
  int threads = 0;            // this rank's OpenMP threads
};

/// Runs `plan`, made from `scene`, with this rank's replicas on `threads` threads (0: the
/// OpenMP default), at most `threads_per_replica` inside one replica (RunOptions), gathers them to rank 0, and there
/// writes `outputs` (creating their directories). The progress line shows on rank 0 when stderr is a terminal, unless
/// `quiet`. Collective under MPI. Throws std::exception on failure; report it with run_failure. With plan.spread =
/// Spread::particles, every replica is one system over all ranks instead (schemes/rank_wave_backend.hpp), the replicas
/// one after another on one thread per rank. With `checkpoints` (not with Spread::particles), the run restores and
/// checkpoints this rank's replicas through it (drivers/run_checkpoints.hpp), keeps them there before the gather,
/// and throws RunInterrupted when a signal stopped it.
JobResult run_job(const Scene& scene, const RunPlan& plan, const JobOutputs& outputs, int threads, bool quiet,
                  int threads_per_replica = 0, RunCheckpoints* checkpoints = nullptr);

/// A failure during a run: one message and exit status 1. Over several MPI ranks the message names the rank
/// and every rank is ended (MPI_Abort), so that none waits for it.
int run_failure(const std::exception& e);

}  // namespace granmc
