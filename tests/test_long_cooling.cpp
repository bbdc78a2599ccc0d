// A cooling run in which T falls by more than 40 decades still gives the right a2: the stored
// velocities are rescaled and the centre-of-mass velocity removed as the gas cools (docs/methods/physics.md,
// "Scaled velocities: cooling over any number of decades"), so the scaled state late in the run is the same homogeneous
// cooling state as early in the run.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "kernel/analysis/replica_statistics.hpp"
#include "kernel/setup/run_scene.hpp"
#include "kernel/theory/scene_theory.hpp"
#include "tests/statistical_check.hpp"
#include "tests/test_scenes.hpp"

using namespace granmc;
using granmc::testing::scene_from_toml;
using granmc::testing::within_ci;

namespace {

Scene long_cooling_scene() {
  return scene_from_toml(R"(
    [run]
    seed = 31
    replicas = 8
    t_end = 1e21  # Haff: T(t_end) / T(0) ~ 1e-41 (a cooling run over 40 decades)
    dt = 0.02     # about 0.14 mean free times, kept so by the thermal scaling
    dt_scaling = "thermal"
    samples = 80
    sample_spacing = "log"

    [[species]]
    particles = 4000

    [collision]
    restitution = 0.5
  )");
}

/// Per replica, the time average of a2 over the samples with log10(T(0) / T) in [lo, hi].
std::vector<double> a2_between_decades(const RunResult& r, double lo, double hi) {
  std::vector<double> out;
  for (const ReplicaSeries& rep : r.replicas) {
    double sum = 0.0;
    int count = 0;
    for (std::size_t k = 0; k < r.times.size(); ++k) {
      const double decades = (rep.log_temperature.front() - rep.log_temperature[k]) / std::log(10.0);
      if (decades >= lo && decades <= hi) {
        sum += rep.species[0].a2[k];
        ++count;
      }
    }
    EXPECT_GE(count, 5) << "too few samples between " << lo << " and " << hi << " decades";
    out.push_back(sum / count);
  }
  return out;
}

class LongCooling : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { result_ = new RunResult(run_scene(long_cooling_scene(), {})); }
  static void TearDownTestSuite() { delete result_; }
  static RunResult* result_;
};
RunResult* LongCooling::result_ = nullptr;

}  // namespace

TEST_F(LongCooling, TemperatureFallsMoreThanFortyDecadesAndStaysFinite) {
  for (const ReplicaSeries& rep : result_->replicas) {
    const double decades = (rep.log_temperature.front() - rep.log_temperature.back()) / std::log(10.0);
    EXPECT_GT(decades, 40.0);
    EXPECT_GT(rep.rescales, 100u);
    for (std::size_t k = 0; k < result_->times.size(); ++k) {
      ASSERT_TRUE(std::isfinite(rep.log_temperature[k]));
      ASSERT_TRUE(std::isfinite(rep.species[0].a2[k]));
      ASSERT_GT(rep.temperature[k], 0.0);  // 1e-33 is still a normal double
      if (k > 0) {
        ASSERT_LT(rep.log_temperature[k], rep.log_temperature[k - 1]);
      }
      // Centre-of-mass speed relative to the rms speed: rounding only (removed at each rescaling).
      ASSERT_LT(rep.momentum_relative[k], 1e-12);
    }
    // The steps' energy bookkeeping against a direct sum (docs/methods/physics.md, "Energy balance").
    ASSERT_TRUE(rep.energy_residual.has_value());
    EXPECT_LT(*rep.energy_residual, energy_balance_tolerance);
    std::printf("[ measured ] energy residual %.2g\n", *rep.energy_residual);
  }
}

TEST_F(LongCooling, LateScaledStateEqualsEarlyScaledState) {
  const std::vector<double> early = a2_between_decades(*result_, 2.0, 6.0);
  const std::vector<double> late = a2_between_decades(*result_, 35.0, 40.0);
  std::vector<double> difference;
  for (std::size_t r = 0; r < early.size(); ++r) difference.push_back(late[r] - early[r]);
  const MeanCI d = replica_mean(difference);
  const MeanCI early_a2 = replica_mean(early);
  std::printf(
      "[ measured ] a2 after 2-6 decades %.4f +- %.4f, after 35-40 decades %.4f +- %.4f, difference %.4f +- %.4f\n",
      early_a2.mean, early_a2.ci, replica_mean(late).mean, replica_mean(late).ci, d.mean, d.ci);
  // Bound: measured today 0.0077; bound 1.5x.
  EXPECT_TRUE(within_ci("a2 late - a2 early", d, 0.0, 0.0115));
  const MeanCI late_a2 = replica_mean(late);
  // And it is the HCS a2 of theory (first Sonine, with its documented model error). Bound 0.02: the comparison
  // can see a change of the order of a2 itself (measured today 0.0041).
  const auto hcs = theory::cooling_state(long_cooling_scene(), result_->times);
  EXPECT_TRUE(within_ci("a2 after 35-40 decades", late_a2, hcs->a2, 0.02, hcs->a2_model_error));
}
