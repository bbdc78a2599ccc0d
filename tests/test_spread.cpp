// One system over several ranks (schemes/rank_wave_backend.hpp) in one process (SingleRank): the wave-ordered
// stage draws the same candidates from the same words as the one-process stage and, as long as the
// majorant is not raised, makes the same collisions. Only the order of the sums over particles differs
// (per chunk, then over chunks), so the observations agree to rounding: the same chain, hence the same
// law. tests/test_mpi.cpp checks that 2, 3 and 6 ranks give the bits of one.
#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>

#include <gtest/gtest.h>

#include "kernel/collide/hard_sphere.hpp"
#include "kernel/core/ranks.hpp"
#include "kernel/schemes/dsmc.hpp"
#include "kernel/schemes/rank_wave_backend.hpp"
#include "kernel/setup/run_scene.hpp"
#include "tests/test_scenes.hpp"

using namespace granmc;
using granmc::testing::scene_from_toml;

namespace {

/// The scenes of these tests: ${thermostat} is the [thermostat] table, ${storage} run.storage, ${dimension}
/// run.dimension, and ${particles} the number of particles.
constexpr std::string_view cooling_text = R"(
  [run]
  dimension = ${dimension}
  seed = 31
  replicas = 2
  t_end = 10.0  # T falls about 25-fold without the thermostat: several rescalings
  dt = 0.01
  samples = 20
  storage = "${storage}"

  [[species]]
  particles = ${particles}

  [collision]
  restitution = 0.7

  [thermostat]
  ${thermostat}

  [output]
  histogram = { shells = 32, radius = 4.0 }
)";

/// A cooling gas of 10^4 particles with `thermostat` (the lines of its [thermostat] table), spheres or disks.
Scene cooling(std::string_view thermostat, int dimension = 3) {
  return scene_from_toml(
      cooling_text,
      {{"storage", "double"}, {"particles", 10000}, {"thermostat", thermostat}, {"dimension", dimension}});
}

/// `one` receives the one-process run; its first replica makes at least `min_collisions` collisions.
void expect_same_chain(const Scene& s, RunResult& one, double min_collisions = 1e5) {
  ASSERT_TRUE(plan_refusal(s, Spread::particles).empty()) << plan_refusal(s, Spread::particles);
  one = run_scene(s, {});
  const SingleRank single;
  RunOptions spread;
  spread.spread = &single;
  const RunResult waves = run_scene(s, spread);
  ASSERT_EQ(waves.replicas.size(), one.replicas.size());
  for (std::size_t r = 0; r < one.replicas.size(); ++r) {
    const ReplicaSeries &a = one.replicas[r], &b = waves.replicas[r];
    EXPECT_EQ(a.majorant_updates, 0u) << "a raise would make the two stages differ (by design)";
    EXPECT_EQ(b.majorant_updates, 0u);
    EXPECT_EQ(b.candidates, a.candidates);
    EXPECT_EQ(b.collisions, a.collisions) << "the same accepted candidates at every sample";
    EXPECT_EQ(b.rescales, a.rescales);
    EXPECT_EQ(b.species[0].speed_counts, a.species[0].speed_counts);
    for (std::size_t k = 0; k < a.temperature.size(); ++k) {
      EXPECT_NEAR(b.temperature[k] / a.temperature[k], 1.0, 1e-12) << "replica " << r << ", sample " << k;
      EXPECT_NEAR(b.species[0].a2[k], a.species[0].a2[k], 1e-12) << "replica " << r << ", sample " << k;
    }
    const SpeciesSeries &sa = a.species[0], &sb = b.species[0];
    ASSERT_EQ(sb.rotational_temperature.size(), sa.rotational_temperature.size());  // rough particles: spins
    for (std::size_t k = 0; k < sa.rotational_temperature.size(); ++k) {
      EXPECT_NEAR(sb.rotational_temperature[k] / sa.rotational_temperature[k], 1.0, 1e-12) << "sample " << k;
      EXPECT_NEAR(sb.a02[k], sa.a02[k], 1e-12) << "sample " << k;
      EXPECT_NEAR(sb.a11[k], sa.a11[k], 1e-12) << "sample " << k;
    }
    EXPECT_LT(b.energy_residual.value(), 1e-12);
  }
  EXPECT_GT(one.replicas[0].collisions.back(), min_collisions);
}

}  // namespace

