// Throughput of the time-stepped DSMC collision stage (000 sec. 3): granmc's collide_step<HardSphere>
// against the naive scalar reference of perf/naive_dsmc.hpp, same N, same run.
//
// Gas: one species of inelastic hard spheres, alpha = 0.8, n = sigma = m = 1, Maxwellian start at T = 1,
// initial majorant as Dsmc's (majorant_bound: a bound on the mean of omega_kl over sigma-hat, a quarter of
// 4 pi sigma^2 n (2 max |c|)); the naive reference keeps the paper's form, sigma-hat first with the
// majorant 4 pi sigma^2 n (2 max |c|), so granmc accepts about four times more of its candidates. Each benchmark
// iteration runs a fixed number of candidate pairs (kCandidatesPerIteration); granmc advances state.step after each, so
// every iteration draws fresh Philox blocks. The gas cools as it collides; as Dsmc does, the velocities
// are rescaled to unit temperature whenever the tracked energy has fallen by a factor 1.25 (outside the
// timed region, same rule for both), so the acceptance ratio stays that of a running simulation.
//
// Counters (rates over CPU time): candidates/s, collisions/s; acceptance = collisions / candidates. At each
// N, the limit kernel of perf/gather_scatter_limit.hpp too (pairs/s), so the stage's fraction of the
// gather/scatter bound comes from one run (with --benchmark_enable_random_interleaving=true, interleaved
// repetitions, as bench_compare runs it).
// Two more benchmarks time the random draws of a candidate alone (no particle memory), to show where
// the time goes. After the runs, a table of the median figures and the ratios granmc / naive is printed.
// Defaults: 3 repetitions, aggregates only, min time 1 s; any --benchmark_* flag overrides them.
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <numbers>
#include <random>
#include <span>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "kernel/collide/hard_sphere.hpp"
#include "kernel/collide/inelastic_rule.hpp"
#include "kernel/collide/pair_coefficients.hpp"
#include "kernel/core/batch_variates.hpp"
#include "kernel/core/philox_stream.hpp"
#include "kernel/core/sampling.hpp"
#include "kernel/core/scene.hpp"
#include "kernel/schemes/collision_stage.hpp"
#include "kernel/schemes/gas_state.hpp"
#include "kernel/schemes/initial_state.hpp"
#include "perf/bench_common.hpp"
#include "perf/gather_scatter_limit.hpp"
#include "perf/naive_dsmc.hpp"

