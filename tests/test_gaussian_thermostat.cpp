// The Gaussian thermostat (000 eqs. 8, 16): exact exponential heating with a fixed zeta, exact
// compensation of the collisional cooling with zeta = "cooling-rate", and the heated steady state (HSS)
// equal to the cooling state (HCS) in scaled variables (000 sec. 2), mixtures included.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "kernel/observe/replica_statistics.hpp"
#include "kernel/setup/run_scene.hpp"
#include "kernel/theory/scene_theory.hpp"

using namespace granmc;

namespace {

Scene gas(double alpha, int replicas, std::int64_t particles) {
  Scene s;
  s.run.seed = 16;
  s.run.replicas = replicas;
  s.run.t_end = 2.0;
  s.run.dt = 0.01;
  s.run.samples = 20;
  s.species.push_back({"a", 1.0, 1.0, 1.0, particles});
  s.collision.restitution = {{{alpha, alpha}, {alpha, alpha}}};
  return s;
}

/// A binary mixture in the spirit of 000 Fig. 3 (mu = m1/m2 = 2, omega = 1, delta = n1/n2 = 2).
Scene mixture(int replicas) {
  Scene s = gas(0.7, replicas, 0);
  s.species = {{"heavy", 2.0, 1.0, 2.0, 20000}, {"light", 1.0, 1.0, 1.0, 10000}};
  s.collision.restitution = {{{0.7, 0.7}, {0.7, 0.7}}};
  return s;
}

/// Per replica, the time average of f(series, k) over samples k >= first; then replica mean and CI.
template <class F>
MeanCI late_average(const RunResult& r, std::size_t first, F f) {
  std::vector<double> v;
  for (const ReplicaSeries& rep : r.replicas) {
    double sum = 0.0;
    for (std::size_t k = first; k < r.times.size(); ++k) sum += f(rep, k);
    v.push_back(sum / static_cast<double>(r.times.size() - first));
  }
  return replica_mean(v);
}

}  // namespace

TEST(GaussianThermostat, FixedZetaHeatsExponentially) {
  Scene s = gas(1.0, 2, 2000);  // elastic: only the thermostat changes T
  s.thermostat.kind = ThermostatKind::gaussian;
  s.thermostat.zeta_is_cooling_rate = false;
  s.thermostat.zeta = 0.7;
  const RunResult r = run_scene(s, {});
  for (const ReplicaSeries& rep : r.replicas)
    for (std::size_t k = 0; k < r.times.size(); ++k)
      EXPECT_NEAR(rep.temperature[k] / rep.temperature[0], std::exp(0.7 * r.times[k]), 1e-12 * std::exp(1.4));
}

TEST(GaussianThermostat, CoolingRateModeHoldsTheTemperature) {
  Scene s = gas(0.5, 2, 2000);
  s.thermostat.kind = ThermostatKind::gaussian;
  const RunResult r = run_scene(s, {});
  for (const ReplicaSeries& rep : r.replicas) {
    EXPECT_GT(rep.collisions.back(), 10000.0);  // it did collide (and would have cooled by a factor ~30)
    for (std::size_t k = 0; k < r.times.size(); ++k) EXPECT_NEAR(rep.temperature[k] / rep.temperature[0], 1.0, 1e-12);
  }
}

TEST(GaussianThermostat, HeatedStateEqualsCoolingStateInScaledVariables) {
  // 000 sec. 2: the Enskog equation of the HSS is that of the HCS in scaled velocities, so the
  // temperature ratio and the cumulants agree. Time averages after 1.5 time units (~30 collisions per
  // particle), replica CIs; the difference of two independent estimates has CI ci_1 + ci_2 at most.
  Scene hcs = mixture(8);
  hcs.run.t_end = 4.0;
  hcs.run.samples = 40;
  Scene hss = hcs;
  hss.thermostat.kind = ThermostatKind::gaussian;
  hss.run.seed = 17;
  const RunResult a = run_scene(hcs, {});
  const RunResult b = run_scene(hss, {});
  const std::size_t first = 15;
  auto ratio = [](const ReplicaSeries& s, std::size_t k) {
    return std::exp(s.species[0].log_temperature[k] - s.species[1].log_temperature[k]);
  };
  const MeanCI ga = late_average(a, first, ratio), gb = late_average(b, first, ratio);
  std::printf("[ measured ] gamma HCS %.4f +- %.4f, HSS %.4f +- %.4f\n", ga.mean, ga.ci, gb.mean, gb.ci);
  EXPECT_NEAR(ga.mean, gb.mean, ga.ci + gb.ci);
  EXPECT_GT(std::fabs(ga.mean - 1.0), 5 * ga.ci);  // non-equipartition is resolved, so the check has teeth
  // Both against the first-Sonine gamma; its model error is taken as the size of its own correction to
  // the Maxwellian gamma (docs/physics.md).
  const auto theory = theory::mixture_state(hss);
  const double model = std::fabs(theory->temperature_ratio_sonine - theory->temperature_ratio_maxwell);
  std::printf("[ measured ] gamma theory: Sonine %.4f, Maxwell %.4f\n", theory->temperature_ratio_sonine,
              theory->temperature_ratio_maxwell);
  EXPECT_NEAR(ga.mean, theory->temperature_ratio_sonine, ga.ci + model);
  EXPECT_NEAR(gb.mean, theory->temperature_ratio_sonine, gb.ci + model);
  for (int i = 0; i < 2; ++i) {
    auto a2 = [i](const ReplicaSeries& s, std::size_t k) { return s.species[i].a2[k]; };
    const MeanCI ca = late_average(a, first, a2), cb = late_average(b, first, a2);
    std::printf("[ measured ] a2_%d HCS %.4f +- %.4f, HSS %.4f +- %.4f\n", i + 1, ca.mean, ca.ci, cb.mean, cb.ci);
    EXPECT_NEAR(ca.mean, cb.mean, ca.ci + cb.ci);
  }
}

TEST(GaussianThermostat, MixtureStateDoesNotDependOnTheTimeStep) {
  // The species pairs' candidates are interleaved within a step (schemes/collision_stage.hpp), so a
  // collision-only step has no splitting error: dt = 0.02 (0.3 collisions per particle per step) gives
  // the temperature ratio of dt = 0.002. Run pair after pair, dt = 0.01 already moved it by 0.01.
  Scene coarse = mixture(8);
  coarse.thermostat.kind = ThermostatKind::gaussian;
  coarse.run.t_end = 3.0;
  coarse.run.samples = 30;
  coarse.run.dt = 0.02;
  Scene fine = coarse;
  fine.run.dt = 0.002;
  fine.run.seed = 18;
  auto ratio = [](const ReplicaSeries& s, std::size_t k) {
    return std::exp(s.species[0].log_temperature[k] - s.species[1].log_temperature[k]);
  };
  const MeanCI a = late_average(run_scene(coarse, {}), 10, ratio);
  const MeanCI b = late_average(run_scene(fine, {}), 10, ratio);
  std::printf("[ measured ] gamma dt = 0.02: %.4f +- %.4f, dt = 0.002: %.4f +- %.4f\n", a.mean, a.ci, b.mean, b.ci);
  EXPECT_NEAR(a.mean, b.mean, a.ci + b.ci);
}
