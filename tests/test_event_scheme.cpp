// The time-step-free white-noise scheme (001 sec. 4) against what is exact:
//  - Maxwell pseudomolecules: the expected bulk-subtracted temperature of n particles is (1 - 1/n) times
//    the Boltzmann relaxation of 001 eqs. (16-17) (docs/physics.md), heating (Example 3) and cooling
//    (Example 4) alike; the 1/n offset is resolved, not hidden in the tolerance;
//  - elastic hard spheres in equilibrium: the real-collision rate is 2 pi rate (n - 1) <|u|>, which
//    checks the thinning of 001 eqs. (25-26);
//  - hard cases: one particle at 1000 times the thermal speed (energy and momentum conserved to rounding
//    when elastic and unheated, the majorant grows without a violation); strong heating with lambda = 1;
//  - the candidates a register at a time: the same bits as one by one.
#include <bit>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "kernel/collide/isotropic_kernels.hpp"
#include "kernel/observe/moments.hpp"
#include "kernel/observe/replica_statistics.hpp"
#include "kernel/schemes/event_white_noise.hpp"
#include "kernel/schemes/initial_state.hpp"
#include "kernel/setup/run_scene.hpp"
#include "kernel/theory/white_noise.hpp"

using namespace granmc;

namespace {

/// 001 Examples 3-5: gamma = 4, C = 1/(4 pi) (rate = 1/pi), alpha = 1/2, Maxwellian at T = 1.
Scene example(CollisionKernel kernel, double beta, std::int64_t particles, int replicas) {
  Scene s;
  s.run.method = Method::event;
  s.run.seed = 5;
  s.run.replicas = replicas;
  s.run.t_end = 8.0;
  s.run.samples = 16;
  s.species.push_back({"a", 1.0, 1.0, 1.0, particles});
  s.collision.kernel = kernel;
  s.collision.lambda = kernel == CollisionKernel::maxwell ? 0.0 : kernel == CollisionKernel::vhs ? 0.5 : 1.0;
  s.collision.rate = 1.0 / std::numbers::pi;
  s.collision.restitution = {{{0.5, 0.5}, {0.5, 0.5}}};
  if (beta > 0.0) {
    s.thermostat.kind = ThermostatKind::white_noise;
    s.thermostat.beta = beta;
  }
  return s;
}

MeanCI at_sample(const RunResult& r, std::size_t k) {
  std::vector<double> v;
  for (const ReplicaSeries& rep : r.replicas) v.push_back(rep.temperature[k]);
  return replica_mean(v);
}

/// T(t_k) / [(1 - 1/n) T_exact(t_k)] = 1 within the CI at every sample, and over the second half of the
/// run the relative deviation from T_exact itself (no 1/n) is -1/n within its CI, which excludes 0.
void check_maxwell_relaxation(const Scene& s) {
  const RunResult r = run_scene(s, {});
  const double n = static_cast<double>(s.species[0].particles);
  const double rate = s.collision.rate, alpha = s.collision.restitution[0][0];
  std::vector<double> late(r.replicas.size(), 0.0);
  const std::size_t first = r.times.size() / 2;
  for (std::size_t k = 0; k < r.times.size(); ++k) {
    const double exact = theory::maxwell_temperature(r.times[k], 1.0, s.thermostat.beta, rate, alpha);
    const MeanCI t = at_sample(r, k);
    EXPECT_NEAR(t.mean, (1.0 - 1.0 / n) * exact, t.ci) << "t = " << r.times[k];
    if (k >= first)
      for (std::size_t q = 0; q < r.replicas.size(); ++q)
        late[q] += (r.replicas[q].temperature[k] / exact - 1.0) / static_cast<double>(r.times.size() - first);
  }
  const MeanCI offset = replica_mean(late);
  EXPECT_NEAR(offset.mean, -1.0 / n, offset.ci);
  EXPECT_LT(offset.ci, 1.0 / n) << "the run cannot resolve the 1/n offset";
  std::printf("n = %g: late relative deviation %.5f +- %.5f (-1/n = %.5f)\n", n, offset.mean, offset.ci, -1.0 / n);
}

}  // namespace

