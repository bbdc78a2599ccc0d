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

static_assert(sizeof(Vec3) == 3 * sizeof(double) && std::is_trivially_copyable_v<Vec3>);
static_assert(sizeof(SymTensor) == 6 * sizeof(double) && std::is_trivially_copyable_v<SymTensor>);
// The fields of a replica in message order are kernel/observe/gas_series.hpp's one list (visit_replica_fields),
// walked by Put (writes each field) and Get (reads into it), so writing and reading cannot disagree. Optionals
// go as a flag byte and, for a record, its fields when present; the energy residual always sends its value (0
// when absent).
struct Put {
  ByteWriter& out;
  template <class T>
  void operator()(const char*, const T& v) {
    out.value(v);
  }
  template <class T>
  void operator()(const char*, const std::vector<T>& v) {
    out.array(v);
  }
  void operator()(const char*, const std::vector<SpeciesSeries>& species) {
    out.value(static_cast<std::uint64_t>(species.size()));
    for (const SpeciesSeries& sp : species) visit_species_fields(sp, *this);
  }
  void operator()(const char*, const std::optional<double>& v) {
    out.value(static_cast<std::uint8_t>(v.has_value()));
    out.value(v.value_or(0.0));
  }
  void operator()(const char*, const std::optional<ShearSeries>& v) {
    out.value(static_cast<std::uint8_t>(v.has_value()));
    if (v) visit_shear_fields(*v, *this);
  }
  void operator()(const char*, const std::optional<IntruderSeries>& v) {
    out.value(static_cast<std::uint8_t>(v.has_value()));
    if (v) visit_intruder_fields(*v, *this);
  }
  void operator()(const char*, const std::optional<WeightedSeries>& v) {
    out.value(static_cast<std::uint8_t>(v.has_value()));
    if (v) visit_weighted_fields(*v, *this);
  }
};

struct Get {
  ByteReader& in;
  template <class T>
  void operator()(const char*, T& v) {
    v = in.value<T>();
  }
  template <class T>
  void operator()(const char*, std::vector<T>& v) {
    v = in.array<T>();
  }
  void operator()(const char*, std::vector<SpeciesSeries>& species) {
    const auto n = in.value<std::uint64_t>();  // one at a time: a corrupt count fails at the end of the bytes
    for (std::uint64_t i = 0; i < n; ++i) visit_species_fields(species.emplace_back(), *this);
  }
  void operator()(const char* name, std::optional<double>& v) {
    const bool present = flag(name);
    const double value = in.value<double>();
    if (present) v = value;
  }
  void operator()(const char* name, std::optional<ShearSeries>& v) {
    if (flag(name)) visit_shear_fields(v.emplace(), *this);
  }
  void operator()(const char* name, std::optional<IntruderSeries>& v) {
    if (flag(name)) visit_intruder_fields(v.emplace(), *this);
  }
  void operator()(const char* name, std::optional<WeightedSeries>& v) {
    if (flag(name)) visit_weighted_fields(v.emplace(), *this);
  }
  bool flag(const char* what) {
    const auto f = in.value<std::uint8_t>();
    if (f > 1) throw std::runtime_error(std::string("replica message: bad ") + what + " flag");
    return f == 1;
  }
};

/// How many of `replicas` replicas a rank with this offset and stride runs.
std::size_t own_count(std::size_t replicas, int offset, int stride) {
  const auto o = static_cast<std::size_t>(offset), s = static_cast<std::size_t>(stride);
  return replicas > o ? (replicas - o + s - 1) / s : 0;
}

void check(int code, const char* what) {
  if (code != MPI_SUCCESS) throw std::runtime_error(std::string("MPI error in ") + what);
}

/// Messages of at most 2^30 bytes (MPI counts are int).
constexpr std::size_t chunk_bytes = std::size_t{1} << 30;
constexpr int tag_replicas = 1;

}  // namespace

void write_replica(ByteWriter& out, const ReplicaSeries& s) {
  Put put{out};
  visit_replica_fields(s, put);
}

ReplicaSeries read_replica(ByteReader& in) {
  ReplicaSeries s;
  Get get{in};
  visit_replica_fields(s, get);
  return s;
}

std::vector<std::byte> serialise_replicas(const std::vector<ReplicaSeries>& replicas, int offset, int stride) {
  ByteWriter out;
  out.value(static_cast<std::uint64_t>(own_count(replicas.size(), offset, stride)));
  for (std::size_t r = static_cast<std::size_t>(offset); r < replicas.size(); r += static_cast<std::size_t>(stride))
    write_replica(out, replicas[r]);
  return out.release();
}

void deserialise_replicas(std::span<const std::byte> bytes, std::vector<ReplicaSeries>& replicas, int offset,
                          int stride) {
  ByteReader in(bytes);
  if (in.value<std::uint64_t>() != own_count(replicas.size(), offset, stride))
    throw std::runtime_error("replica message: wrong number of replicas");
  for (std::size_t r = static_cast<std::size_t>(offset); r < replicas.size(); r += static_cast<std::size_t>(stride))
    replicas[r] = read_replica(in);
  if (!in.at_end()) throw std::runtime_error("replica message: bytes left after the last replica");
}

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
