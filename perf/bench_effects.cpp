// The cost of each effect: whole time steps of Dsmc through its public API (advance_to)
// for a hard-sphere cooling state at N = 10^6, per candidate pair, with each effect that exists today
// added alone, as a ratio to the plain scene measured in the same run; and a hand-specialised kernel
// for the plain scene (perf/hand_specialised_hcs.hpp), which the plain scene should match within 3%.
//
// Scenes (all: inelastic hard spheres, alpha = 0.8, sigma = m = 1, total n = 1, total N = 10^6,
// Maxwellian start at T = 1, seed kSeed, replica 0):
//   plain                one species, packing_fraction = 0, no thermostat: dsmc<hard-sphere>
//   enskog_chi           packing_fraction = 0.2 (chi = 1.758 in the pair rate; no per-candidate work)
//   gaussian_thermostat  thermostat gaussian, zeta = "cooling-rate" (O(1) per step, on log u)
//   white_noise          thermostat white-noise, beta = zeta(T = 1) / 2 (Haff's zeta with the HCS a2), so the
//                        noise heating 2 beta balances the collisional cooling zeta T at T = 1 (O(N) per step)
//   two_species          two identical species of N/2 each, n_i = 1/2: the mixture path (4 ordered pairs,
//                        interleaved) with the plain scene's physics
//   maxwell_kernel       kernel maxwell with collision.rate = 1/4 (the 001 form): dsmc<maxwell>
//   hand_specialised     perf/hand_specialised_hcs.hpp on the plain scene's initial state
//   shear                shear.rate = 0.5, dilute: the inertial force in free flight (O(N) per step) and the
//                        kinetic pressure only at samples (none here): dsmc<hard-sphere, lagrangian-shear>
//   enskog_shear         shear.rate = 0.5 at phi = 0.2 (n = 6 phi / pi, as shear requires): the inertial force
//                        and the Enskog shift with its shear-work and collisional-transfer tallies per collision
//   relaxation           the gaussian_thermostat scene with 003's relaxation term (O(replaced) per step)
//
// Each benchmark iteration is one whole time step: advance_to(t + dt) with the scene's run.dt = t_end as an
// upper bound and dt chosen before each step so that the step has kCandidateFraction N = N/10 candidates
// in total, sum_q 1/2 N_q' omega_max^(q) u^lambda dt = N/10 (Dsmc::step's count; N_q' = N_i - 1 within
// a species). So every scene runs whole steps of the same size whatever its cooling, chi or kernel, and a
// per-step cost (white noise: O(N)) is weighed against the same number of candidates everywhere. The
// rescaling of Dsmc (an O(N) pass when the stored energy has fallen by 1.25) is inside the step, as in a
// run. Each scene's gas is built once (not timed) and kept alive for the whole program, so it goes on
// cooling across Google Benchmark's calls.
//
// Counters (CPU time): time/cand = CPU time per candidate pair of whole steps; cand/step; acceptance =
// collisions / candidates; rescales/kstep = Dsmc's O(N) rescaling passes per 1000 steps (a scene that
// loses more energy per candidate rescales more often: part of its cost, not overhead). Two more
// benchmarks time the white-noise effect alone (WhiteNoise::apply on a GasState of N = 10^6) and its
// random draws alone (1 Philox block and 2 Box-Muller pairs, no particle memory), per particle, to
// compare with the extra cost per particle per step of the white_noise scene.
// After the runs a table gives the medians, the ratios to plain and the plain / hand-specialised ratio.
//
// Before anything runs, check_hand_matches_library() runs collide_step<HardSphere> and hand_collide on
// the same states and seeds and aborts unless velocities, majorants and tallies are the same bits.
//
// Defaults: 5 repetitions, aggregates only, min time 1 s (0.5 s for the per-particle benchmarks),
// random interleaving of the repetitions (the gases stay alive, so this costs no rebuilding); any
// --benchmark_* flag overrides them. About 90 s on the project machine (2 vCPUs); nine gases of 32 MB each.
// Without the plain benchmark (e.g. --benchmark_filter=hand) the ratios print as nan.
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>
#include <memory>
#include <numbers>
#include <string>
#include <tuple>
#include <vector>

