#include "drivers/run_job.hpp"

#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <iostream>

#include "drivers/cli.hpp"
#include "drivers/progress.hpp"
#include "io/hdf5_output.hpp"
#include "io/summary_json.hpp"
#include "kernel/analysis/run_report.hpp"
#include "kernel/schemes/run_options.hpp"
#include "kernel/setup/run_scene.hpp"
#ifdef GRANMC_HAVE_MPI
#include "drivers/mpi_replicas.hpp"
#endif

namespace granmc {

namespace {

/// The run's result with every replica: the result itself in one process; over several MPI ranks,
/// rank 0's gathered copy (drivers/mpi_replicas.hpp), the other ranks' without replicas.
RunResult completed(RunResult local) {
#ifdef GRANMC_HAVE_MPI
  return mpi::gather_replicas(std::move(local));
#else
  return local;
#endif
}

}  // namespace

Place place() {
#ifdef GRANMC_HAVE_MPI
  const mpi::World w = mpi::world();
  return {w.rank, w.size};
#else
  return {};
#endif
}

int own_replicas(int replicas, Place at) {
  return replicas > at.rank ? (replicas - at.rank + at.size - 1) / at.size : 0;
}

bool all_ranks_ok(bool ok_here, const std::string& message) {
#ifdef GRANMC_HAVE_MPI
  const bool root_is_ok = mpi::root_ok(ok_here);
  if (!ok_here && (place().rank == 0 || root_is_ok)) std::cerr << message;
  return mpi::all_ok(ok_here);
#else
  if (!ok_here) std::cerr << message;
  return ok_here;
#endif
}

bool rank0_value(bool value) {
#ifdef GRANMC_HAVE_MPI
  return mpi::root_ok(value);
#else
  return value;
#endif
}

JobResult run_job(const Scene& scene, const RunPlan& plan, const JobOutputs& outputs, int threads, bool quiet,
                  int threads_per_replica, RunCheckpoints* checkpoints) {
  const bool spread_particles = plan.spread == Spread::particles;
  const Place at = place();
  const ProgressLine::Mode progress_mode = at.rank != 0 || quiet   ? ProgressLine::Mode::off
                                           : isatty(STDERR_FILENO) ? ProgressLine::Mode::terminal
                                                                   : ProgressLine::Mode::log;
  const int replicas_here = spread_particles ? scene.run.replicas : own_replicas(scene.run.replicas, at);
  // The samples left: those of the replicas the checkpoint lacks, less those its replicas in flight have taken.
  const int to_run = replicas_here - static_cast<int>(checkpoints != nullptr ? checkpoints->restored() : 0);
  const std::uint64_t taken = checkpoints != nullptr ? checkpoints->restored_samples() : 0;
  ProgressLine progress(static_cast<std::uint64_t>(to_run) * (scene.run.samples + 1) - taken, progress_mode);
  RunOptions options;
  options.threads = threads;
  options.threads_per_replica = threads_per_replica;
  options.on_sample = [&progress] { progress.tick(); };
  options.replica_offset = at.rank;
  options.replica_stride = at.size;
#ifdef GRANMC_HAVE_MPI
  const mpi::WorldRanks ranks;
#else
  const SingleRank ranks;
#endif
  if (spread_particles) options.spread = &ranks;
  if (checkpoints != nullptr) checkpoints->attach(options);

  const auto start = std::chrono::steady_clock::now();
  // Spread over the ranks, every rank holds every replica's series; otherwise rank 0 gathers them, after each
  // rank has kept its replicas in its checkpoint (a run ended while ranks wait loses none of them).
  RunResult result = run_plan(plan, scene, options);
  if (!spread_particles) {
    if (checkpoints != nullptr && at.size > 1) checkpoints->write_before_waiting();
    result = completed(std::move(result));
  }
  result.ranks = at.size;
  progress.finish();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (at.rank != 0) return {wall, result.threads};  // rank 0 alone reports and writes
  const RunReport report = make_run_report(scene, result, wall);
  for (const std::string& file : {outputs.hdf5, outputs.summary}) {
    const auto dir = std::filesystem::path(file).parent_path();
    if (!file.empty() && !dir.empty()) std::filesystem::create_directories(dir);
  }
  write_hdf5(outputs.hdf5, scene, result, report);
  if (!outputs.summary.empty()) write_summary(outputs.summary, summary_json(scene, result, report));
  if (checkpoints != nullptr) checkpoints->run_completed();
  return {wall, result.threads};
}

int run_failure(const std::exception& e) {
  const Place at = place();
  if (at.size == 1) {
    std::cerr << "granmc: run failed: " << e.what() << "\n";
    return exit_run_failure;
  }
  std::cerr << "granmc: run failed on MPI rank " << at.rank << " of " << at.size << ": " << e.what()
            << "\n(ending all ranks)\n"
            << std::flush;
#ifdef GRANMC_HAVE_MPI
  mpi::abort_all(exit_run_failure);
#endif
  return exit_run_failure;
}

}  // namespace granmc
