#include "io/checkpoint.hpp"

#include <cstddef>
#include <fstream>
#include <iterator>
#include <span>
#include <string_view>
#include <vector>

#include "io/atomic_file.hpp"
#include "io/fnv1a.hpp"
#include "io/replica_bytes.hpp"

namespace granmc {
namespace {

constexpr std::string_view magic = "granmc checkpoint\n";
constexpr std::uint32_t byte_order_mark = 0x01020304;

std::uint64_t fnv1a(std::span<const std::byte> bytes) {
  return fnv1a64({reinterpret_cast<const char*>(bytes.data()), bytes.size()});
}

void put_text(ByteWriter& out, const std::string& text) { out.array(std::vector<char>(text.begin(), text.end())); }
std::string get_text(ByteReader& in) {
  const std::vector<char> v = in.array<char>();
  return {v.begin(), v.end()};
}

}  // namespace

void write_checkpoint(const std::string& path, const Checkpoint& checkpoint) {
  ByteWriter out;
  for (const char c : magic) out.value(c);
  out.value(checkpoint_format_version);
  out.value(byte_order_mark);
  put_text(out, checkpoint.build);
  put_text(out, checkpoint.scene_text);
  out.value(checkpoint.seed);
  out.value(checkpoint.replicas);
  out.value(static_cast<std::uint64_t>(checkpoint.finished.size()));
  for (const auto& [replica, series] : checkpoint.finished) {
    out.value(replica);
    write_replica(out, series);
  }
  out.value(static_cast<std::uint64_t>(checkpoint.in_flight.size()));
  for (const auto& [replica, state] : checkpoint.in_flight) {
    out.value(replica);
    write_in_flight(out, state);
  }
  out.value(fnv1a(out.bytes()));
  const std::vector<std::byte>& bytes = out.bytes();
  try {
    write_file_atomically(path, {reinterpret_cast<const char*>(bytes.data()), bytes.size()}, "checkpoint");
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(std::string(e.what()) + "; the previous checkpoint, if any, is intact");
  }
}

Checkpoint read_checkpoint(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw CheckpointError("cannot open checkpoint '" + path + "'");
  const std::string raw{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
  const std::span<const std::byte> bytes(reinterpret_cast<const std::byte*>(raw.data()), raw.size());
  const auto bad = [&](const std::string& why) { return CheckpointError("'" + path + "' " + why); };
  if (raw.compare(0, magic.size(), magic) != 0) throw bad("is not a granmc checkpoint");
  constexpr std::size_t trailer = sizeof(std::uint64_t);
  if (bytes.size() < magic.size() + 2 * sizeof(std::uint32_t) + trailer) throw bad("is truncated");
  try {
    ByteReader in(bytes.first(bytes.size() - trailer));
    for (std::size_t k = 0; k < magic.size(); ++k) in.value<char>();
    const auto version = in.value<std::uint32_t>();
    if (version != checkpoint_format_version)
      throw bad("has checkpoint format " + std::to_string(version) + "; this build reads format " +
                std::to_string(checkpoint_format_version));
    if (in.value<std::uint32_t>() != byte_order_mark) throw bad("was written on a machine of another byte order");
    ByteReader tail(bytes.last(trailer));
    if (tail.value<std::uint64_t>() != fnv1a(bytes.first(bytes.size() - trailer)))
      throw bad("is corrupt (its checksum does not match)");
    Checkpoint c;
    c.build = get_text(in);
    c.scene_text = get_text(in);
    c.seed = in.value<std::uint64_t>();
    c.replicas = in.value<std::uint64_t>();
    const auto count = in.value<std::uint64_t>();
    for (std::uint64_t k = 0; k < count; ++k) {
      const auto replica = in.value<std::uint64_t>();
      if (replica >= c.replicas || c.finished.contains(replica)) throw bad("is corrupt (a replica index)");
      c.finished.emplace(replica, read_replica(in));
    }
    const auto in_flight = in.value<std::uint64_t>();
    for (std::uint64_t k = 0; k < in_flight; ++k) {
      const auto replica = in.value<std::uint64_t>();
      if (replica >= c.replicas || c.finished.contains(replica) || c.in_flight.contains(replica))
        throw bad("is corrupt (a replica index)");
      c.in_flight.emplace(replica, read_in_flight(in));
    }
    if (!in.at_end()) throw bad("is corrupt (bytes after the last replica)");
    return c;
  } catch (const CheckpointError&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw bad(std::string("is corrupt (") + e.what() + ")");
  }
}

void merge_checkpoint(Checkpoint& into, Checkpoint&& other) {
  for (auto& [r, series] : other.finished) {
    into.in_flight.erase(r);
    into.finished.try_emplace(r, std::move(series));
  }
  for (auto& [r, state] : other.in_flight) {
    if (into.finished.contains(r)) continue;
    const auto at = into.in_flight.find(r);
    if (at == into.in_flight.end())
      into.in_flight.emplace(r, std::move(state));
    else if (state.samples_taken > at->second.samples_taken)
      at->second = std::move(state);
  }
}

std::string checkpoint_mismatch(const Checkpoint& checkpoint, const std::string& build, const std::string& scene_text,
                                std::uint64_t seed, std::uint64_t replicas) {
  if (checkpoint.build != build)
    return "it was written by granmc " + checkpoint.build + ", this is " + build +
           " (another build may draw other random numbers)";
  if (checkpoint.scene_text != scene_text) return "it is a checkpoint of another scene (the scene text differs)";
  if (checkpoint.seed != seed)
    return "it is a checkpoint of seed " + std::to_string(checkpoint.seed) + ", this run has seed " +
           std::to_string(seed);
  if (checkpoint.replicas != replicas)
    return "it is a checkpoint of " + std::to_string(checkpoint.replicas) + " replicas, this run has " +
           std::to_string(replicas);
  return "";
}

}  // namespace granmc