namespace {

using namespace granmc;

constexpr std::uint64_t kCandidatesPerIteration = 1'000'000;
constexpr double kRestitution = 0.8;
constexpr std::uint64_t kSeed = 20240601;
constexpr double kRescaleFactor = 1.25;  // as Dsmc::rescale_factor
constexpr std::int64_t kSizes[] = {100'000, 1'000'000, 10'000'000};

Scene bench_scene(std::int64_t particles) {
  Scene scene;
  scene.run.seed = kSeed;
  scene.run.t_end = 1.0;
  scene.run.dt = 0.01;
  SpeciesConfig s;
  s.name = "grains";
  s.mass = 1.0;
  s.diameter = 1.0;
  s.density = 1.0;
  s.particles = particles;
  scene.species.push_back(s);
  scene.collision.kernel = CollisionKernel::hard_sphere;
  scene.collision.restitution = {{{kRestitution, kRestitution}, {kRestitution, kRestitution}}};
  scene.initial_temperature = 1.0;
  return scene;
}

// ---- granmc --------------------------------------------------------------------------------------

struct GranmcGas {
  explicit GranmcGas(std::int64_t n)
      : scene(bench_scene(n)),
        rng(scene.run.seed, 0),
        pair(pair_coefficients(scene).front()),
        state(maxwellian_state(scene, rng)) {
    double max2 = 0.0;
    state.species[0].for_each_velocity([&](const Vec3& c) { max2 = std::max(max2, norm2(c)); });
    const double max_speed = std::sqrt(max2);
    omega_max = majorant_bound<NoCollisionShift>(HardSphere{}, pair, max_speed + max_speed);
    rescale();
  }

  double twice_energy_exact() const {
    double e = 0.0;
    state.species[0].for_each_velocity([&](const Vec3& c) { e += norm2(c); });
    return e;
  }
  /// As Dsmc::rescale: the centre-of-mass velocity removed, then unit temperature.
  void rescale() {
    const double n = static_cast<double>(state.species[0].size());
    Vec3 sum;
    state.species[0].for_each_velocity([&](const Vec3& c) { sum += c; });
    const Vec3 v_cm = (1.0 / n) * sum;
    state.species[0].for_each_velocity([&](Vec3& c) { c -= v_cm; });
    const double s = std::sqrt(3.0 * n / twice_energy_exact());
    state.species[0].for_each_velocity([&](Vec3& c) { c = s * c; });
    twice_energy = reference = 3.0 * n;
  }
  bool needs_rescale() const { return twice_energy < reference / kRescaleFactor; }

  Scene scene;
  RandomStream rng;
  PairCoefficients pair;
  GasState state;
  double omega_max = 0.0;
  double twice_energy = 0.0;
  double reference = 0.0;
};

// One gas per implementation, kept across Google Benchmark's calls of the same size (building 10^7
// Maxwellian velocities is not what is measured); replaced when the size changes.
GranmcGas& granmc_gas(std::int64_t n) {
  static std::unique_ptr<GranmcGas> gas;
  if (!gas || static_cast<std::int64_t>(gas->state.species[0].size()) != n) {
    gas.reset();
    gas = std::make_unique<GranmcGas>(n);
  }
  return *gas;
}

/// Runs `collide` (one iteration of kCandidatesPerIteration candidates, returning its tally) on `gas`,
/// rescaling outside the timed region as Dsmc does, and reports the rates. Shared by both subjects.
template <class Gas, class Collide>
void measure_stage(benchmark::State& bs, Gas& gas, Collide&& collide) {
  std::uint64_t candidates = 0, collisions = 0;
  for (auto _ : bs) {
    const auto tally = collide();
    gas.twice_energy -= tally.twice_energy_loss;
    candidates += tally.candidates;
    collisions += tally.collisions;
    if (gas.needs_rescale()) {
      bs.PauseTiming();
      gas.rescale();
      bs.ResumeTiming();
    }
  }
  bs.counters["candidates/s"] = benchmark::Counter(static_cast<double>(candidates), benchmark::Counter::kIsRate);
  bs.counters["collisions/s"] = benchmark::Counter(static_cast<double>(collisions), benchmark::Counter::kIsRate);
  bs.counters["acceptance"] = static_cast<double>(collisions) / static_cast<double>(candidates);
}

void granmc_stage(benchmark::State& bs) {
  GranmcGas& g = granmc_gas(bs.range(0));
  measure_stage(bs, g, [&g] {
    CollisionTally tally;
    collide_step<HardSphere>(g.state, {&g.pair, 1}, {&g.omega_max, 1}, {&kCandidatesPerIteration, 1}, g.rng,
                             {&tally, 1});
    ++g.state.step;
    return tally;
  });
}

// ---- naive reference -----------------------------------------------------------------------------

struct NaiveGas {
  explicit NaiveGas(std::int64_t n) : dsmc(static_cast<std::size_t>(n), kSeed, 1.0, kRestitution, 1.0, 1.0) {
    rescale();
  }
  /// As GranmcGas::rescale.
  void rescale() {
    const double n = static_cast<double>(dsmc.particles.size());
    double mx = 0.0, my = 0.0, mz = 0.0;
    for (const naive::Particle& p : dsmc.particles) {
      mx += p.vx;
      my += p.vy;
      mz += p.vz;
    }
    mx /= n;
    my /= n;
    mz /= n;
    double e = 0.0;
    for (naive::Particle& p : dsmc.particles) {
      p.vx -= mx;
      p.vy -= my;
      p.vz -= mz;
      e += p.vx * p.vx + p.vy * p.vy + p.vz * p.vz;
    }
    const double s = std::sqrt(3.0 * n / e);
    for (naive::Particle& p : dsmc.particles) {
      p.vx *= s;
      p.vy *= s;
      p.vz *= s;
    }
    twice_energy = reference = 3.0 * n;
  }
  bool needs_rescale() const { return twice_energy < reference / kRescaleFactor; }

  naive::NaiveDsmc dsmc;
  double twice_energy = 0.0;
  double reference = 0.0;
};

NaiveGas& naive_gas(std::int64_t n) {
  static std::unique_ptr<NaiveGas> gas;
  if (!gas || static_cast<std::int64_t>(gas->dsmc.particles.size()) != n) {
    gas.reset();
    gas = std::make_unique<NaiveGas>(n);
  }
  return *gas;
}

void naive_collide(benchmark::State& bs) {
  NaiveGas& g = naive_gas(bs.range(0));
  measure_stage(bs, g, [&g] { return g.dsmc.collide(kCandidatesPerIteration); });
}

// ---- the random draws alone ---------------------------------------------------------------------
// The draws of the candidates without touching particle memory: what the RNG and the variate
// conversions cost, as a bound on candidates/s. granmc: the draw phase of the collision stage, batch by
// batch of 64 as collide_step does it (2 Philox4x32-10 blocks per candidate over the batch's counters as
// arrays, 2 indices, the direction n in SIMD, the acceptance uniform). naive: 2 indices
// (std::uniform_int_distribution), the 2 uniforms of the direction and its sin/cos, and the acceptance
// uniform for every other candidate (the loop draws it only when g.sigma > 0, about half of them).

void granmc_draws(benchmark::State& bs) {
  constexpr std::uint64_t batch = 64;
  const RandomStream rng(kSeed, 0);
  const std::uint64_t n = 10'000'000;
  std::uint64_t step = 0, candidates = 0;
  std::array<double, batch> dir1{}, dir2{}, sx, sy, sz, accept;
  std::array<std::uint64_t, batch> ks, ls;
  std::array<std::uint32_t, batch> range_k, range_l;
  range_k.fill(static_cast<std::uint32_t>(n));
  range_l.fill(static_cast<std::uint32_t>(n - 1));
  std::array<std::uint64_t, 2 * batch> steps, index;
  for (auto _ : bs) {
    double sink = 0.0;
    steps.fill(step);
    for (std::uint64_t s0 = 0; s0 < kCandidatesPerIteration; s0 += batch) {
      for (std::uint64_t b = 0; b < batch; ++b) {  // as the stage: block 2s in lane b, 2s + 1 in lane batch + b
        index[b] = 2 * (s0 + b);
        index[batch + b] = 2 * (s0 + b) + 1;
      }
      const RandomBlocks<2 * batch> blocks = rng.blocks(RngPurpose::collision_pair, 0, steps, index);
      const auto& w = blocks.word;
      auto pick = [&](std::size_t word) { return std::span<const std::uint32_t, batch>(w[word].data(), batch); };
      uniform_indices(pick(0), pick(1), range_k, ks);
      uniform_indices(pick(2), pick(3), range_l, ls);
      for (std::uint64_t b = 0; b < batch; ++b) {
        dir1[b] = uniform_open(w[0][batch + b]);
        dir2[b] = uniform_open(w[1][batch + b]);
        accept[b] = uniform_open(w[2][batch + b]);
      }
      unit_vectors(std::span<const double, batch>(dir1), std::span<const double, batch>(dir2), std::span(sx),
                   std::span(sy), std::span(sz));
      for (std::uint64_t b = 0; b < batch; ++b)
        sink += static_cast<double>(ks[b] ^ ls[b]) + sx[b] + sy[b] + sz[b] + accept[b];
    }
    benchmark::DoNotOptimize(sink);
    ++step;
    candidates += kCandidatesPerIteration;
  }
  bs.counters["candidates/s"] = benchmark::Counter(static_cast<double>(candidates), benchmark::Counter::kIsRate);
}

void naive_draws(benchmark::State& bs) {
  std::mt19937_64 gen(kSeed);
  const std::size_t n = 10'000'000;
  std::uint64_t candidates = 0;
  for (auto _ : bs) {
    std::uniform_int_distribution<std::size_t> pick(0, n - 1);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    double sink = 0.0;
    for (std::uint64_t c = 0; c < kCandidatesPerIteration; ++c) {
      const std::size_t k = pick(gen);
      std::size_t l = pick(gen);
      while (l == k) l = pick(gen);
      const double cos_theta = 2.0 * uniform(gen) - 1.0;
      const double sin_theta = std::sqrt(1.0 - cos_theta * cos_theta);
      const double phi = 2.0 * std::numbers::pi * uniform(gen);
      sink += static_cast<double>(k ^ l) + sin_theta * std::cos(phi) + sin_theta * std::sin(phi) + cos_theta;
      if (c & 1u) sink += uniform(gen);
    }
    benchmark::DoNotOptimize(sink);
    candidates += kCandidatesPerIteration;
  }
  bs.counters["candidates/s"] = benchmark::Counter(static_cast<double>(candidates), benchmark::Counter::kIsRate);
}

// ---- ratio table ---------------------------------------------------------------------------------

void print_ratio_table(const perf::RecordingReporter& rep) {
  const auto granmc = rep.counters.find("granmc_collide");
  if (granmc != rep.counters.end() && rep.counters.count("naive_collide")) {
    std::printf("\nCollision stage, alpha = %.1f, %llu candidates per iteration (median of the repetitions)\n",
                kRestitution, static_cast<unsigned long long>(kCandidatesPerIteration));
    std::printf(
        "| N | granmc candidates/s | naive candidates/s | ratio | granmc collisions/s | "
        "naive collisions/s | ratio | acceptance granmc / naive | limit pairs/s | granmc / limit |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
    for (const auto& [args, unused] : granmc->second) {
      const auto g = [&](const char* c) { return rep.value("granmc_collide", args, c); };
      const auto n = [&](const char* c) { return rep.value("naive_collide", args, c); };
      const double limit = rep.value("limit_collide", args, "pairs/s");
      std::printf("| %s | %.3g | %.3g | %.2f | %.3g | %.3g | %.2f | %.4f / %.4f | %.3g | %.2f |\n", args.c_str(),
                  g("candidates/s"), n("candidates/s"), g("candidates/s") / n("candidates/s"), g("collisions/s"),
                  n("collisions/s"), g("collisions/s") / n("collisions/s"), g("acceptance"), n("acceptance"), limit,
                  g("candidates/s") / limit);
    }
    std::printf(
        "(limit: random pair gather + scatter of packed records with prefetch, nothing else; "
        "target granmc / limit >= 0.5)\n");
  }
  const double a = rep.value("granmc_draws", "", "candidates/s"), b = rep.value("naive_draws", "", "candidates/s");
  if (!std::isnan(a) && !std::isnan(b)) {
    std::printf(
        "\nRandom draws alone (no particle memory): granmc %.3g candidates/s (%.1f ns each), "
        "naive %.3g candidates/s (%.1f ns each), ratio %.2f\n",
        a, 1e9 / a, b, 1e9 / b, a / b);
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (!perf::initialize(argc, argv, "1.0")) return 1;

  // Same size next to each other, so that only one gas of each kind is alive at a time.
  for (const std::int64_t n : kSizes) {
    benchmark::RegisterBenchmark("granmc_collide", granmc_stage)->Arg(n)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("naive_collide", naive_collide)->Arg(n)->Unit(benchmark::kMillisecond);
    // The limit kernel, perf/gather_scatter_limit.hpp: the bound the stage is held to (at least
    // half its pairs/s), measured in the same run.
    benchmark::RegisterBenchmark("limit_collide", perf::limit_pairs<kCandidatesPerIteration>)
        ->Arg(n)
        ->Unit(benchmark::kMillisecond);
  }

  benchmark::RegisterBenchmark("granmc_draws", granmc_draws)->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("naive_draws", naive_draws)->Unit(benchmark::kMillisecond);

  perf::RecordingReporter reporter(isatty(STDOUT_FILENO) != 0);
  benchmark::RunSpecifiedBenchmarks(&reporter);
  print_ratio_table(reporter);
  benchmark::Shutdown();
  return 0;
}
