// Throughput of the time-step-free white-noise event scheme (001 sec. 4, schemes/event_scheme.hpp):
// one replica of EventScheme<MaxwellPseudomolecules> (001 Example 7) and EventScheme<HardSphere>
// (001 Example 8) at N = 10^5 and 10^7.
//
// Gas: the physics of drivers/scenes/001_tails/example7.toml and example8.toml, rate = 4/pi, alpha = 0.1,
// white noise beta = 30, Maxwellian start at T = 1 (seeds 1007 and 1008, replica 0). The scheme is built
// once per kernel and size (10^7 particles take about a second, untimed) and kept across Google Benchmark's
// calls, so the gas runs on from one call to the next. Each iteration is advance_to(t + slice), the slice
// chosen from the candidate rate at the iteration's start, pi_hat = 2 pi rate (n - 1) U_max^lambda (001
// eq. 25: 8 (n - 1) per unit time for Maxwell, times the majorant for hard spheres), for about
// candidates_per_iteration(N) candidates: 10^6 at N = 10^5, 2 10^7 at N = 10^7. A hard-sphere slice has a
// few per cent more (U_max rises within it; the first one at 10^7, from T = 1, 25 % more).
//
// Where on the trajectory (counter t): at 10^5 the default run takes the gas to t ~ 2 (hard spheres) and
// ~ 40 (Maxwell), well past the examples' 0.25 and 2.5, i.e. the white-noise steady state. At 10^7 each
// call is one slice, so the 3 repetitions are the first 3 slices: hard spheres to t ~ 0.05 of Example 8's
// 0.25, the heating transient, whose acceptance falls as the gas heats (0.185, 0.181, 0.176 for the three;
// 0.15 by t ~ 0.1 with more repetitions), so --benchmark_repetitions changes the mix a little.
//
// advance_to ends with an O(N) pass that brings every particle to the slice end (001 Remark 2: a Philox
// block, Box-Muller and a record update per particle; for hard spheres also the two passes that reset the
// majorant), 12-16 ns per particle. A production run syncs only at its sample times (examples 7 and 8:
// once), so the pass is timed on its own as well (event_sync_*: advance_to by a slice with about 10^-4
// expected candidates), and the table shows its share of an iteration (about 2 % at 10^5, 10 candidates
// per particle per slice; 5-10 % at 10^7, 2 per particle; more as the loop gets faster) and the candidate
// rate without it.
//
// Counters (rates over CPU time): candidates/s, collisions/s from the difference of tally() before and after
// the timed loop; acceptance = collisions / candidates (1 for Maxwell); candidates/iter; t, the gas time at
// the end. event_sync_*: particles/s. limit_pairs/N: the packed-record gather/scatter limit kernel
// (perf/gather_scatter_limit.hpp, 10^6 pairs per iteration, pairs/s), run after the event benchmarks of the
// same N, so that event_<kernel>_over_packed_limit comes from one run. A table of the medians follows.
// Defaults: 3 repetitions, aggregates only, min time 0.5 s; any --benchmark_* flag overrides them.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <memory>
#include <numbers>
#include <string>

#include <benchmark/benchmark.h>

#include "kernel/collide/hard_sphere.hpp"
#include "kernel/collide/maxwell_pseudomolecules.hpp"
#include "kernel/collide/variable_hard_spheres.hpp"
#include "kernel/core/scene.hpp"
#include "kernel/schemes/event_scheme.hpp"
#include "perf/bench_common.hpp"
#include "perf/gather_scatter_limit.hpp"

