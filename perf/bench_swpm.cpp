// Throughput of the weighted particles (SWPM, schemes/swpm_scheme.hpp) against the equal-weight event scheme
// (schemes/event_scheme.hpp) in the same run: one replica of SwpmScheme<MaxwellPseudomolecules> (001 Example 7)
// and SwpmScheme<HardSphere> (001 Example 8), each beside an EventScheme of the same physics holding as many
// particles as the weighted gas holds at its steady state, so that swpm / event is per particle held and
// both sides share the state of the (shared, noisy) machine.
//
// Gas: the physics of drivers/scenes/001_tails_weighted/example7.toml and example8.toml, rate = 4/pi,
// alpha = 0.1, white noise beta = 30, Maxwellian start at T = 1 with 20000 particles, replica 0, seeds 2007
// and 2008; the weighted gas with histogram = { shells = 256, radius = 80 } (Maxwell) or radius = 32 (hard
// spheres) and [weights] particles_per_shell = 128, growth 2. The event gas has the same scene without
// [weights] and N = the weighted gas's count (below), so it starts from another Maxwellian.
//
// Warm-up (not timed, on the first call; each gas is kept for the whole program, so it runs on from one of
// Google Benchmark's calls to the next): advance_to(0.8 t_s), then to t_s in kCalibrationSlices equal
// steps, t_s = 2.5 (Maxwell) and 0.25 (hard spheres), where the examples' histogram window starts and the
// weighted count has long stopped growing (it settles by t ~ 1 and t ~ 0.1; between its controls it is a
// sawtooth, see below). The candidates of [0.8 t_s, t_s] over its length give the mean candidate rate, and
// each timed iteration is advance_to(t + slice) with slice = kCandidatesPerIteration / that rate, 10^6
// candidates on average (the weighted count, hence the majorant rate pi_hat = 4 pi rate U_max^lambda W_hat
// (n - 1), grows within a slice, so the rate at a slice's start would undercount). The event gas's N is
// the mean of the weighted count at the ends of those steps, rounded, and it is built and warmed the same
// way (same t_s), after the weighted gas of its kernel.
//
// What "particles held" means: advance_to ends, as at a sample time, by bringing every particle to the
// slice end and running the weight control (schemes/weight_control.hpp), which splits heavy particles and
// reduces shells holding more than 2 M; in between, every collision of unequal weights adds a particle
// (the weight transfer) and touched heavy particles are split, until the count reaches growth = 2 times
// its value after the last control and the control runs again. So the count at a slice end (counter
// particles, and the event N) is the sawtooth's low end, what a sample sees; averaged over time the weighted
// gas holds about 15 % more (docs/developer-guide/performance.md). The event scheme's rates hardly depend on N at this
// size (bench_event's event_maxwell runs as fast at 10^5), so the ratios do not hang on which count is taken.
//
// Counters (rates over CPU time): candidates/s, collisions/s (real collisions, the tally's difference over
// the timed loop; for the weighted gas a collision of unequal weights is one collision, whatever weight it
// moves), acceptance = collisions / candidates, candidates/iter, particles (mean count at the iteration
// ends), bytes/particle, gas_time/s (gas time advanced per CPU second), controls/iter (weighted gas: whole-
// system weight controls per iteration, each an O(n) split pass and a sort of the overfull shells), t (gas
// time at the end). bytes/particle is the size of the per-particle arrays, not their capacity: the event
// scheme's packed record (x, y, z, last update; 4 doubles = 32 bytes); WeightedParticles' velocity (Vec3),
// last update and weight (doubles), its class (int), its place in the class list and its entry in that list
// (uint32), 52 bytes. Not counted: the vectors' unused capacity (push_back growth; a reduction rebuilds them
// at their size), the class lists' headers (a vector per weight class) and the control's scratch arrays,
// which live only while it runs. A table of the medians and the ratios swpm / event follows.
// Defaults: 3 repetitions, aggregates only, min time 0.5 s; any --benchmark_* flag overrides them
// (--benchmark_enable_random_interleaving=true is cheap: no gas is rebuilt).
#include <unistd.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <string>

#include <benchmark/benchmark.h>

#include "kernel/collide/hard_sphere.hpp"
#include "kernel/collide/maxwell_pseudomolecules.hpp"
#include "kernel/core/scene.hpp"
#include "kernel/core/vec3.hpp"
#include "kernel/schemes/event_scheme.hpp"
#include "kernel/schemes/swpm_scheme.hpp"
#include "perf/bench_common.hpp"

