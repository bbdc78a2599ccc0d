#pragma once
// Checkpoints of `granmc run` (docs/scenes.md, "Checkpoints"; io/checkpoint.hpp): the finished replicas are
// written to OUT.checkpoint beside the HDF5 output every `every_minutes` of wall-clock time (0: after each
// replica that finishes) and when SIGINT or SIGTERM arrives; then the run ends (exit status 3) and says how to
// resume. `--resume FILE` runs only the replicas the checkpoint lacks and writes the files an uninterrupted
// run writes, bit for bit. A replica in flight at the signal stops at its next observation and its work is
// lost: checkpoints are whole replicas. A checkpoint that cannot be written (a full disk) leaves the previous
// one as it was; the run says so on stderr and goes on.
//
// One process only: under MPI (several ranks, or one replica spread over them) a run has no checkpoints,
// and `--resume` is refused.
#include <chrono>
#include <cstdint>
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
  double every_minutes = 10.0;  // 0: after every replica that finishes
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
  [[nodiscard]] std::size_t restored() const noexcept { return restored_; }

 private:
  void write_locked();

  CheckpointSettings settings_;
  std::string path_;
  mutable std::mutex mutex_;
  Checkpoint checkpoint_;
  std::size_t restored_ = 0;
  std::chrono::steady_clock::time_point last_write_;
};

}  // namespace granmc
