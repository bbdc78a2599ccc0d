#pragma once
// Checkpoints of `granmc run` (docs/scenes.md, "Checkpoints"; io/checkpoint.hpp): the finished replicas, and
// the time-stepped scheme's replicas in flight at a sample time, are written to OUT.checkpoint beside the HDF5
// output every `every_minutes` of wall-clock time (0: at every sample and every finished replica) and when
// SIGINT or SIGTERM arrives; then the run ends (exit status 3) and says how to resume. `--resume FILE` goes on
// with the replicas in flight, runs those the checkpoint lacks, and writes the files an uninterrupted run
// writes, bit for bit. At the signal a replica in flight stops at its next sample time; the other schemes'
// replicas lose their work there (they are kept whole only). A checkpoint that cannot be written (a full
// disk) leaves the previous one as it was; the run says so on stderr and goes on.
//
// One process only: under MPI (several ranks, or one replica spread over them) a run has no checkpoints,
// and `--resume` is refused.
#include <chrono>
#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <string>

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

/// The checkpoint file of a run whose HDF5 output is `hdf5`.
std::string checkpoint_path(const std::string& hdf5);

class RunCheckpoints {
 public:
  /// Reads settings.resume, if given (throws CheckpointError naming what is wrong, before anything is written),
  /// and installs the SIGINT and SIGTERM handlers (restored by the destructor).
  RunCheckpoints(const Scene& scene, const std::string& hdf5, const CheckpointSettings& settings);
  ~RunCheckpoints();
  RunCheckpoints(const RunCheckpoints&) = delete;
  RunCheckpoints& operator=(const RunCheckpoints&) = delete;

  /// Hooks the run into `options`: restored replicas, finished ones, and the stop on a signal.
  void attach(RunOptions& options);
  /// Writes the checkpoint now (after RunInterrupted); returns its path.
  const std::string& write_now();
  /// After the run's files are written: removes the checkpoint beside them, which they replace.
  void run_completed();

  [[nodiscard]] std::size_t finished() const;
  /// Replicas kept at a sample time, to go on from there.
  [[nodiscard]] std::size_t in_flight() const;
  [[nodiscard]] std::size_t restored() const noexcept { return restored_; }
  /// Replicas the resumed checkpoint had in flight (the time-stepped scheme goes on with them mid-run).
  [[nodiscard]] std::size_t restored_in_flight() const noexcept { return restored_in_flight_; }

 private:
  void write_locked();
  void write_if_due_locked();  // when every_minutes have passed since the last write
  static double minutes_since(std::chrono::steady_clock::time_point t);

  CheckpointSettings settings_;
  std::string path_;
  mutable std::mutex mutex_;
  Checkpoint checkpoint_;
  std::size_t restored_ = 0, restored_in_flight_ = 0;
  std::chrono::steady_clock::time_point started_, last_write_;
  std::map<std::uint64_t, std::chrono::steady_clock::time_point> last_in_flight_;  // per replica in flight
};

}  // namespace granmc