namespace {

using namespace granmc;

constexpr double kRate = 4.0 / std::numbers::pi;  // gamma C_lambda = 16 / (4 pi)
constexpr double kRestitution = 0.1;
constexpr double kBeta = 30.0;
constexpr std::int64_t kSizes[] = {100'000, 10'000'000};
constexpr double kSyncCandidates = 1e-4;  // expected candidates in an event_sync slice

/// Candidates per benchmark iteration (one advance_to): 10 per particle at 10^5, 2 per particle at 10^7.
constexpr double candidates_per_iteration(std::int64_t n) { return n >= 10'000'000 ? 2e7 : 1e6; }

template <class Kernel>
constexpr std::uint64_t seed_of() {
  return Kernel::constant_rate ? 1007 : 1008;  // example7.toml, example8.toml
}

Scene event_scene(std::int64_t particles, CollisionKernel kernel, std::uint64_t seed) {
  Scene s;
  s.run.method = Method::event;
  s.run.seed = seed;
  s.run.replicas = 1;
  s.run.t_end = 1.0;  // not used: the benchmark advances by slices
  s.run.samples = 1;
  s.species.push_back({"grains", 1.0, 1.0, 1.0, particles});
  s.collision.kernel = kernel;
  s.collision.lambda = kernel == CollisionKernel::maxwell ? 0.0 : 1.0;
  s.collision.rate = kRate;
  s.collision.restitution = {{{kRestitution, kRestitution}, {kRestitution, kRestitution}}};
  s.thermostat.kind = ThermostatKind::white_noise;
  s.thermostat.beta = kBeta;
  s.initial_temperature = 1.0;
  return s;
}

template <class Kernel>
struct EventGas {
  explicit EventGas(std::int64_t n)
      : particles(n),
        sim(event_scene(n, Kernel::constant_rate ? CollisionKernel::maxwell : CollisionKernel::hard_sphere,
                        seed_of<Kernel>()),
            0, Kernel{}) {}

  /// pi_hat of 001 eq. (25) now, per unit time: 2 pi rate (n - 1) U_max^lambda (u = 1: T(0) = 1).
  double candidate_rate() const {
    const double base = 2.0 * std::numbers::pi * kRate * static_cast<double>(particles - 1);
    return Kernel::constant_rate ? base : base * std::pow(sim.majorant(), Kernel{}.lambda);
  }
  /// advance_to the time when about `candidates` candidates are expected (at least one ulp ahead).
  void advance_by(double candidates) {
    const double t = sim.state().time;
    sim.advance_to(std::max(t + candidates / candidate_rate(), std::nextafter(t, INFINITY)));
  }

  std::int64_t particles;
  EventScheme<Kernel> sim;
};

// One gas alive at a time (10^7 particles are 320 MB), kept across Google Benchmark's calls of the same
// kernel and size; building another frees it first.
std::function<void()> release_current_gas;

template <class Kernel>
EventGas<Kernel>& event_gas(std::int64_t n) {
  static std::unique_ptr<EventGas<Kernel>> gas;
  if (!gas || gas->particles != n) {
    if (release_current_gas) release_current_gas();
    gas.reset();
    gas = std::make_unique<EventGas<Kernel>>(n);
    release_current_gas = [] { gas.reset(); };
  }
  return *gas;
}

template <class Kernel>
void event_run(benchmark::State& bs) {
  EventGas<Kernel>& g = event_gas<Kernel>(bs.range(0));
  const double per_iteration = candidates_per_iteration(bs.range(0));
  const EventTally before = g.sim.tally();
  for (auto _ : bs) g.advance_by(per_iteration);
  const EventTally after = g.sim.tally();
  const auto candidates = static_cast<double>(after.candidates - before.candidates);
  const auto collisions = static_cast<double>(after.collisions - before.collisions);
  bs.counters["candidates/s"] = benchmark::Counter(candidates, benchmark::Counter::kIsRate);
  bs.counters["collisions/s"] = benchmark::Counter(collisions, benchmark::Counter::kIsRate);
  bs.counters["acceptance"] = candidates > 0.0 ? collisions / candidates : 0.0;
  bs.counters["candidates/iter"] = benchmark::Counter(candidates, benchmark::Counter::kAvgIterations);
  bs.counters["t"] = g.sim.state().time;  // how far the gas has run (the examples: 2.5 and 0.25)
}

/// The O(N) pass of advance_to alone: a slice with about kSyncCandidates expected candidates.
template <class Kernel>
void event_sync(benchmark::State& bs) {
  EventGas<Kernel>& g = event_gas<Kernel>(bs.range(0));
  for (auto _ : bs) g.advance_by(kSyncCandidates);
  bs.counters["particles/s"] = benchmark::Counter(
      static_cast<double>(bs.iterations()) * static_cast<double>(g.particles), benchmark::Counter::kIsRate);
}

// ---- table ---------------------------------------------------------------------------------------

void print_table(const perf::RecordingReporter& rep) {
  std::printf("\nEvent scheme, 001 examples 7-8 (rate 4/pi, alpha = %.1f, beta = %.0f), median of the repetitions\n",
              kRestitution, kBeta);
  std::printf(
      "| kernel | N | candidates/s | collisions/s | acceptance | candidates/iter | sync ms | "
      "sync share | candidates/s without sync | candidates/s / limit pairs/s |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  for (const char* kernel : {"maxwell", "hard_sphere"}) {
    const std::string run = std::string("event_") + kernel, sync = std::string("event_sync_") + kernel;
    const auto runs = rep.counters.find(run);
    if (runs == rep.counters.end()) continue;
    for (const auto& [args, unused] : runs->second) {
      const auto get = [&](const char* c) { return rep.value(run, args, c); };
      const double cand = get("candidates/s"), per_iter = get("candidates/iter");
      const double n = std::stod(args);
      const double sync_s = n / rep.value(sync, args, "particles/s");  // NaN if event_sync_* did not run
      const double iter_s = per_iter / cand;
      std::printf("| %s | %s | %.3g | %.3g | %.4f | %.3g | ", kernel, args.c_str(), cand, get("collisions/s"),
                  get("acceptance"), per_iter);
      if (std::isnan(sync_s))
        std::printf("- | - | - | ");  // event_sync_* filtered out
      else
        std::printf("%.1f | %.0f %% | %.3g | ", 1e3 * sync_s, 100.0 * sync_s / iter_s, per_iter / (iter_s - sync_s));
      std::printf("%.3f |\n", cand / rep.value("limit_pairs", args, "pairs/s"));  // NaN if limit_pairs did not run
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (!perf::initialize(argc, argv, "0.5")) return 1;

  // Each kernel's runs next to each other at one size, so that each gas is built once.
  for (const std::int64_t n : kSizes) {
    benchmark::RegisterBenchmark("event_maxwell", event_run<MaxwellPseudomolecules>)
        ->Arg(n)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("event_sync_maxwell", event_sync<MaxwellPseudomolecules>)
        ->Arg(n)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("event_hard_sphere", event_run<HardSphere>)->Arg(n)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("event_sync_hard_sphere", event_sync<HardSphere>)
        ->Arg(n)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("limit_pairs", perf::limit_pairs<1'000'000>)->Arg(n)->Unit(benchmark::kMillisecond);
  }

  perf::RecordingReporter reporter(isatty(STDOUT_FILENO) != 0);
  benchmark::RunSpecifiedBenchmarks(&reporter);
  print_table(reporter);
  benchmark::Shutdown();
  return 0;
}
