#pragma once
// A run's replica series as bytes: what MPI ranks send to rank 0 (drivers/mpi_replicas.hpp) and what a
// checkpoint keeps of the finished replicas (io/checkpoint.hpp). The format is private to one executable:
// native byte order, sizes as std::uint64_t, trivially copyable arrays copied with memcpy; the fields of a
// replica in the order of kernel/observe/gas_series.hpp's one list (visit_replica_fields).
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

#include "kernel/observe/gas_series.hpp"
#include "kernel/schemes/replica_in_flight.hpp"

namespace granmc {

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
    if (n > (bytes_.size() - position_) / sizeof(T)) throw std::runtime_error("replica bytes: array past the end");
    std::vector<T> v(static_cast<std::size_t>(n));
    raw(v.data(), v.size() * sizeof(T));
    return v;
  }
  [[nodiscard]] bool at_end() const noexcept { return position_ == bytes_.size(); }

 private:
  void raw(void* data, std::size_t size) {
    if (size > bytes_.size() - position_) throw std::runtime_error("replica bytes: read past the end");
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

/// A replica stopped at a sample (kernel/schemes/replica_in_flight.hpp): its series, then its state.
void write_in_flight(ByteWriter& out, const ReplicaInFlight& replica);
ReplicaInFlight read_in_flight(ByteReader& in);

/// The replicas r = offset, offset + stride, ... of `replicas`, as bytes (count first).
std::vector<std::byte> serialise_replicas(const std::vector<ReplicaSeries>& replicas, int offset, int stride);
/// Writes the series of `bytes` to replicas[offset], [offset + stride], ...; throws std::runtime_error if
/// the count does not match replicas.size() or the bytes are not exactly one such list.
void deserialise_replicas(std::span<const std::byte> bytes, std::vector<ReplicaSeries>& replicas, int offset,
                          int stride);

}  // namespace granmc
