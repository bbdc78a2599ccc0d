#include "io/replica_bytes.hpp"

#include <optional>
#include <string>
#include <variant>

namespace granmc {

namespace {

static_assert(sizeof(Vec3) == 3 * sizeof(double) && std::is_trivially_copyable_v<Vec3>);
static_assert(sizeof(SymTensor) == 6 * sizeof(double) && std::is_trivially_copyable_v<SymTensor>);
static_assert(std::is_trivially_copyable_v<CollisionTally> && std::is_trivially_copyable_v<EventTally> &&
              std::is_trivially_copyable_v<SwpmTally> && std::is_trivially_copyable_v<WeightControlTally> &&
              std::is_trivially_copyable_v<VelocityScale>);
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
  template <class T>
  void operator()(const char*, const std::vector<std::vector<T>>& arrays) {
    out.value(static_cast<std::uint64_t>(arrays.size()));
    for (const std::vector<T>& a : arrays) out.array(a);
  }
  void operator()(const char*, const WeightedParticles& p) { WeightedParticles::visit_fields(p, *this); }
  void operator()(const char*, const WeightControl& c) { WeightControl::visit_fields(c, *this); }
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
  template <class T>
  void operator()(const char*, std::vector<std::vector<T>>& arrays) {
    const auto n = in.value<std::uint64_t>();
    for (std::uint64_t i = 0; i < n; ++i) arrays.push_back(in.array<T>());
  }
  void operator()(const char*, WeightedParticles& p) { WeightedParticles::visit_fields(p, *this); }
  void operator()(const char*, WeightControl& c) { WeightControl::visit_fields(c, *this); }
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
    if (f > 1) throw std::runtime_error(std::string("replica bytes: bad ") + what + " flag");
    return f == 1;
  }
};

/// How many of `replicas` replicas a rank with this offset and stride runs.
std::size_t own_count(std::size_t replicas, int offset, int stride) {
  const auto o = static_cast<std::size_t>(offset), s = static_cast<std::size_t>(stride);
  return replicas > o ? (replicas - o + s - 1) / s : 0;
}

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

void write_in_flight(ByteWriter& out, const ReplicaInFlight& f) {
  write_replica(out, f.series);
  out.value(f.samples_taken);
  out.array(f.initial_majorant);
  // The scheme: 0 time-stepped, 1 time-step-free, 2 weighted particles.
  out.value(static_cast<std::uint8_t>(f.state.index()));
  Put put{out};
  if (const auto* dsmc = std::get_if<DsmcSnapshot>(&f.state)) visit_snapshot_fields(*dsmc, put);
  if (const auto* event = std::get_if<EventSnapshot>(&f.state)) visit_event_snapshot_fields(*event, put);
  if (const auto* swpm = std::get_if<SwpmSnapshot>(&f.state)) visit_swpm_snapshot_fields(*swpm, put);
}

ReplicaInFlight read_in_flight(ByteReader& in) {
  ReplicaInFlight f;
  f.series = read_replica(in);
  f.samples_taken = in.value<std::uint64_t>();
  f.initial_majorant = in.array<double>();
  Get get{in};
  switch (in.value<std::uint8_t>()) {
    case 0:
      visit_snapshot_fields(f.state.emplace<DsmcSnapshot>(), get);
      break;
    case 1:
      visit_event_snapshot_fields(f.state.emplace<EventSnapshot>(), get);
      break;
    case 2:
      visit_swpm_snapshot_fields(f.state.emplace<SwpmSnapshot>(), get);
      break;
    default:
      throw std::runtime_error("replica bytes: bad scheme of a replica in flight");
  }
  return f;
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
    throw std::runtime_error("replica bytes: wrong number of replicas");
  for (std::size_t r = static_cast<std::size_t>(offset); r < replicas.size(); r += static_cast<std::size_t>(stride))
    replicas[r] = read_replica(in);
  if (!in.at_end()) throw std::runtime_error("replica bytes: bytes left after the last replica");
}

}  // namespace granmc
