#pragma once
// Replicas over MPI ranks (built only with GRANMC_MPI=ON; docs/developer-guide/scaling.md). Rank k of R runs the
// replicas r with r % R == k (RunOptions::replica_offset, replica_stride); gather_replicas then brings every
// ReplicaSeries to rank 0 as a byte-exact copy, in replica order, so that rank 0's RunResult is the one a
// single process computes with the same seed (each replica depends only on (seed, replica),
// kernel/core/philox_stream.hpp).
//
// The replicas travel in io/replica_bytes.hpp's format, private to one executable (all ranks run the same
// binary on the same kind of machine).
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

#include "io/replica_bytes.hpp"
#include "kernel/core/ranks.hpp"
#include "kernel/observe/gas_series.hpp"

namespace granmc::mpi {

// --- MPI (MPI_COMM_WORLD) ---

struct World {
  int rank = 0;
  int size = 1;
};

/// MPI_Init_thread (funneled: only the main thread calls MPI, OpenMP threads run the replicas) in the
/// constructor, MPI_Finalize in the destructor.
class Session {
 public:
  Session(int& argc, char**& argv);
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;
};

/// This rank and the number of ranks of the run: MPI_COMM_WORLD, or this rank's group while a RankGroups
/// lives. Every collective below (but abort_all) acts on the same ranks.
World world();

/// Splits the world into `groups` groups of consecutive ranks (collective over the world); while it lives,
/// the run's collectives act within this rank's group, so that a sweep can give whole scenes to groups.
class RankGroups {
 public:
  explicit RankGroups(int groups);
  ~RankGroups();
  RankGroups(const RankGroups&) = delete;
  RankGroups& operator=(const RankGroups&) = delete;
  /// This rank's group, 0 .. groups - 1.
  [[nodiscard]] int group() const noexcept { return group_; }

 private:
  int group_ = 0;
};

/// Element-wise maximum over every rank of the world, whatever RankGroups is in force (collective).
void world_max(std::span<int> values);

/// True on every rank when `ok_here` is true on every rank (collective).
bool all_ok(bool ok_here);
/// True on every rank when rank 0's `ok_here` was true (collective).
bool root_ok(bool ok_here);

/// The ranks of the run (world() above) as kernel/core/ranks.hpp's collectives (one system over several ranks).
class WorldRanks final : public Ranks {
 public:
  [[nodiscard]] int rank() const noexcept override;
  [[nodiscard]] int size() const noexcept override;
  void sum(std::span<double> values) const override;
  [[nodiscard]] double max(double value) const override;
  void exchange(const std::vector<std::vector<double>>& send, std::vector<std::vector<double>>& receive) const override;
};

/// Ends every rank of the run (MPI_Abort) with this exit status.
[[noreturn]] void abort_all(int status);

/// Collective: `local` holds this rank's replicas (RunOptions offset = rank, stride = size), the others
/// default-constructed. Rank 0 returns the RunResult with every replica in place; the other ranks return
/// `local` with no replicas. Throws std::runtime_error on a malformed message.
RunResult gather_replicas(RunResult local);

}  // namespace granmc::mpi
