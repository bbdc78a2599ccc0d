// The measurement that decides the velocity layout of SpeciesStore (kernel/core/species_store.hpp): random pair
// gather + scatter, as the collision stage does it, with one array per component (SoA: x[], y[], z[])
// against packed 32-byte records (x, y, z, aux), at N = 10^5 (fits in L2 + L3) and N = 10^7 (does not);
// and, with prefetch, packed 16-byte float records (run.storage = "float") against the double ones.
//
// The pairs, the packed layout and the two loops are perf/gather_scatter_limit.hpp's (the packed layout
// with prefetch is the limit kernel bench_collisions runs beside the collision stage). Both layouts use
// granmc's AlignedBuffer (2 MiB alignment and MADV_HUGEPAGE for large buffers), so they differ only in
// layout.
//
// Besides the two plain loops, two "prefetch" variants generate the pairs kPrefetchDistance ahead
// and prefetch their cache lines (2 for packed, 6 for SoA): not part of the layout decision, but the
// figure for the batching-with-prefetch that docs/developer-guide/performance.md discusses.
//
// Counter (rate over CPU time): pairs/s. A table of the medians and the ratios follows the runs.
// Defaults: 3 repetitions, aggregates only, min time 0.5 s; any --benchmark_* flag overrides them.
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "kernel/core/aligned_buffer.hpp"
#include "perf/bench_common.hpp"
#include "perf/gather_scatter_limit.hpp"

namespace {

using granmc::AlignedBuffer;
using namespace granmc::perf;

constexpr std::uint64_t kPairsPerIteration = 1'000'000;
constexpr std::int64_t kSizes[] = {100'000, 10'000'000};

// ---- the SoA layout (the packed one is in gather_scatter_limit.hpp) ------------------------------

struct SoaLayout {
  explicit SoaLayout(std::size_t n) : x(n), y(n), z(n) {
    SplitMix64 gen{1};
    for (std::size_t k = 0; k < n; ++k) {
      x[k] = initial_value(gen);
      y[k] = initial_value(gen);
      z[k] = initial_value(gen);
    }
  }
  std::size_t size() const noexcept { return x.size(); }
  void prefetch(std::uint64_t k) const noexcept {
    __builtin_prefetch(&x[k], 1, 3);
    __builtin_prefetch(&y[k], 1, 3);
    __builtin_prefetch(&z[k], 1, 3);
  }
  void collide(std::uint64_t k, std::uint64_t l, const Direction& s) noexcept {
    const double gx = x[k] - x[l], gy = y[k] - y[l], gz = z[k] - z[l];
    const double gs = gx * s.x + gy * s.y + gz * s.z;
    x[k] -= gs * s.x;
    y[k] -= gs * s.y;
    z[k] -= gs * s.z;
    x[l] += gs * s.x;
    y[l] += gs * s.y;
    z[l] += gs * s.z;
  }
  AlignedBuffer<double> x, y, z;
};

template <class Layout, bool prefetched>
void layout_pairs(benchmark::State& bs) {
  Layout& lay = layout_for<Layout>(static_cast<std::size_t>(bs.range(0)));  // gather_scatter_limit.hpp
  SplitMix64 gen{0x5EEDull};                                                // the same pair sequence for every layout
  std::uint64_t pairs = 0;
  for (auto _ : bs) {
    if constexpr (prefetched) {
      run_pairs_prefetched(lay, gen, kPairsPerIteration);
    } else {
      run_pairs(lay, gen, kPairsPerIteration);
    }
    benchmark::ClobberMemory();
    pairs += kPairsPerIteration;
  }
  bs.counters["pairs/s"] = benchmark::Counter(static_cast<double>(pairs), benchmark::Counter::kIsRate);
}

// ---- ratio table ---------------------------------------------------------------------------------

void print_ratio_table(const granmc::perf::RecordingReporter& rep) {
  std::printf("\nRandom pair gather + scatter, %llu pairs per iteration (median of the repetitions)\n",
              static_cast<unsigned long long>(kPairsPerIteration));
  std::printf(
      "| N | SoA pairs/s | packed pairs/s | packed / SoA | SoA+prefetch pairs/s | "
      "packed+prefetch pairs/s | packed+prefetch / packed | float packed+prefetch pairs/s | float / double |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  const auto soa_runs = rep.counters.find("layout_soa");
  if (soa_runs == rep.counters.end()) return;
  for (const auto& [args, unused] : soa_runs->second) {
    const auto get = [&](const char* name) { return rep.value(name, args, "pairs/s"); };
    const double soa = get("layout_soa"), packed = get("layout_packed");
    const double soa_p = get("layout_soa_prefetch"), packed_p = get("layout_packed_prefetch");
    const double float_p = get("layout_packed_float_prefetch");
    std::printf("| %s | %.3g | %.3g | %.2f | %.3g | %.3g | %.2f | %.3g | %.2f |\n", args.c_str(), soa, packed,
                packed / soa, soa_p, packed_p, packed_p / packed, float_p, float_p / packed_p);
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (!granmc::perf::initialize(argc, argv, "0.5")) return 1;

  for (const std::int64_t n : kSizes) {
    benchmark::RegisterBenchmark("layout_soa", layout_pairs<SoaLayout, false>)->Arg(n)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("layout_packed", layout_pairs<PackedLayout, false>)
        ->Arg(n)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("layout_soa_prefetch", layout_pairs<SoaLayout, true>)
        ->Arg(n)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("layout_packed_prefetch", layout_pairs<PackedLayout, true>)
        ->Arg(n)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("layout_packed_float_prefetch", layout_pairs<PackedFloatLayout, true>)
        ->Arg(n)
        ->Unit(benchmark::kMillisecond);
  }

  granmc::perf::RecordingReporter reporter(isatty(STDOUT_FILENO) != 0);
  benchmark::RunSpecifiedBenchmarks(&reporter);
  print_ratio_table(reporter);
  benchmark::Shutdown();
  return 0;
}