#include <benchmark/benchmark.h>

#include "kernel/collide/enskog_shear_shift.hpp"
#include "kernel/collide/hard_sphere.hpp"
#include "kernel/collide/maxwell_pseudomolecules.hpp"
#include "kernel/collide/pair_coefficients.hpp"
#include "kernel/core/philox_stream.hpp"
#include "kernel/core/sampling.hpp"
#include "kernel/core/scene.hpp"
#include "kernel/effects/bgk_relaxation.hpp"
#include "kernel/effects/gaussian_thermostat.hpp"
#include "kernel/effects/lagrangian_shear.hpp"
#include "kernel/effects/white_noise.hpp"
#include "kernel/schemes/collision_stage.hpp"
#include "kernel/schemes/dsmc.hpp"
#include "kernel/schemes/gas_state.hpp"
#include "kernel/schemes/initial_state.hpp"
#include "kernel/setup/explain.hpp"
#include "kernel/setup/run_scene.hpp"
#include "kernel/theory/sonine.hpp"
#include "perf/bench_common.hpp"
#include "perf/hand_specialised_hcs.hpp"

namespace {

using namespace granmc;

constexpr std::int64_t kParticles = 1'000'000;
constexpr double kCandidateFraction = 0.1;  // candidates per step / N
constexpr double kRestitution = 0.8;
constexpr std::uint64_t kSeed = 20240601;
constexpr double kPackingFraction = 0.2;
constexpr double kMaxwellRate = 0.25;  // collision.rate of the maxwell_kernel scene (n sigma^2 = 4 rate)
int paired_rounds = 301;  // rounds of the paired ratios (--paired_rounds=N, this program's own flag; 0: none)

// ---- scenes --------------------------------------------------------------------------------------

SpeciesConfig species(const char* name, double density, std::int64_t particles) {
  SpeciesConfig s;
  s.name = name;
  s.mass = 1.0;
  s.diameter = 1.0;
  s.density = density;
  s.particles = particles;
  return s;
}

/// The plain scene: one species, dilute, hard spheres, no thermostat. The benchmark chooses every
/// step's length (see the header); run.dt = t_end only keeps Dsmc::advance_to from splitting a step. (With
/// run.dt = 1, a cooling gas's N/10-candidate step outgrew it once T had fallen by about 3 10^4, and
/// advance_to split each benchmark step into hundreds: a long run, e.g. with a --benchmark_filter,
/// measured the plain scene at a median of 34521 candidates per step.)
Scene plain_scene(std::int64_t particles = kParticles) {
  Scene scene;
  scene.run.seed = kSeed;
  scene.run.t_end = 1e12;
  scene.run.dt = scene.run.t_end;
  scene.run.dt_scaling = DtScaling::fixed;
  scene.species.push_back(species("grains", 1.0, particles));
  scene.collision.kernel = CollisionKernel::hard_sphere;
  scene.collision.restitution = {{{kRestitution, kRestitution}, {kRestitution, kRestitution}}};
  scene.initial_temperature = 1.0;
  return scene;
}

Scene enskog_scene() {
  Scene s = plain_scene();
  s.collision.packing_fraction = kPackingFraction;
  return s;
}

Scene gaussian_scene() {
  Scene s = plain_scene();
  s.thermostat.kind = ThermostatKind::gaussian;
  s.thermostat.zeta_is_cooling_rate = true;
  return s;
}

/// beta = zeta(T = 1) / 2: dT/dt = 2 beta m - zeta T vanishes at T = 1 (roughly: the HCS a2 in zeta).
double balancing_beta() {
  return 0.5 * theory::cooling_rate(kRestitution, 1.0, 1.0, 1.0, 1.0, 1.0, theory::hcs_a2(kRestitution));
}

Scene white_noise_scene() {
  Scene s = plain_scene();
  s.thermostat.kind = ThermostatKind::white_noise;
  s.thermostat.beta = balancing_beta();
  return s;
}

constexpr double kShearRate = 0.5;  // a* = 0.2 at T = 1 (dilute)

Scene shear_scene() {
  Scene s = plain_scene();
  s.shear_rate = kShearRate;
  return s;
}

Scene enskog_shear_scene() {
  Scene s = enskog_scene();
  s.species[0].density = 6.0 * kPackingFraction / std::numbers::pi;  // phi = pi n sigma^3 / 6
  s.shear_rate = kShearRate;
  return s;
}

Scene relaxation_scene() {
  Scene s = gaussian_scene();
  s.relaxation = true;
  return s;
}

Scene two_species_scene() {
  Scene s = plain_scene();
  s.species = {species("a", 0.5, kParticles / 2), species("b", 0.5, kParticles - kParticles / 2)};
  return s;
}

Scene maxwell_scene() {
  Scene s = plain_scene();
  s.collision.kernel = CollisionKernel::maxwell;
  s.collision.lambda = 0.0;
  s.collision.rate = kMaxwellRate;
  return s;
}

// ---- gases that take whole steps -----------------------------------------------------------------

struct Counts {
  std::uint64_t steps = 0, candidates = 0, collisions = 0, rescales = 0;
};

class Gas {
 public:
  virtual ~Gas() = default;
  /// One whole time step with kCandidateFraction N candidates (to the carried fraction).
  virtual void step() = 0;
  [[nodiscard]] virtual Counts counts() const = 0;
};

template <class Kernel, class... Effects>
class DsmcGas final : public Gas {
 public:
  /// make_effects(scene) gives the effects as a tuple; they may keep a pointer to the gas's own scene.
  template <class MakeEffects>
  DsmcGas(Scene scene, MakeEffects make_effects) : scene_(std::move(scene)), pairs_(pair_coefficients(scene_)) {
    if (const std::string why = plan_refusal(scene_); !why.empty()) {
      std::fprintf(stderr, "bench_effects: a benchmark scene is not supported: %s\n", why.c_str());
      std::abort();
    }
    sim_ = std::apply([&](auto... e) { return std::make_unique<Dsmc<Kernel, Effects...>>(scene_, 0, e...); },
                      make_effects(scene_));
  }