namespace {

using namespace granmc;

constexpr double kRate = 4.0 / std::numbers::pi;  // gamma C_lambda = 16 / (4 pi)
constexpr double kRestitution = 0.1;
constexpr double kBeta = 30.0;
constexpr std::int64_t kStartParticles = 20'000;
constexpr int kShells = 256;
constexpr int kParticlesPerShell = 128;
constexpr double kCandidatesPerIteration = 1e6;
constexpr int kCalibrationSlices = 5;  // steps of [0.8 t_s, t_s] whose end counts give the event N

/// Per-particle bytes of the arrays (see the header): WeightedParticles' velocity_, last_update_, weight_,
/// class_, position_ and the entry in members_; the event scheme's packed record.
constexpr std::size_t kSwpmBytes = sizeof(Vec3) + 2 * sizeof(double) + sizeof(int) + 2 * sizeof(std::uint32_t);
constexpr std::size_t kEventBytes = 4 * sizeof(double);

/// Example 7 (Maxwell) or 8 (hard spheres): seed, histogram radius, the time the warm-up reaches.
template <class Kernel>
struct Example {
  static constexpr bool maxwell = Kernel::constant_rate;
  static constexpr std::uint64_t seed = maxwell ? 2007 : 2008;
  static constexpr double radius = maxwell ? 80.0 : 32.0;
  static constexpr double steady_time = maxwell ? 2.5 : 0.25;
};

template <class Kernel>
Scene example_scene(std::int64_t particles, bool weighted) {
  using E = Example<Kernel>;
  Scene s;
  s.run.method = Method::event;
  s.run.seed = E::seed;
  s.run.replicas = 1;
  s.run.t_end = 1.0;  // not used: the benchmark advances by slices
  s.run.samples = 1;
  s.species.push_back({"grains", 1.0, 1.0, 1.0, particles});
  s.collision.kernel = E::maxwell ? CollisionKernel::maxwell : CollisionKernel::hard_sphere;
  s.collision.lambda = E::maxwell ? 0.0 : 1.0;
  s.collision.rate = kRate;
  s.collision.restitution = {{{kRestitution, kRestitution}, {kRestitution, kRestitution}}};
  s.thermostat.kind = ThermostatKind::white_noise;
  s.thermostat.beta = kBeta;
  s.initial_temperature = 1.0;
  s.histogram.shells = kShells;
  s.histogram.radius = E::radius;
  if (weighted) s.weights = WeightsConfig{kParticlesPerShell, 2.0};
  return s;
}

// The two schemes' accessors, under one name.
template <class K>
double gas_time(const SwpmScheme<K>& sim) {
  return sim.time();
}
template <class K>
double gas_time(const EventScheme<K>& sim) {
  return sim.state().time;
}
template <class K>
std::size_t held(const SwpmScheme<K>& sim) {
  return sim.particles().size();
}
template <class K>
std::size_t held(const EventScheme<K>& sim) {
  return sim.state().species[0].size();
}
template <class K>
std::uint64_t controls(const SwpmScheme<K>& sim) {
  return sim.control_tally().controls;
}
template <class K>
std::uint64_t controls(const EventScheme<K>&) {
  return 0;
}

/// One gas, warmed up and calibrated on construction. The scene is a member before the scheme: SwpmScheme
/// keeps a reference to it.
template <class Kernel, template <class> class Scheme>
struct Warmed {
  Warmed(std::int64_t start_particles, bool weighted)
      : scene(example_scene<Kernel>(start_particles, weighted)), sim(scene, 0, Kernel{}) {
    const double t_s = Example<Kernel>::steady_time, t_a = 0.8 * t_s;
    sim.advance_to(t_a);
    const std::uint64_t before = sim.tally().candidates;
    double count = 0.0;
    for (int k = 1; k <= kCalibrationSlices; ++k) {
      sim.advance_to(t_a + (t_s - t_a) * k / kCalibrationSlices);
      count += static_cast<double>(held(sim));
    }
    steady_count = count / kCalibrationSlices;
    slice = kCandidatesPerIteration * (t_s - t_a) / static_cast<double>(sim.tally().candidates - before);
  }