TEST(SpreadSystem, CoolingMakesTheCollisionsOfTheOneProcessStage) {
  RunResult one;
  const Scene s = cooling(R"(kind = "none")");
  expect_same_chain(s, one);
  EXPECT_LT(one.replicas[0].temperature.back(), 0.1 * one.replicas[0].temperature.front()) << "the gas cooled";
  EXPECT_GT(one.replicas[0].rescales, 3u);
}

TEST(SpreadSystem, GaussianThermostatMakesTheCollisionsOfTheOneProcessStage) {
  RunResult one;
  const Scene s = cooling(R"(kind = "gaussian")");
  expect_same_chain(s, one);
}

TEST(SpreadSystem, WhiteNoiseMakesTheCollisionsOfTheOneProcessStage) {  // the kicks: the same normals
  const Scene s = cooling(R"(
    kind = "white-noise"
    beta = 2.0  # heats the gas: T rises towards its steady value
  )");
  RunResult one;
  expect_same_chain(s, one);
  EXPECT_GT(one.replicas[0].temperature.back(), 1.5 * one.replicas[0].temperature.front()) << "the noise heated";
}

TEST(SpreadSystem, DisksMakeTheCollisionsOfTheOneProcessStage) {
  // The cooling disks' first replica makes about 6.7 10^4 collisions by t = 10 (the spheres' more than 10^5).
  for (const char* thermostat : {R"(kind = "none")", R"(kind = "white-noise"
                                                         beta = 2.0)"}) {
    RunResult one;
    expect_same_chain(cooling(thermostat, 2), one, 5e4);
  }
}

TEST(SpreadSystem, RoughParticlesMakeTheCollisionsOfTheOneProcessStage) {
  // Rough spheres and disks (beta = 0): a partner's spin travels with its velocity; without a thermostat and
  // under white noise with half its power on the spins (their kicks: the same normals per global index).
  for (int d : {3, 2})
    for (const bool heated : {false, true}) {
      Scene s = cooling(heated ? R"(kind = "white-noise"
                                    beta = 2.0)"
                               : R"(kind = "none")",
                        d);
      s.collision.tangential_restitution = 0.0;
      s.collision.reduced_inertia = d == 3 ? 0.4 : 0.5;
      if (heated) s.thermostat.rotational_share = 0.5;
      SCOPED_TRACE("d = " + std::to_string(d) + (heated ? ", white noise" : ""));
      RunResult one;
      expect_same_chain(s, one, 5e4);
      EXPECT_FALSE(one.replicas[0].species[0].rotational_temperature.empty());
    }
}

TEST(SpreadSystem, RefusesWhatItDoesNotImplement) {
  const Scene s = scene_from_toml(
      cooling_text, {{"storage", "float"}, {"particles", 10000}, {"thermostat", R"(kind = "none")"}, {"dimension", 3}});
  EXPECT_NE(plan_refusal(s, Spread::particles).find("float"), std::string::npos);
  const Scene two = scene_from_toml(
      std::string(cooling_text) + R"(
    [[species]]
    name = "b"
    particles = 10000
  )",
      {{"storage", "double"}, {"particles", 10000}, {"thermostat", R"(kind = "none")"}, {"dimension", 3}});
  EXPECT_NE(plan_refusal(two, Spread::particles).find("two species"), std::string::npos);
  const SingleRank single;
  RunOptions spread;
  spread.spread = &single;
  EXPECT_THROW(run_scene(two, spread), std::invalid_argument);
}

TEST(SpreadSystem, AStepNeedsAHandfulOfWaves) {
  // The cost model of docs/developer-guide/scaling.md: two exchanges per wave. A particle is in about 2C/N of a step's
  // C candidates, so chains of candidates that share particles stay short.
  const Scene s = scene_from_toml(
      cooling_text,
      {{"storage", "double"}, {"particles", 100000}, {"thermostat", R"(kind = "none")"}, {"dimension", 3}});
  const SingleRank single;
  BasicDsmc<RankWaveBackend, double, HardSphere> sim(s, 0, single);
  const double t = 0.5;
  sim.advance_to(t);
  const double steps = t / s.run.dt;
  const double per_step = static_cast<double>(sim.tally().candidates) / steps;
  const double waves = static_cast<double>(sim.backend().waves()) / steps;
  std::printf("[ measured ] %.0f candidates per step (2C/N = %.3f), %.1f waves per step\n", per_step,
              2.0 * per_step / 100000.0, waves);
  EXPECT_GT(waves, 1.0);
  EXPECT_LT(waves, 12.0);
}