  void step() override { sim_->advance_to(sim_->state().time + step_length()); }

  [[nodiscard]] Counts counts() const override {
    return {sim_->state().step, sim_->tally().candidates, sim_->tally().collisions, sim_->rescales()};
  }

 private:
  /// dt with sum_q 1/2 N_q' omega_max^(q) u^lambda dt = kCandidateFraction N (Dsmc::step's count).
  [[nodiscard]] double step_length() const noexcept {
    double per_time = 0.0;
    double n = 0.0;
    for (std::size_t q = 0; q < pairs_.size(); ++q) {
      const double n_i = static_cast<double>(scene_.species[pairs_[q].i].particles);
      per_time += 0.5 * (pairs_[q].i == pairs_[q].j ? n_i - 1.0 : n_i) * sim_->omega_max()[q];
    }
    for (const SpeciesConfig& s : scene_.species) n += static_cast<double>(s.particles);
    return kCandidateFraction * n / (per_time * std::exp(Kernel::lambda * sim_->state().scale.log_u));
  }

  Scene scene_;  // Dsmc and the effects keep references to it: the gas is never moved
  std::vector<PairCoefficients> pairs_;
  std::unique_ptr<Dsmc<Kernel, Effects...>> sim_;
};

class HandGas final : public Gas {
 public:
  HandGas() {
    const Scene scene = plain_scene();
    const RandomStream rng(scene.run.seed, 0);
    const GasState s0 = maxwellian_state(scene, rng);  // the plain scene's initial state
    hand_ = std::make_unique<perf::HandHcs>([&](std::uint64_t k) { return s0.species[0].velocity(k); },
                                            s0.species[0].size(), s0.scale.log_u,
                                            perf::HandConstants::of(kRestitution, 1.0, 1.0, 1.0), rng);
  }
  void step() override {
    const double n = static_cast<double>(hand_->particles());
    hand_->step(kCandidateFraction * n / (0.5 * (n - 1.0) * hand_->omega_max() * std::exp(hand_->log_u())));
  }
  [[nodiscard]] Counts counts() const override {
    return {hand_->steps(), hand_->candidates(), hand_->collisions(), hand_->rescales()};
  }

