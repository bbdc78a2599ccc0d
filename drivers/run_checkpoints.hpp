#pragma once
// Checkpoints of `granmc run` (docs/formats/scenes.md, "Checkpoints"; io/checkpoint.hpp): the finished replicas, and
// the gas schemes' replicas in flight at a sample time, are written to OUT.checkpoint beside the HDF5
// output every `every_minutes` of wall-clock time (0: at every sample and every finished replica) and when
// SIGINT or SIGTERM arrives; then the run ends (exit status 3) and says how to resume. `--resume FILE` goes on
// with the replicas in flight, runs those the checkpoint lacks, and writes the files an uninterrupted run
// writes, bit for bit. At the signal a replica in flight stops at its next sample time; the replicas of the
// intruder schemes lose their work there (they are kept whole only). A checkpoint that cannot be
// written (a full disk) leaves the previous one as it was; the run says so on stderr and goes on.
//
// Over MPI ranks (replicas on ranks, drivers/mpi_replicas.hpp) each rank keeps its own replicas in its own file,
// OUT.checkpoint.K-of-R for rank K of R, written on its own clock and before it waits for the others at the
// end. `--resume OUT.checkpoint` reads every file of the run (OUT.checkpoint and each OUT.checkpoint.K-of-R),
// merges them (io/checkpoint.hpp: each replica at its furthest state) and goes on in one process or on any
// number of ranks, each rank taking its own replicas. A run with one replica spread over the ranks
// (run.spread = particles) has no checkpoints.
#include <chrono>
#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "io/checkpoint.hpp"
#include "kernel/core/scene.hpp"
#include "kernel/schemes/run_options.hpp"

namespace granmc {

inline constexpr int exit_interrupted = 3;

struct CheckpointSettings {
  bool enabled = true;
  double every_minutes = 10.0;  // 0: at every sample and every finished replica
  std::string resume;           // a checkpoint to continue from, or empty
};

/// The checkpoint of a run whose HDF5 output is `hdf5`: the file of a run in one process, and the name that
/// `--resume` takes for a run on any number of ranks.
std::string checkpoint_path(const std::string& hdf5);
/// The file rank `rank` of `ranks` writes: `base` itself for one rank, else base.K-of-R.
std::string checkpoint_file(const std::string& base, int rank, int ranks);
/// The files of the checkpoint `base` that exist: base itself and each base.K-of-R, in name order. A path of
/// the form base.K-of-R stands for its base.
std::vector<std::string> checkpoint_files(const std::string& base);

class RunCheckpoints {
 public:
  /// Reads settings.resume, if given: every file of that checkpoint, merged, of which rank `rank` of `ranks`
  /// keeps its own replicas (throws CheckpointError naming what is wrong, before anything is written); and
  /// installs the SIGINT and SIGTERM handlers (restored by the destructor).
  RunCheckpoints(const Scene& scene, const std::string& hdf5, const CheckpointSettings& settings, int rank = 0,
                 int ranks = 1);
  ~RunCheckpoints();
  RunCheckpoints(const RunCheckpoints&) = delete;
  RunCheckpoints& operator=(const RunCheckpoints&) = delete;

  /// Hooks the run into `options`: restored replicas, finished ones, and the stop on a signal.
  void attach(RunOptions& options);
  /// Writes the checkpoint now (after RunInterrupted); returns its path.
  const std::string& write_now();
  /// Over MPI ranks, when this rank's replicas are done and it waits for the others: writes its file, so that
  /// nothing it ran is lost if the run ends there (a failed write is reported and the run goes on).
  void write_before_waiting();
  /// After the run's files are written: removes every file of the checkpoint, which they replace.
  void run_completed();

  [[nodiscard]] std::size_t finished() const;
  /// Replicas kept at a sample time, to go on from there.
  [[nodiscard]] std::size_t in_flight() const;
  /// Of this rank's replicas, those the resumed checkpoint had finished.
  [[nodiscard]] std::size_t restored() const noexcept { return restored_; }
  /// Of this rank's replicas, those it had in flight (they go on from the sample time they stopped at).
  [[nodiscard]] std::size_t restored_in_flight() const noexcept { return restored_in_flight_; }
  /// The samples this rank's replicas in flight had taken.
  [[nodiscard]] std::uint64_t restored_samples() const noexcept { return restored_samples_; }
  /// The same two over every rank's replicas.
  [[nodiscard]] std::size_t restored_all() const noexcept { return restored_all_; }
  [[nodiscard]] std::size_t restored_in_flight_all() const noexcept { return restored_in_flight_all_; }

 private:
  void write_locked();
  void write_if_due_locked();              // when every_minutes have passed since the last write
  void write_or_report_locked() noexcept;  // a failed write is reported; the run goes on
  static double minutes_since(std::chrono::steady_clock::time_point t);

  CheckpointSettings settings_;
  std::string base_, path_;
  mutable std::mutex mutex_;
  Checkpoint checkpoint_;
  std::size_t restored_ = 0, restored_in_flight_ = 0, restored_all_ = 0, restored_in_flight_all_ = 0;
  std::uint64_t restored_samples_ = 0;
  std::chrono::steady_clock::time_point started_, last_write_;
  std::map<std::uint64_t, std::chrono::steady_clock::time_point> last_in_flight_;  // per replica in flight
};

}  // namespace granmc