TEST(EventScheme, MaxwellHeatingIsExactExample3) {
  check_maxwell_relaxation(example(CollisionKernel::maxwell, 1.0, 64, 2000));
}

TEST(EventScheme, MaxwellHeatingIsExactWithFloatStorage) {  // run.storage = "float": 16-byte particles
  Scene s = example(CollisionKernel::maxwell, 1.0, 64, 2000);
  s.run.storage = Storage::single_precision;
  check_maxwell_relaxation(s);
}

TEST(EventScheme, MaxwellCoolingIsExactExample4) {
  check_maxwell_relaxation(example(CollisionKernel::maxwell, 0.125, 64, 2000));
}

TEST(EventScheme, MaxwellWithoutNoiseCoolsExponentially) {
  check_maxwell_relaxation(example(CollisionKernel::maxwell, 0.0, 32, 4000));
}

TEST(EventScheme, ElasticHardSphereCollisionRateIsExact) {
  Scene s = example(CollisionKernel::hard_sphere, 0.0, 20000, 32);
  s.collision.restitution = {{{1.0, 1.0}, {1.0, 1.0}}};
  s.run.t_end = 1.0;
  s.run.samples = 5;
  const RunResult r = run_scene(s, {});
  // Equilibrium at T = (1 - 1/n) (zero total momentum): real collisions per unit time
  // 1/2 sum_{i != j} (4 pi rate / n) <|u|> = 2 pi rate (n - 1) <|u|>.
  const double n = static_cast<double>(s.species[0].particles);
  const double mean_speed = theory::maxwellian_relative_speed_moment(1.0, 1.0 - 1.0 / n);
  const double expected = 2.0 * std::numbers::pi * s.collision.rate * (n - 1.0) * mean_speed * s.run.t_end;
  std::vector<double> ratio;
  for (const ReplicaSeries& rep : r.replicas) {
    ratio.push_back(rep.collisions.back() / expected);
    EXPECT_EQ(rep.majorant_violations, 0u);
  }
  const MeanCI m = replica_mean(ratio);
  EXPECT_NEAR(m.mean, 1.0, m.ci);
  std::printf("collisions / (2 pi rate (n-1) <|u|> t) = %.5f +- %.5f\n", m.mean, m.ci);
}

TEST(EventScheme, ElasticCollisionRatesAreExactInBothSchemes) {
  // Elastic, no noise: real collisions per unit time 2 pi rate (n - 1) <|u|^lambda>, for the event scheme
  // (001 eqs. 25-26) and for the time-stepped one in the 001 form (prefactor 16 pi rate, N - 1
  // candidates): VHS lambda = 1/2 and hard spheres.
  for (auto [kernel, method] :
       {std::pair{CollisionKernel::vhs, Method::event}, std::pair{CollisionKernel::vhs, Method::dsmc},
        std::pair{CollisionKernel::hard_sphere, Method::dsmc}}) {
    Scene s = example(kernel, 0.0, 20000, 32);
    s.run.method = method;
    s.run.dt = 0.02;
    s.collision.restitution = {{{1.0, 1.0}, {1.0, 1.0}}};
    s.run.t_end = 1.0;
    s.run.samples = 5;
    const RunResult r = run_scene(s, {});
    const double n = static_cast<double>(s.species[0].particles);
    const double mean = theory::maxwellian_relative_speed_moment(s.collision.lambda, 1.0 - 1.0 / n);
    const double expected = 2.0 * std::numbers::pi * s.collision.rate * (n - 1.0) * mean * s.run.t_end;
    std::vector<double> ratio;
    for (const ReplicaSeries& rep : r.replicas) ratio.push_back(rep.collisions.back() / expected);
    const MeanCI m = replica_mean(ratio);
    EXPECT_NEAR(m.mean, 1.0, m.ci) << method_name(method) << ", lambda = " << s.collision.lambda;
    std::printf("%s, lambda = %g: collisions / (2 pi rate (n-1) <|u|^lambda> t) = %.5f +- %.5f\n", method_name(method),
                s.collision.lambda, m.mean, m.ci);
  }
}