 private:
  std::unique_ptr<perf::HandHcs> hand_;
};

auto no_effects = [](const Scene&) { return std::tuple<>{}; };

struct SceneBench {
  const char* name;
  std::function<Scene()> scene;  // for the instantiation name in the table (empty: hand-specialised)
  std::function<std::unique_ptr<Gas>()> make;
};

const std::vector<SceneBench>& scene_benches() {
  static const std::vector<SceneBench> list = {
      {"plain", [] { return plain_scene(); },
       [] { return std::make_unique<DsmcGas<HardSphere>>(plain_scene(), no_effects); }},
      {"enskog_chi", enskog_scene, [] { return std::make_unique<DsmcGas<HardSphere>>(enskog_scene(), no_effects); }},
      {"gaussian_thermostat", gaussian_scene,
       [] {
         return std::make_unique<DsmcGas<HardSphere, GaussianThermostat>>(gaussian_scene(), [](const Scene& s) {
           return std::tuple{GaussianThermostat{true, s.thermostat.zeta}};
         });
       }},
      {"white_noise", white_noise_scene,
       [] {
         return std::make_unique<DsmcGas<HardSphere, WhiteNoise>>(white_noise_scene(), [](const Scene& s) {
           return std::tuple{WhiteNoise{s.thermostat.beta, species_masses(s)}};
         });
       }},
      {"shear", shear_scene,
       [] {
         return std::make_unique<DsmcGas<HardSphere, LagrangianShear>>(shear_scene(), [](const Scene& s) {
           return std::tuple{LagrangianShear{s.shear_rate, species_masses(s)}};
         });
       }},
      {"enskog_shear", enskog_shear_scene,
       [] {
         return std::make_unique<DsmcGas<HardSphere, LagrangianShear, EnskogShearShift>>(
             enskog_shear_scene(), [](const Scene& s) {
               return std::tuple{LagrangianShear{s.shear_rate, species_masses(s)}, EnskogShearShift{s.shear_rate}};
             });
       }},
      {"relaxation", relaxation_scene,
       [] {
         return std::make_unique<DsmcGas<HardSphere, GaussianThermostat, BgkRelaxation>>(
             relaxation_scene(), [](const Scene& s) {
               return std::tuple{GaussianThermostat{true, s.thermostat.zeta},
                                 BgkRelaxation{SonineMaxwellian(theory::hcs_a2(kRestitution)), 1.0}};
             });
       }},
      {"two_species", two_species_scene,
       [] { return std::make_unique<DsmcGas<HardSphere>>(two_species_scene(), no_effects); }},
      {"maxwell_kernel", maxwell_scene,
       [] { return std::make_unique<DsmcGas<MaxwellPseudomolecules>>(maxwell_scene(), no_effects); }},
      {"hand_specialised", nullptr, [] { return std::make_unique<HandGas>(); }},
  };
  return list;
}

/// Each scene's gas, built on first use and kept for the whole program (about 32 MB each).
Gas& gas(const SceneBench& b) {
  static std::map<std::string, std::unique_ptr<Gas>> gases;
  std::unique_ptr<Gas>& g = gases[b.name];
  if (!g) g = b.make();
  return *g;
}

void whole_steps(benchmark::State& bs, const SceneBench* b) {
  Gas& g = gas(*b);
  const Counts c0 = g.counts();
  for (auto _ : bs) g.step();
  const Counts c1 = g.counts();
  const double candidates = static_cast<double>(c1.candidates - c0.candidates);
  bs.counters["time/cand"] = benchmark::Counter(candidates, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  bs.counters["cand/step"] = candidates / static_cast<double>(c1.steps - c0.steps);
  bs.counters["acceptance"] = static_cast<double>(c1.collisions - c0.collisions) / candidates;
  bs.counters["rescales/kstep"] =
      1000.0 * static_cast<double>(c1.rescales - c0.rescales) / static_cast<double>(c1.steps - c0.steps);
}

// ---- the white-noise effect alone, per particle -------------------------------------------------

void white_noise_apply(benchmark::State& bs) {
  static const Scene scene = white_noise_scene();
  static const RandomStream rng(kSeed, 1);
  static GasState state = maxwellian_state(scene, rng);
  const WhiteNoise effect{scene.thermostat.beta, species_masses(scene)};
  // dt of a plain step at T = 1: N/10 candidates at omega_max ~ 4 pi (2 max |c|) ~ 4 pi 11
  const double dt = 2.0 * kCandidateFraction / (4.0 * std::numbers::pi * 11.0);
  double change = 0.0;
  std::uint64_t particles = 0;
  for (auto _ : bs) {
    change += effect.apply(state, StepContext{dt, 3.0 * kParticles, 0.0, &rng});
    ++state.step;
    particles += state.species[0].size();
  }
  benchmark::DoNotOptimize(change);
  bs.counters["time/particle"] =
      benchmark::Counter(static_cast<double>(particles), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void white_noise_draws(benchmark::State& bs) {
  const RandomStream rng(kSeed, 1);
  std::uint64_t step = 0, particles = 0;
  for (auto _ : bs) {
    double sink = 0.0;
    for (std::uint64_t k = 0; k < static_cast<std::uint64_t>(kParticles); ++k) {
      const RandomBlock r = rng.block(RngPurpose::white_noise_kick, 0, step, k);
      double x, y, z, unused;
      standard_normal_pair(uniform_open(r[0]), uniform_open(r[1]), x, y);
      standard_normal_pair(uniform_open(r[2]), uniform_open(r[3]), z, unused);
      sink += x + y + z;
    }
    benchmark::DoNotOptimize(sink);
    ++step;
    particles += kParticles;
  }
  bs.counters["time/particle"] =
      benchmark::Counter(static_cast<double>(particles), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// ---- the hand-specialised kernel gives the library's bits ---------------------------------------

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

[[noreturn]] void fail(const char* what, std::int64_t n) {
  std::fprintf(stderr,
               "bench_effects: hand_collide and collide_step<HardSphere> differ (%s, N = %lld): the "
               "hand-specialised kernel is not the same computation, so the comparison would be meaningless\n",
               what, static_cast<long long>(n));
  std::abort();
}

/// collide_step<HardSphere> and hand_collide on the same states and seeds give the same bits: a few
/// particles (batches full of shared particles) and 10^5 (a candidate count that is not a multiple of
/// the batch), 3 steps each, from a majorant low on purpose so the update branch runs.
void check_hand_matches_library() {
  struct Case {
    std::int64_t n;
    std::uint64_t candidates;
  };
  for (const Case cs : {Case{50, 5'000}, Case{100'000, 50'011}}) {
    const Scene scene = plain_scene(cs.n);
    const RandomStream rng(kSeed, 7);
    GasState state = maxwellian_state(scene, rng);
    const std::vector<PairCoefficients> pairs = pair_coefficients(scene);
    const perf::HandConstants c = perf::HandConstants::of(kRestitution, 1.0, 1.0, 1.0);
    if (!same_bits(c.rate_prefactor, pairs[0].rate_prefactor) ||
        !same_bits(c.one_plus_alpha, pairs[0].one_plus_alpha) ||
        !same_bits(c.twice_energy_loss, 2.0 * pairs[0].energy_loss))
      fail("pair constants", cs.n);
    AlignedBuffer<perf::HandRecord> hand(state.species[0].size());
    for (std::size_t k = 0; k < hand.size(); ++k) {
      const Vec3 v = state.species[0].velocity(k);
      hand[k] = {v.x, v.y, v.z, 0.0};
    }
    double omega_library = pairs[0].rate_prefactor;  // low: every |g| > 4 updates it
    double omega_hand = omega_library;
    std::uint64_t collisions = 0, updates = 0;
    for (int s = 0; s < 3; ++s, ++state.step) {
      CollisionTally tally;
      collide_step<HardSphere>(state, pairs, {&omega_library, 1}, {&cs.candidates, 1}, rng, {&tally, 1});
      const perf::HandTally t =
          perf::hand_collide(hand.data(), hand.size(), omega_hand, cs.candidates, rng, state.step, c);
      if (t.collisions != tally.collisions) fail("collision count", cs.n);
      if (t.majorant_updates != tally.majorant_updates) fail("majorant updates", cs.n);
      if (!same_bits(t.twice_energy_loss, tally.twice_energy_loss)) fail("energy loss", cs.n);
      if (!same_bits(omega_hand, omega_library)) fail("majorant", cs.n);
      collisions += t.collisions;
      updates += t.majorant_updates;
    }
    for (std::size_t k = 0; k < hand.size(); ++k) {
      const Vec3 v = state.species[0].velocity(k);
      if (!same_bits(v.x, hand[k].x) || !same_bits(v.y, hand[k].y) || !same_bits(v.z, hand[k].z))
        fail("velocities", cs.n);
    }
    if (collisions == 0 || updates == 0) fail("the check exercised no collision or no majorant update", cs.n);
  }
  std::printf(
      "check: hand_collide and collide_step<HardSphere> give bit-identical velocities, majorants and "
      "tallies (N = 50 and 10^5, 3 steps each)\n");
}

// ---- paired ratios: one step of each scene in turn ----------------------------------------------

/// This thread's CPU time in seconds.
double thread_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

/// CPU seconds per candidate of one whole step of g.
double seconds_per_candidate(Gas& g) {
  const std::uint64_t c0 = g.counts().candidates;
  const double t0 = thread_seconds();
  g.step();
  const double t1 = thread_seconds();
  return (t1 - t0) / static_cast<double>(g.counts().candidates - c0);
}

struct PairedRatio {
  double median = std::nan(""), low = std::nan(""), high = std::nan("");
};

/// The ratio of a's time per candidate to b's, `rounds` times, each from one step of a and one of b taken
/// back to back (alternating which goes first), so that both see the same state of the shared host; the
/// median of the rounds with its distribution-free 95 % confidence interval (the order statistics at
/// n/2 -+ 0.98 sqrt(n), from the binomial(n, 1/2) law of the number of rounds below the true median).
/// The Google Benchmark medians above compare repetitions seconds apart, and this host's load drifts by
/// +-10 % over seconds; here the drift cancels within each round.
PairedRatio paired_ratio(Gas& a, Gas& b, int rounds) {
  std::vector<double> r;
  for (int i = 0; i < rounds; ++i) {
    double ta, tb;
    if (i % 2 == 0) {
      ta = seconds_per_candidate(a);
      tb = seconds_per_candidate(b);
    } else {
      tb = seconds_per_candidate(b);
      ta = seconds_per_candidate(a);
    }
    r.push_back(ta / tb);
  }
  std::sort(r.begin(), r.end());
  const double n = static_cast<double>(r.size()), half_width = 0.98 * std::sqrt(n);
  const auto at = [&](double rank1) {  // 1-based rank, clamped to the sample
    return r[static_cast<std::size_t>(std::clamp(rank1, 1.0, n)) - 1];
  };
  return {0.5 * (at(std::floor((n + 1) / 2)) + at(std::ceil((n + 1) / 2))), at(std::floor(n / 2 - half_width)),
          at(std::ceil(n / 2 + 1 + half_width))};
}

// ---- table ---------------------------------------------------------------------------------------

void print_table(const perf::RecordingReporter& rep) {
  const auto v = [&](const char* f, const char* c) { return 1e9 * rep.value(f, "", c); };  // ns
  const auto x = [&](const char* f, const char* c) { return rep.value(f, "", c); };
  const double plain = v("plain", "time/cand");
  const double n = static_cast<double>(kParticles);
  std::printf(
      "\nWhole time steps, hard-sphere cooling state (alpha = %.1f), N = 10^6, ~N/10 candidates per step "
      "(median of the repetitions)\n",
      kRestitution);
  std::printf(
      "| scene | instantiation | ns / candidate | ratio to plain | cand / step | acceptance | ns / collision | "
      "rescales / 1000 steps | extra ns / particle / step |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  for (const SceneBench& b : scene_benches()) {
    const double t = v(b.name, "time/cand");
    if (std::isnan(t)) continue;
    const double per_step = x(b.name, "cand/step"), acc = x(b.name, "acceptance");
    const std::string inst =
        b.scene ? instantiation_name(make_plan(b.scene()), b.scene()) : std::string("perf/hand_specialised_hcs.hpp");
    std::printf("| %s | %s | %.1f | %.3f | %.0f | %.4f | %.0f | %.1f | %+.2f |\n", b.name, inst.c_str(), t, t / plain,
                per_step, acc, t / acc, x(b.name, "rescales/kstep"), (t - plain) * per_step / n);
  }
  const double hand = v("hand_specialised", "time/cand");
  if (!std::isnan(hand) && !std::isnan(plain))
    std::printf("\nplain / hand_specialised = %.3f (target: within 3%%, i.e. <= 1.03)\n", plain / hand);
  if (!std::isnan(plain) && paired_rounds > 0) {
    std::printf(
        "\nPaired: each scene against plain, %d rounds of one step of each back to back (CPU time of this "
        "thread); median ratio and its 95 %% confidence interval\n| scene | ratio to plain | 95 %% CI "
        "|\n|---|---|---|\n",
        paired_rounds);
    const SceneBench& plain_bench = scene_benches().front();
    for (const SceneBench& b : scene_benches()) {
      if (&b == &plain_bench || std::isnan(v(b.name, "time/cand"))) continue;
      const PairedRatio r = paired_ratio(gas(b), gas(plain_bench), paired_rounds);
      std::printf("| %s | %.3f | [%.3f, %.3f] |\n", b.name, r.median, r.low, r.high);
      if (std::string(b.name) == "hand_specialised")
        std::printf("|   (plain / hand_specialised) | %.3f | [%.3f, %.3f] (target: <= 1.03) |\n", 1.0 / r.median,
                    1.0 / r.high, 1.0 / r.low);
    }
  }
  const double apply = v("white_noise_apply", "time/particle"), draws = v("white_noise_draws", "time/particle");
  const double wn = v("white_noise", "time/cand");
  if (!std::isnan(wn) && !std::isnan(plain) && !std::isnan(apply) && !std::isnan(draws))
    std::printf(
        "white noise in the step: %.2f ns per particle per step more than plain; the effect alone "
        "(WhiteNoise::apply): %.2f ns per particle; its draws alone: %.2f ns per particle\n",
        (wn - plain) * x("white_noise", "cand/step") / n, apply, draws);
}

}  // namespace

int main(int argc, char** argv) {
  // This benchmark's defaults, before the user's flags (which win) and after bench_common's.
  std::vector<char*> args = {argv[0]};
  std::string reps = "--benchmark_repetitions=5", interleave = "--benchmark_enable_random_interleaving=true";
  args.push_back(reps.data());
  args.push_back(interleave.data());
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i], flag = "--paired_rounds=";
    if (a.starts_with(flag))
      paired_rounds = std::atoi(a.c_str() + flag.size());
    else
      args.push_back(argv[i]);
  }
  if (!perf::initialize(static_cast<int>(args.size()), args.data(), "1.0")) return 1;

  check_hand_matches_library();

  for (const SceneBench& b : scene_benches())
    benchmark::RegisterBenchmark(b.name, whole_steps, &b)->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("white_noise_apply", white_noise_apply)->Unit(benchmark::kMillisecond)->MinTime(0.5);
  benchmark::RegisterBenchmark("white_noise_draws", white_noise_draws)->Unit(benchmark::kMillisecond)->MinTime(0.5);

  perf::RecordingReporter reporter(isatty(STDOUT_FILENO) != 0);
  benchmark::RunSpecifiedBenchmarks(&reporter);
  print_table(reporter);
  benchmark::Shutdown();
  return 0;
}
