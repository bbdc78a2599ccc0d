// Hard cases of the time-stepped scheme stay numerically stable: mass ratios
// 1e-3 and 1e3, alpha = 0, packing fraction 0.5. Each runs to the end with finite results, total momentum
// conserved to rounding, and majorants that stay bounded.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string_view>

#include <gtest/gtest.h>

#include "kernel/setup/run_scene.hpp"
#include "tests/test_scenes.hpp"

using namespace granmc;
using granmc::testing::scene_from_toml;

namespace {

Scene hard_case(double mass_ratio, double alpha, double phi, bool heated) {
  constexpr std::string_view text = R"(
    [run]
    seed = 5
    replicas = 2
    t_end = 1.0
    dt = 0.005
    samples = 10

    [[species]]
    name = "1"
    mass = ${mass_ratio}
    particles = 4000

    [[species]]
    name = "2"
    particles = 4000

    [collision]
    restitution = ${alpha}
    packing_fraction = ${phi}

    [thermostat]
    kind = "${kind}"
  )";
  return scene_from_toml(
      text, {{"mass_ratio", mass_ratio}, {"alpha", alpha}, {"phi", phi}, {"kind", heated ? "gaussian" : "none"}});
}

void expect_stable(const Scene& scene, const char* what) {
  const RunResult r = run_scene(scene, {});
  for (const ReplicaSeries& rep : r.replicas) {
    EXPECT_GT(rep.collisions.back(), 1000.0) << what;
    for (std::size_t k = 0; k < r.times.size(); ++k) {
      for (const SpeciesSeries& sp : rep.species) {
        ASSERT_TRUE(std::isfinite(sp.log_temperature[k])) << what;
        ASSERT_TRUE(std::isfinite(sp.a2[k])) << what;
        ASSERT_GT(sp.temperature[k], 0.0) << what;
      }
      // Centre-of-mass speed over rms speed: rounding only (about 1e-16 sqrt(collisions)).
      ASSERT_LT(rep.momentum_relative[k], 1e-12) << what << " at t = " << r.times[k];
    }
    // The steps' energy bookkeeping against a direct sum (docs/methods/physics.md, "Energy balance").
    ASSERT_TRUE(rep.energy_residual.has_value()) << what;
    EXPECT_LT(*rep.energy_residual, energy_balance_tolerance) << what;
    // The majorant is an estimate that grows when exceeded (000 sec. 3); in these states it must not run
    // away (it is held in units of the thermal speed).
    for (double growth : rep.majorant_growth) EXPECT_LT(growth, 4.0) << what;
    std::printf(
        "[ measured ] %s: %g collisions, %lu majorant updates, largest growth %.3f, |P| rel %.2g, "
        "energy residual %.2g\n",
        what, rep.collisions.back(), static_cast<unsigned long>(rep.majorant_updates),
        *std::max_element(rep.majorant_growth.begin(), rep.majorant_growth.end()), rep.momentum_relative.back(),
        *rep.energy_residual);
  }
}

}  // namespace

TEST(MixtureStability, MassRatioOneThousand) { expect_stable(hard_case(1e3, 0.5, 0.0, true), "m1/m2 = 1e3"); }

TEST(MixtureStability, MassRatioOneThousandth) { expect_stable(hard_case(1e-3, 0.5, 0.0, true), "m1/m2 = 1e-3"); }

TEST(MixtureStability, PerfectlyInelastic) { expect_stable(hard_case(2.0, 0.0, 0.0, false), "alpha = 0, cooling"); }

TEST(MixtureStability, PerfectlyInelasticHeated) { expect_stable(hard_case(2.0, 0.0, 0.0, true), "alpha = 0, heated"); }

TEST(MixtureStability, PackingFractionOneHalf) { expect_stable(hard_case(2.0, 0.7, 0.5, true), "phi = 0.5"); }