TEST(EventScheme, FastParticleConservesEnergyAndGrowsTheMajorant) {
  Scene s = example(CollisionKernel::hard_sphere, 0.0, 10000, 1);
  s.collision.restitution = {{{1.0, 1.0}, {1.0, 1.0}}};
  s.run.t_end = 0.2;
  GasState initial = maxwellian_state(s, RandomStream(s.run.seed, 0));
  SpeciesStore& store = initial.species[0];
  store.set_velocity(0, store.velocity(0) + Vec3{1000.0, 0.0, 0.0});  // 1000 thermal speeds
  const SpeciesMoments before = species_moments(store);
  EventWhiteNoise<IsotropicHardSphereKernel> sim(s, 0, {}, initial);
  const double majorant0 = sim.majorant();
  for (double t : {0.01, 0.1, 0.2}) sim.advance_to(t);
  const SpeciesMoments after = species_moments(sim.state().species[0]);
  EXPECT_NEAR(after.sum_c2 / before.sum_c2, 1.0, 1e-12);
  EXPECT_NEAR(after.sum_c.x, before.sum_c.x, 1e-9 * 1000.0);
  EXPECT_EQ(sim.tally().majorant_violations, 0u);
  EXPECT_GT(sim.tally().collisions, 0u);
  // The fast particle has shared its energy: the majorant, reset at each sample time to 2 max |v - V|,
  // has fallen far below its start (2000 thermal speeds).
  EXPECT_LT(sim.majorant(), 0.5 * majorant0);
}

TEST(EventScheme, StrongHeatingOfHardSpheresStaysFiniteWithoutViolations) {
  Scene s = example(CollisionKernel::hard_sphere, 30.0, 5000, 2);  // 001 Example 8's heating, alpha = 0.1
  s.collision.rate = 16.0 / (4.0 * std::numbers::pi);
  s.collision.restitution = {{{0.1, 0.1}, {0.1, 0.1}}};
  s.run.t_end = 0.25;
  s.run.samples = 5;
  const RunResult r = run_scene(s, {});
  for (const ReplicaSeries& rep : r.replicas) {
    EXPECT_EQ(rep.majorant_violations, 0u);
    EXPECT_GT(rep.majorant_updates, 0u) << "the heating should raise U_max between samples";
    for (double t : rep.temperature) EXPECT_TRUE(std::isfinite(t));
    // Momentum: the noise moves the bulk velocity as a random walk of variance 6 beta t / n per
    // particle mass (001 Remark 1); 6 standard deviations.
    const Vec3 p = rep.momentum.back();
    const double n = static_cast<double>(s.species[0].particles);
    EXPECT_LT(norm(p) / n, 6.0 * std::sqrt(6.0 * 30.0 * s.run.t_end / n));
  }
}

TEST(EventScheme, ThinningOnSquaresGivesTheOutcomesOfTheRatio) {
  // thinning() against the paper's test on the rounded ratio |u| / U_max: random candidates, and candidates
  // within a few hundred ulp of both boundaries (threshold U_max and U_max), where the squares cannot
  // decide and the ratio must be computed.
  auto by_ratio = [](double g2, double threshold, double majorant) {
    const double ratio = std::sqrt(g2) / majorant;
    if (ratio > 1.0) return Thinning::violation;
    return threshold < ratio ? Thinning::real : Thinning::fictitious;
  };
  const RandomStream rng(77, 0);
  std::size_t near = 0;
  for (std::uint64_t n = 0; n < 400000; ++n) {
    const RandomBlock r = rng.block(RngPurpose::initial_velocity, 0, 0, n);
    const double majorant = std::ldexp(uniform_open(r[0]), static_cast<int>(r[1] % 21) - 10);
    const double threshold = uniform_open(r[2]);
    const double edge = (n % 3 == 0 ? threshold * majorant : majorant);
    const double g = n % 3 == 2 ? 1.3 * majorant * uniform_open(r[3])
                                : edge * (1.0 + (static_cast<double>(r[3] % 801) - 400.0) * 0x1p-52);
    const double g2 = g * g;
    if (n % 3 != 2) ++near;
    ASSERT_EQ(thinning(g2, threshold, majorant, majorant * majorant), by_ratio(g2, threshold, majorant))
        << n << " " << g2 << " " << threshold << " " << majorant;
  }
  EXPECT_GT(near, 250000u);
}

