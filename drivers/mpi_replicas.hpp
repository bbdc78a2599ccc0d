#pragma once
// Replicas over MPI ranks (built only with GRANMC_MPI=ON; docs/scaling.md). Rank k of R runs the replicas
// r with r % R == k (RunOptions::replica_offset, replica_stride); gather_replicas then brings every
// ReplicaSeries to rank 0 as a byte-exact copy, in replica order, so that rank 0's RunResult is the one a
// single process computes with the same seed (each replica depends only on (seed, replica),
// kernel/core/philox_stream.hpp).
//
// The byte format is private to one run of one executable (all ranks run the same binary on the same kind
// of machine): native byte order, sizes as std::uint64_t, trivially copyable arrays copied with memcpy.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

#include "kernel/core/ranks.hpp"
#include "kernel/observe/gas_series.hpp"

namespace granmc::mpi {

/// Appends values and arrays to a byte buffer.
class ByteWriter {
 public:
  template <class T>
  void value(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    raw(&v, sizeof(T));
  }
  /// The size, then the elements' bytes.
  template <class T>
  void array(const std::vector<T>& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    value(static_cast<std::uint64_t>(v.size()));
    raw(v.data(), v.size() * sizeof(T));
  }
  [[nodiscard]] const std::vector<std::byte>& bytes() const noexcept { return bytes_; }
  [[nodiscard]] std::vector<std::byte> release() noexcept { return std::move(bytes_); }

 private:
  void raw(const void* data, std::size_t size) {
    if (size == 0) return;
    const std::size_t at = bytes_.size();
    bytes_.resize(at + size);
    std::memcpy(bytes_.data() + at, data, size);
  }
  std::vector<std::byte> bytes_;
};

/// Reads back what ByteWriter wrote, in the same order; throws std::runtime_error past the end.
class ByteReader {
 public:
  explicit ByteReader(std::span<const std::byte> bytes) noexcept : bytes_(bytes) {}
  template <class T>
  T value() {
    static_assert(std::is_trivially_copyable_v<T>);
    T v;
    raw(&v, sizeof(T));
    return v;
  }
  template <class T>
  std::vector<T> array() {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto n = value<std::uint64_t>();
    if (n > (bytes_.size() - position_) / sizeof(T)) throw std::runtime_error("replica message: array past the end");
    std::vector<T> v(static_cast<std::size_t>(n));
    raw(v.data(), v.size() * sizeof(T));
    return v;
  }
  [[nodiscard]] bool at_end() const noexcept { return position_ == bytes_.size(); }

 private:
  void raw(void* data, std::size_t size) {
    if (size > bytes_.size() - position_) throw std::runtime_error("replica message: read past the end");
    if (size == 0) return;
    std::memcpy(data, bytes_.data() + position_, size);
    position_ += size;
  }
  std::span<const std::byte> bytes_;
  std::size_t position_ = 0;
};

/// Every field of a replica's series, the optional IntruderSeries included.
void write_replica(ByteWriter& out, const ReplicaSeries& series);
ReplicaSeries read_replica(ByteReader& in);

/// The replicas r = offset, offset + stride, ... of `replicas`, as bytes (count first).
std::vector<std::byte> serialise_replicas(const std::vector<ReplicaSeries>& replicas, int offset, int stride);
/// Writes the series of `bytes` to replicas[offset], [offset + stride], ...; throws std::runtime_error if
/// the count does not match replicas.size() or the bytes are not exactly one such list.
void deserialise_replicas(std::span<const std::byte> bytes, std::vector<ReplicaSeries>& replicas, int offset,
                          int stride);

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