  Scene scene;
  Scheme<Kernel> sim;
  double steady_count = 0.0;  // mean count at the calibration steps' ends
  double slice = 0.0;         // gas time per iteration
};

template <class Kernel>
Warmed<Kernel, SwpmScheme>& swpm_gas() {
  static Warmed<Kernel, SwpmScheme> gas(kStartParticles, true);
  return gas;
}

template <class Kernel>
Warmed<Kernel, EventScheme>& event_gas() {
  // N = the weighted gas's steady count
  static Warmed<Kernel, EventScheme> gas(std::llround(swpm_gas<Kernel>().steady_count), false);
  return gas;
}

template <class Gas>
void run(benchmark::State& bs, Gas& g, double bytes) {
  const auto before = g.sim.tally();
  const std::uint64_t controls_before = controls(g.sim);
  const double t0 = gas_time(g.sim);
  double count = 0.0;
  for (auto _ : bs) {
    g.sim.advance_to(gas_time(g.sim) + g.slice);
    count += static_cast<double>(held(g.sim));
  }
  const auto after = g.sim.tally();
  const auto candidates = static_cast<double>(after.candidates - before.candidates);
  const auto collisions = static_cast<double>(after.collisions - before.collisions);
  const auto iterations = static_cast<double>(bs.iterations());
  bs.counters["candidates/s"] = benchmark::Counter(candidates, benchmark::Counter::kIsRate);
  bs.counters["collisions/s"] = benchmark::Counter(collisions, benchmark::Counter::kIsRate);
  bs.counters["acceptance"] = candidates > 0.0 ? collisions / candidates : 0.0;
  bs.counters["candidates/iter"] = benchmark::Counter(candidates, benchmark::Counter::kAvgIterations);
  bs.counters["particles"] = iterations > 0.0 ? count / iterations : 0.0;
  bs.counters["bytes/particle"] = bytes;
  bs.counters["gas_time/s"] = benchmark::Counter(gas_time(g.sim) - t0, benchmark::Counter::kIsRate);
  bs.counters["controls/iter"] =
      benchmark::Counter(static_cast<double>(controls(g.sim) - controls_before), benchmark::Counter::kAvgIterations);
  bs.counters["t"] = gas_time(g.sim);
}

template <class Kernel>
void swpm_run(benchmark::State& bs) {
  run(bs, swpm_gas<Kernel>(), kSwpmBytes);
}
template <class Kernel>
void event_run(benchmark::State& bs) {
  run(bs, event_gas<Kernel>(), kEventBytes);
}

// ---- table ---------------------------------------------------------------------------------------

void print_table(const perf::RecordingReporter& rep) {
  std::printf(
      "\nWeighted (swpm) against equal-weight (event) particles, 001 examples 7-8 (rate 4/pi, alpha = %.1f, "
      "beta = %.0f), median of the repetitions\n",
      kRestitution, kBeta);
  std::printf(
      "| kernel | scheme | particles | bytes/particle | candidates/s | collisions/s | acceptance | gas time/s | "
      "controls/iter |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  for (const char* kernel : {"maxwell", "hard_sphere"})
    for (const char* scheme : {"swpm", "event"}) {
      const std::string name = std::string(scheme) + "_" + kernel;
      if (rep.counters.find(name) == rep.counters.end()) continue;
      const auto get = [&](const char* c) { return rep.value(name, "", c); };
      std::printf("| %s | %s | %.0f | %.0f | %.3g | %.3g | %.4f | %.3g | %.1f |\n", kernel, scheme, get("particles"),
                  get("bytes/particle"), get("candidates/s"), get("collisions/s"), get("acceptance"), get("gas_time/s"),
                  get("controls/iter"));
    }
  std::printf("\n| kernel | swpm / event: collisions/s | candidates/s | gas time/s |\n|---|---|---|---|\n");
  for (const char* kernel : {"maxwell", "hard_sphere"}) {
    const std::string swpm = std::string("swpm_") + kernel, event = std::string("event_") + kernel;
    const auto ratio = [&](const char* c) { return rep.value(swpm, "", c) / rep.value(event, "", c); };
    const double collisions = ratio("collisions/s");
    if (std::isnan(collisions)) continue;  // one of the two filtered out
    std::printf("| %s | %.3f | %.3f | %.3f |\n", kernel, collisions, ratio("candidates/s"), ratio("gas_time/s"));
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (!perf::initialize(argc, argv, "0.5")) return 1;

  // Each weighted gas first (its warm-up sets the event gas's N), then the event gas of the same kernel.
  benchmark::RegisterBenchmark("swpm_maxwell", swpm_run<MaxwellPseudomolecules>)->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("event_maxwell", event_run<MaxwellPseudomolecules>)->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("swpm_hard_sphere", swpm_run<HardSphere>)->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("event_hard_sphere", event_run<HardSphere>)->Unit(benchmark::kMillisecond);

  perf::RecordingReporter reporter(isatty(STDOUT_FILENO) != 0);
  benchmark::RunSpecifiedBenchmarks(&reporter);
  print_table(reporter);
  benchmark::Shutdown();
  return 0;
}