namespace {

template <class Real>
void expect_same_store(const BasicSpeciesStore<Real>& a, const BasicSpeciesStore<Real>& b, double t) {
  for (std::size_t k = 0; k < a.size(); ++k) {
    const Vec3 va = a.velocity(k), vb = b.velocity(k);
    ASSERT_EQ(std::bit_cast<std::uint64_t>(va.x), std::bit_cast<std::uint64_t>(vb.x))
        << "particle " << k << " at t = " << t;
    ASSERT_EQ(std::bit_cast<std::uint64_t>(va.y), std::bit_cast<std::uint64_t>(vb.y))
        << "particle " << k << " at t = " << t;
    ASSERT_EQ(std::bit_cast<std::uint64_t>(va.z), std::bit_cast<std::uint64_t>(vb.z))
        << "particle " << k << " at t = " << t;
    ASSERT_EQ(std::bit_cast<std::uint64_t>(a.last_update(k)), std::bit_cast<std::uint64_t>(b.last_update(k)));
  }
}

/// The scheme with candidates in registers and one by one from the same start, to the same sample times:
/// every particle and every count the same bits.
template <class Real, class Kernel>
void expect_registers_match_one_by_one(const Scene& s, Kernel kernel, bool fast_particle) {
  BasicGasState<Real> initial = maxwellian_state<Real>(s, RandomStream(s.run.seed, 0));
  if (fast_particle) {  // 30 thermal speeds: U_max is raised and falls back, the registers stop at raises
    BasicSpeciesStore<Real>& store = initial.species[0];
    store.set_velocity(0, store.velocity(0) + Vec3{30.0, 0.0, 0.0});
  }
  BasicEventWhiteNoise<Real, Kernel, true> registers(s, 0, kernel, initial);
  BasicEventWhiteNoise<Real, Kernel, false> one_by_one(s, 0, kernel, initial);
  for (int k = 1; k <= s.run.samples; ++k) {
    const double t = s.run.t_end * k / s.run.samples;
    registers.advance_to(t);
    one_by_one.advance_to(t);
    expect_same_store(registers.state().species[0], one_by_one.state().species[0], t);
  }
  const EventTally &a = registers.tally(), &b = one_by_one.tally();
  EXPECT_GT(a.candidates, 1000u);
  EXPECT_EQ(a.candidates, b.candidates);
  EXPECT_EQ(a.collisions, b.collisions);
  EXPECT_EQ(a.majorant_updates, b.majorant_updates);
  EXPECT_EQ(a.majorant_violations, b.majorant_violations);
  if (fast_particle) {
    EXPECT_GT(a.majorant_updates, 0u);
  }
}

template <class Real>
void expect_registers_match_one_by_one_for_each_kernel() {
  for (const std::int64_t n : {64, 3000}) {  // with 64 particles a register's pairs often share one
    for (const bool fast : {false, true}) {
      Scene s = example(CollisionKernel::hard_sphere, 30.0, n, 1);  // 001 Examples 8-9's heating
      s.collision.rate = 16.0 / (4.0 * std::numbers::pi);
      s.collision.restitution = {{{0.1, 0.1}, {0.1, 0.1}}};
      s.run.t_end = n == 64 ? 2.0 : 0.1;
      s.run.samples = 4;
      SCOPED_TRACE("n = " + std::to_string(n) + (fast ? ", a fast particle" : ""));
      expect_registers_match_one_by_one<Real>(s, IsotropicHardSphereKernel{}, fast);
      expect_registers_match_one_by_one<Real>(s, VhsKernel{0.5}, fast);
      expect_registers_match_one_by_one<Real>(s, VhsKernel{0.3}, fast);
    }
  }
}

}  // namespace

TEST(EventScheme, CandidatesInRegistersAreTheSameBitsAsOneByOne) {
  expect_registers_match_one_by_one_for_each_kernel<double>();
}

TEST(EventScheme, CandidatesInRegistersAreTheSameBitsAsOneByOneWithFloatStorage) {
  expect_registers_match_one_by_one_for_each_kernel<float>();
}
