#pragma once
// `granmc sweep SWEEP.toml`: the scenes of a sweep file (io/sweep_file.hpp) run one after another as one
// job, each exactly as `granmc run` runs it (drivers/run_job.hpp, over the MPI ranks when there are
// several). The output directory gets <name>.h5 and <name>.json per scene and index.json, which lists every
// scene with its values, files, status (done or pending) and the hash of the scene text it runs; rank 0
// rewrites it (temporary name, then rename) before the first scene and after each one. A rerun skips the
// scenes that index.json records as done with the same scene hash and whose two files exist, and removes
// the temporary files (NAME.tmp-PID) an interrupted run left of its outputs.
// docs/user-guide/parallel-runs.md, "Sweeps".
#include <string>

namespace granmc {

struct SweepArgs {
  std::string sweep;            // the sweep file
  std::string out_dir;          // empty: the sweep file's stem, in the current directory
  int threads = 0;              // 0: the OpenMP default
  int threads_per_replica = 0;  // at most this many inside one replica (run_job; 0: by the replicas' size)
  bool quiet = false;
  bool keep_other_builds = false;  // keep the files of scenes done by another build of granmc (not rerun)
};

/// Exit status as cli_main's: 2 for a bad sweep file or scene (one message, nothing written).
int sweep_command(const SweepArgs& args);

}  // namespace granmc
