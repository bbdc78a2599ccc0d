#include "drivers/mpi_replicas.hpp"

#include <mpi.h>

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <optional>
#include <string>

namespace granmc::mpi {

namespace {

/// The communicator of the run's collectives: the world, or this rank's group while a RankGroups lives.
MPI_Comm run_communicator = MPI_COMM_WORLD;
MPI_Comm run_comm() { return run_communicator; }

void check(int code, const char* what) {
  if (code != MPI_SUCCESS) throw std::runtime_error(std::string("MPI error in ") + what);
}

/// Messages of at most 2^30 bytes (MPI counts are int).
constexpr std::size_t chunk_bytes = std::size_t{1} << 30;
constexpr int tag_replicas = 1;

}  // namespace

Session::Session(int& argc, char**& argv) {
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
}

Session::~Session() { MPI_Finalize(); }

World world() {
  World w;
  MPI_Comm_rank(run_comm(), &w.rank);
  MPI_Comm_size(run_comm(), &w.size);
  return w;
}

RankGroups::RankGroups(int groups) {
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  group_ = static_cast<int>(static_cast<long long>(rank) * groups / size);  // consecutive ranks
  MPI_Comm group;
  check(MPI_Comm_split(MPI_COMM_WORLD, group_, rank, &group), "MPI_Comm_split");
  run_communicator = group;
}

RankGroups::~RankGroups() {
  MPI_Comm group = run_communicator;
  run_communicator = MPI_COMM_WORLD;
  MPI_Comm_free(&group);
}

void world_max(std::span<int> values) {
  MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_INT, MPI_MAX, MPI_COMM_WORLD);
}

int WorldRanks::rank() const noexcept { return world().rank; }
int WorldRanks::size() const noexcept { return world().size; }

void WorldRanks::sum(std::span<double> values) const {
  if (values.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw std::runtime_error("spread system: a sum of more than 2^31 values");
  MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_SUM, run_comm());
}

double WorldRanks::max(double value) const {
  double m = value;
  MPI_Allreduce(&value, &m, 1, MPI_DOUBLE, MPI_MAX, run_comm());
  return m;
}

void WorldRanks::exchange(const std::vector<std::vector<double>>& send,
                          std::vector<std::vector<double>>& receive) const {
  const std::size_t ranks = send.size();
  std::vector<int> send_counts(ranks), send_at(ranks), receive_counts(ranks), receive_at(ranks);
  std::vector<double> out, in;
  for (std::size_t r = 0; r < ranks; ++r) {
    send_at[r] = static_cast<int>(out.size());
    send_counts[r] = static_cast<int>(send[r].size());
    out.insert(out.end(), send[r].begin(), send[r].end());
    receive_at[r] = static_cast<int>(in.size());
    receive_counts[r] = static_cast<int>(receive[r].size());
    in.resize(in.size() + receive[r].size());
  }
  if (out.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()) ||
      in.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw std::runtime_error("spread system: an exchange of more than 2^31 values");
  MPI_Alltoallv(out.data(), send_counts.data(), send_at.data(), MPI_DOUBLE, in.data(), receive_counts.data(),
                receive_at.data(), MPI_DOUBLE, run_comm());
  for (std::size_t r = 0; r < ranks; ++r)
    std::copy(in.begin() + receive_at[r], in.begin() + receive_at[r] + receive_counts[r], receive[r].begin());
}

bool all_ok(bool ok_here) {
  int ok = ok_here ? 1 : 0, all = 0;
  MPI_Allreduce(&ok, &all, 1, MPI_INT, MPI_MIN, run_comm());
  return all == 1;
}

bool root_ok(bool ok_here) {
  int ok = ok_here ? 1 : 0;
  MPI_Bcast(&ok, 1, MPI_INT, 0, run_comm());
  return ok == 1;
}

void abort_all(int status) {
  MPI_Abort(MPI_COMM_WORLD, status);
  std::abort();  // not reached: MPI_Abort does not return
}

RunResult gather_replicas(RunResult local) {
  const World w = world();
  if (w.size == 1) return local;  // a single process ran every replica
  std::vector<std::byte> mine = serialise_replicas(local.replicas, w.rank, w.size);
  if (w.rank != 0) local.replicas.clear();
  const auto my_size = static_cast<std::uint64_t>(mine.size());
  std::vector<std::uint64_t> sizes(w.rank == 0 ? static_cast<std::size_t>(w.size) : 0);
  check(MPI_Gather(&my_size, 1, MPI_UINT64_T, sizes.data(), 1, MPI_UINT64_T, 0, run_comm()), "MPI_Gather");
  if (w.rank != 0) {
    for (std::size_t at = 0; at < mine.size(); at += chunk_bytes) {
      const std::size_t n = std::min(chunk_bytes, mine.size() - at);
      check(MPI_Send(mine.data() + at, static_cast<int>(n), MPI_BYTE, 0, tag_replicas, run_comm()), "MPI_Send");
    }
    return local;
  }
  for (int k = 1; k < w.size; ++k) {  // rank 0's own replicas are in place already
    std::vector<std::byte> bytes(static_cast<std::size_t>(sizes[static_cast<std::size_t>(k)]));
    for (std::size_t at = 0; at < bytes.size(); at += chunk_bytes) {
      const std::size_t n = std::min(chunk_bytes, bytes.size() - at);
      MPI_Status status;
      check(MPI_Recv(bytes.data() + at, static_cast<int>(n), MPI_BYTE, k, tag_replicas, run_comm(), &status),
            "MPI_Recv");
      int received = 0;
      check(MPI_Get_count(&status, MPI_BYTE, &received), "MPI_Get_count");
      if (static_cast<std::size_t>(received) != n) throw std::runtime_error("replica message: short message");
    }
    deserialise_replicas(bytes, local.replicas, k, w.size);
  }
  return local;
}

}  // namespace granmc::mpi
