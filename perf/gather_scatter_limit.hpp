#pragma once
// The limit kernel of the collision stage: random pair gather + scatter with nothing else, as the
// collision stage does it (read two particles' velocities, write both back), with the particles in packed
// 32-byte records (x, y, z, aux) and the pairs generated kPrefetchDistance ahead and prefetched. It is
// the layout decision's measurement (perf/bench_layout.cpp) and the bound the collision stage is
// compared with in the same run (perf/bench_collisions.cpp and perf/bench_event.cpp, as
// the benchmark limit_pairs below).
//
// Each pair: two indices k, l uniform on {0..N-1} and a direction from a table of 8 unit vectors, all from
// one inline splitmix64 generator (the same sequence for every layout); read both velocities, apply an
// elastic collision along the direction (g.s, then v_k -= (g.s) s, v_l += (g.s) s: energy-conserving, so
// the values stay normal over any number of iterations), write both back. The buffer is granmc's
// AlignedBuffer (2 MiB alignment and MADV_HUGEPAGE for large buffers), as SpeciesStore's.
#include <cstddef>
#include <cstdint>
#include <memory>

#include <benchmark/benchmark.h>

#include "kernel/core/aligned_buffer.hpp"

namespace granmc::perf {

inline constexpr std::uint64_t kPrefetchDistance = 16;

struct SplitMix64 {
  std::uint64_t s;
  std::uint64_t next() noexcept {
    std::uint64_t z = (s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
};

struct Pair {
  std::uint64_t k, l;
  unsigned dir;
};

inline Pair next_pair(SplitMix64& gen, std::uint64_t n) noexcept {
  __extension__ using uint128 = unsigned __int128;
  const std::uint64_t r1 = gen.next();
  const std::uint64_t r2 = gen.next();
  return {static_cast<std::uint64_t>((static_cast<uint128>(r1) * n) >> 64),
          static_cast<std::uint64_t>((static_cast<uint128>(r2) * n) >> 64), static_cast<unsigned>(r2 & 7u)};
}

struct Direction {
  double x, y, z;
};
// The 8 unit vectors (+-1, +-1, +-1) / sqrt(3).
constexpr double kInvSqrt3 = 0.57735026918962576451;
constexpr Direction kDirections[8] = {{kInvSqrt3, kInvSqrt3, kInvSqrt3},   {kInvSqrt3, kInvSqrt3, -kInvSqrt3},
                                      {kInvSqrt3, -kInvSqrt3, kInvSqrt3},  {kInvSqrt3, -kInvSqrt3, -kInvSqrt3},
                                      {-kInvSqrt3, kInvSqrt3, kInvSqrt3},  {-kInvSqrt3, kInvSqrt3, -kInvSqrt3},
                                      {-kInvSqrt3, -kInvSqrt3, kInvSqrt3}, {-kInvSqrt3, -kInvSqrt3, -kInvSqrt3}};

inline double initial_value(SplitMix64& gen) noexcept {
  return static_cast<double>(gen.next() >> 11) * 0x1p-52 - 1.0;  // uniform on [-1, 1)
}

/// Packed records (x, y, z, aux) of Real: 32 bytes for double (SpeciesStore), 16 for float
/// (FloatSpeciesStore, run.storage = "float"); the arithmetic is in double either way, as granmc's.
template <class Real>
struct BasicPackedLayout {
  struct alignas(4 * sizeof(Real)) Record {
    Real v[3];
    Real aux;
  };
  static_assert(sizeof(Record) == 4 * sizeof(Real));

  explicit BasicPackedLayout(std::size_t n) : r(n) {
    SplitMix64 gen{1};
    for (std::size_t k = 0; k < n; ++k) {
      r[k].v[0] = static_cast<Real>(initial_value(gen));
      r[k].v[1] = static_cast<Real>(initial_value(gen));
      r[k].v[2] = static_cast<Real>(initial_value(gen));
      r[k].aux = 0;
    }
  }
  std::size_t size() const noexcept { return r.size(); }
  void prefetch(std::uint64_t k) const noexcept { __builtin_prefetch(&r[k], 1, 3); }
  void collide(std::uint64_t k, std::uint64_t l, const Direction& s) noexcept {
    Record& a = r[k];
    Record& b = r[l];
    const double ax = a.v[0], ay = a.v[1], az = a.v[2], bx = b.v[0], by = b.v[1], bz = b.v[2];
    const double gs = (ax - bx) * s.x + (ay - by) * s.y + (az - bz) * s.z;
    a.v[0] = static_cast<Real>(ax - gs * s.x);
    a.v[1] = static_cast<Real>(ay - gs * s.y);
    a.v[2] = static_cast<Real>(az - gs * s.z);
    b.v[0] = static_cast<Real>(bx + gs * s.x);
    b.v[1] = static_cast<Real>(by + gs * s.y);
    b.v[2] = static_cast<Real>(bz + gs * s.z);
  }
  AlignedBuffer<Record> r;
};
using PackedLayout = BasicPackedLayout<double>;
using PackedFloatLayout = BasicPackedLayout<float>;

template <class Layout>
void run_pairs(Layout& lay, SplitMix64& gen, std::uint64_t pairs) noexcept {
  const std::uint64_t n = lay.size();
  for (std::uint64_t c = 0; c < pairs; ++c) {
    const Pair p = next_pair(gen, n);
    lay.collide(p.k, p.l, kDirections[p.dir]);
  }
}

/// The same pairs in the same order, generated kPrefetchDistance ahead and prefetched.
template <class Layout>
void run_pairs_prefetched(Layout& lay, SplitMix64& gen, std::uint64_t pairs) noexcept {
  const std::uint64_t n = lay.size();
  Pair ring[kPrefetchDistance];
  const std::uint64_t ahead = pairs < kPrefetchDistance ? pairs : kPrefetchDistance;
  for (std::uint64_t c = 0; c < ahead; ++c) {
    ring[c] = next_pair(gen, n);
    lay.prefetch(ring[c].k);
    lay.prefetch(ring[c].l);
  }
  for (std::uint64_t c = 0; c < pairs; ++c) {
    Pair& slot = ring[c % kPrefetchDistance];
    lay.collide(slot.k, slot.l, kDirections[slot.dir]);
    if (c + kPrefetchDistance < pairs) {
      slot = next_pair(gen, n);
      lay.prefetch(slot.k);
      lay.prefetch(slot.l);
    }
  }
}

/// One buffer of n particles per layout, kept across Google Benchmark's calls of the same size.
template <class Layout>
Layout& layout_for(std::size_t n) {
  static std::unique_ptr<Layout> lay;
  if (!lay || lay->size() != n) {
    lay.reset();
    lay = std::make_unique<Layout>(n);
  }
  return *lay;
}

/// The limit kernel as a benchmark: `pairs_per_iteration` prefetched pairs per iteration among bs.range(0)
/// packed records; counter pairs/s (rate over CPU time).
template <std::uint64_t pairs_per_iteration>
void limit_pairs(benchmark::State& bs) {
  PackedLayout& lay = layout_for<PackedLayout>(static_cast<std::size_t>(bs.range(0)));
  SplitMix64 gen{0x5EEDull};
  std::uint64_t pairs = 0;
  for (auto _ : bs) {
    run_pairs_prefetched(lay, gen, pairs_per_iteration);
    benchmark::ClobberMemory();
    pairs += pairs_per_iteration;
  }
  bs.counters["pairs/s"] = benchmark::Counter(static_cast<double>(pairs), benchmark::Counter::kIsRate);
}

}  // namespace granmc::perf
