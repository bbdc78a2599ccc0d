#include "drivers/mpi_replicas.hpp"

#include <mpi.h>

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <string>

namespace granmc::mpi {

namespace {

static_assert(sizeof(Vec3) == 3 * sizeof(double) && std::is_trivially_copyable_v<Vec3>);
static_assert(sizeof(SymTensor) == 6 * sizeof(double) && std::is_trivially_copyable_v<SymTensor>);
#if defined(__GLIBCXX__) && defined(__x86_64__) && !defined(_GLIBCXX_DEBUG)
// Tripwire: a field added to these structs (kernel/observe/gas_series.hpp) must be added to write_replica
// and read_replica below (and to the round trip in tests/test_mpi.cpp); then update the sizes.
static_assert(sizeof(SpeciesSeries) == 120, "SpeciesSeries changed: serialise the new field");
static_assert(sizeof(IntruderSeries) == 144, "IntruderSeries changed: serialise the new field");
static_assert(sizeof(ReplicaSeries) == 480, "ReplicaSeries changed: serialise the new field");
#endif

void write_species(ByteWriter& out, const SpeciesSeries& s) {
  out.array(s.temperature);
  out.array(s.log_temperature);
  out.array(s.a2);
  out.array(s.a3);
  out.array(s.speed_counts);
}

SpeciesSeries read_species(ByteReader& in) {
  SpeciesSeries s;
  s.temperature = in.array<double>();
  s.log_temperature = in.array<double>();
  s.a2 = in.array<double>();
  s.a3 = in.array<double>();
  s.speed_counts = in.array<double>();
  return s;
}

void write_intruder(ByteWriter& out, const IntruderSeries& s) {
  out.array(s.velocity);
  out.array(s.speed_counts);
  out.value(s.sampling_attempts);
  out.array(s.velocity_y);
  out.array(s.angular_velocity);
  out.array(s.angular_counts);
  out.value(s.newton_iterations);
  out.value(s.bisection_fallbacks);
}

IntruderSeries read_intruder(ByteReader& in) {
  IntruderSeries s;
  s.velocity = in.array<double>();
  s.speed_counts = in.array<double>();
  s.sampling_attempts = in.value<std::uint64_t>();
  s.velocity_y = in.array<double>();
  s.angular_velocity = in.array<double>();
  s.angular_counts = in.array<double>();
  s.newton_iterations = in.value<std::uint64_t>();
  s.bisection_fallbacks = in.value<std::uint64_t>();
  return s;
}

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
  out.array(s.temperature);
  out.array(s.log_temperature);
  out.value(static_cast<std::uint64_t>(s.species.size()));
  for (const SpeciesSeries& sp : s.species) write_species(out, sp);
  out.array(s.momentum);
  out.array(s.momentum_relative);
  out.array(s.collisions);
  out.array(s.pair_collisions);
  out.value(s.histogram_samples);
  out.value(s.candidates);
  out.value(s.majorant_updates);
  out.value(s.majorant_violations);
  out.array(s.majorant_growth);
  out.array(s.pressure_kinetic);
  out.array(s.pressure_collisional);
  out.array(s.reduced_shear_rate);
  out.value(s.rescales);
  out.value(s.momentum_removed_relative);
  out.value(static_cast<std::uint8_t>(s.energy_residual.has_value()));
  out.value(s.energy_residual.value_or(0.0));
  out.value(static_cast<std::uint8_t>(s.intruder.has_value()));
  if (s.intruder) write_intruder(out, *s.intruder);
}

ReplicaSeries read_replica(ByteReader& in) {
  ReplicaSeries s;
  s.temperature = in.array<double>();
  s.log_temperature = in.array<double>();
  const auto species = in.value<std::uint64_t>();
  for (std::uint64_t i = 0; i < species; ++i) s.species.push_back(read_species(in));
  s.momentum = in.array<Vec3>();
  s.momentum_relative = in.array<double>();
  s.collisions = in.array<double>();
  s.pair_collisions = in.array<std::uint64_t>();
  s.histogram_samples = in.value<std::uint64_t>();
  s.candidates = in.value<std::uint64_t>();
  s.majorant_updates = in.value<std::uint64_t>();
  s.majorant_violations = in.value<std::uint64_t>();
  s.majorant_growth = in.array<double>();
  s.pressure_kinetic = in.array<SymTensor>();
  s.pressure_collisional = in.array<SymTensor>();
  s.reduced_shear_rate = in.array<double>();
  s.rescales = in.value<std::uint64_t>();
  s.momentum_removed_relative = in.value<double>();
  const auto has_energy_residual = in.value<std::uint8_t>();
  const double energy_residual = in.value<double>();
  if (has_energy_residual > 1) throw std::runtime_error("replica message: bad energy residual flag");
  if (has_energy_residual) s.energy_residual = energy_residual;
  const auto has_intruder = in.value<std::uint8_t>();
  if (has_intruder > 1) throw std::runtime_error("replica message: bad intruder flag");
  if (has_intruder) s.intruder = read_intruder(in);
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
  MPI_Comm_rank(MPI_COMM_WORLD, &w.rank);
  MPI_Comm_size(MPI_COMM_WORLD, &w.size);
  return w;
}

bool all_ok(bool ok_here) {
  int ok = ok_here ? 1 : 0, all = 0;
  MPI_Allreduce(&ok, &all, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  return all == 1;
}

bool root_ok(bool ok_here) {
  int ok = ok_here ? 1 : 0;
  MPI_Bcast(&ok, 1, MPI_INT, 0, MPI_COMM_WORLD);
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
  check(MPI_Gather(&my_size, 1, MPI_UINT64_T, sizes.data(), 1, MPI_UINT64_T, 0, MPI_COMM_WORLD), "MPI_Gather");
  if (w.rank != 0) {
    for (std::size_t at = 0; at < mine.size(); at += chunk_bytes) {
      const std::size_t n = std::min(chunk_bytes, mine.size() - at);
      check(MPI_Send(mine.data() + at, static_cast<int>(n), MPI_BYTE, 0, tag_replicas, MPI_COMM_WORLD), "MPI_Send");
    }
    return local;
  }
  for (int k = 1; k < w.size; ++k) {  // rank 0's own replicas are in place already
    std::vector<std::byte> bytes(static_cast<std::size_t>(sizes[static_cast<std::size_t>(k)]));
    for (std::size_t at = 0; at < bytes.size(); at += chunk_bytes) {
      const std::size_t n = std::min(chunk_bytes, bytes.size() - at);
      MPI_Status status;
      check(MPI_Recv(bytes.data() + at, static_cast<int>(n), MPI_BYTE, k, tag_replicas, MPI_COMM_WORLD, &status),
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
