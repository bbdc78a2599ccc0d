#pragma once
// A checkpoint of a run (`granmc run --checkpoint-every`, `--resume`; docs/formats/scenes.md, "Checkpoints"): the
// series of the replicas that have finished and the state of those stopped at a sample time (the
// time-stepped and time-step-free schemes', kernel/schemes/replica_in_flight.hpp), with what identifies the run they
// belong to (the build, the scene text, the seed, the number of replicas). Each replica depends only on (seed, replica)
// (kernel/core/philox_stream.hpp), so a run resumed from it goes on with the replicas in flight, runs the
// others and writes the files an uninterrupted run writes, bit for bit.
//
// File: a magic line, the format version, a byte-order mark, the identity, then each finished replica as
// its index and io/replica_bytes.hpp's bytes, then each replica in flight the same way, and last a 64-bit
// FNV-1a checksum of everything before it.
// Native byte order and the replica bytes of one build: a checkpoint is read by the build that wrote it.
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>

#include "kernel/observe/gas_series.hpp"
#include "kernel/schemes/replica_in_flight.hpp"

namespace granmc {

inline constexpr std::uint32_t checkpoint_format_version = 4;

struct Checkpoint {
  std::string build;       // io/build_id.hpp of the build that wrote it
  std::string scene_text;  // Scene::source_text of the run
  std::uint64_t seed = 0;  // the run's seed (run.seed or --seed)
  std::uint64_t replicas = 0;
  std::map<std::uint64_t, ReplicaSeries> finished;     // replica index -> its series
  std::map<std::uint64_t, ReplicaInFlight> in_flight;  // replica index -> its state at a sample time
};

/// A file that is not a checkpoint this build can resume from; what() says why.
class CheckpointError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Writes `checkpoint` to `path` atomically (io/atomic_file.hpp): on failure the previous checkpoint is intact,
/// and the std::runtime_error says so.
void write_checkpoint(const std::string& path, const Checkpoint& checkpoint);

/// Reads a checkpoint; throws CheckpointError for a file that is missing, not a checkpoint, of another format
/// version or byte order, truncated or corrupt (checksum).
Checkpoint read_checkpoint(const std::string& path);

/// Adds to `into` what `other` (a checkpoint of the same run, e.g. another MPI rank's) holds: its finished
/// replicas, and its replicas in flight that `into` has neither finished nor taken further (more samples).
/// So checkpoint files of one run merge in any order to the furthest state of each replica.
void merge_checkpoint(Checkpoint& into, Checkpoint&& other);

/// Why `checkpoint` cannot resume the run of this build with this scene text, seed and replicas ("" if it can).
std::string checkpoint_mismatch(const Checkpoint& checkpoint, const std::string& build, const std::string& scene_text,
                                std::uint64_t seed, std::uint64_t replicas);

}  // namespace granmc
