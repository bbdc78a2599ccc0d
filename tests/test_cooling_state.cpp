// The homogeneous cooling state of monodisperse inelastic hard spheres and hard disks (alpha = 0.8) against
// theory: Haff's law with the first-Sonine cooling rate, and the Sonine a2, in d = 3 and d = 2. Tolerance:
// the replica confidence half-width (001 eq. 31) plus the documented model error of the theory
// (docs/methods/physics.md, "Model error of the Sonine predictions"). The sphere scene with float storage
// (run.storage) cools as the double one does: the paired difference of each replica (same seed) is zero
// within its CI.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <string_view>

#include <gtest/gtest.h>

#include "kernel/analysis/replica_statistics.hpp"
#include "kernel/setup/run_scene.hpp"
#include "kernel/theory/scene_theory.hpp"
#include "tests/statistical_check.hpp"
#include "tests/test_scenes.hpp"

using namespace granmc;
using granmc::testing::expected_ci_bound;
using granmc::testing::scene_from_toml;
using granmc::testing::within_ci;

namespace {

/// `storage` is run.storage: "double" or "float"; `dimension` 3 (spheres) or 2 (disks).
Scene cooling_scene(const char* storage, int dimension = 3) {
  constexpr std::string_view text = R"(
    [run]
    seed = 8
    replicas = 16
    t_end = 20.0  # T falls about 100-fold (spheres; 50-fold for disks), 70 (30) collisions per particle
    dt = 0.01
    samples = 40
    storage = "${storage}"
    dimension = ${dimension}

    [[species]]
    particles = 50000

    [collision]
    restitution = 0.8
  )";
  return scene_from_toml(text, {{"storage", storage}, {"dimension", dimension}});
}

/// Per replica, the time average of value(species, k) once the scaled state is stationary (t >= 5: about
/// 20 collisions per particle for spheres, 10 for disks, while a2 and a3 relax within a few); then the
/// replica mean and its CI.
template <class Value>
MeanCI stationary_average(const RunResult& r, Value value) {
  std::vector<double> per_replica;
  for (const ReplicaSeries& rep : r.replicas) {
    double sum = 0.0;
    int count = 0;
    for (std::size_t k = 0; k < r.times.size(); ++k)
      if (r.times[k] >= 5.0) {
        sum += value(rep.species[0], k);
        ++count;
      }
    per_replica.push_back(sum / count);
  }
  return replica_mean(per_replica);
}

struct CoolingRun {
  Scene scene;
  RunResult result;
  theory::CoolingStatePrediction theory;
};

/// The double-storage run in `dimension`, run once for every test that reads it.
const CoolingRun& cooling_run(int dimension) {
  static std::map<int, std::unique_ptr<CoolingRun>> runs;
  std::unique_ptr<CoolingRun>& run = runs[dimension];
  if (!run) {
    Scene scene = cooling_scene("double", dimension);
    RunResult result = run_scene(scene, {});
    theory::CoolingStatePrediction theory = *theory::cooling_state(scene, result.times);
    run = std::make_unique<CoolingRun>(CoolingRun{std::move(scene), std::move(result), std::move(theory)});
  }
  return *run;
}

class CoolingState : public ::testing::TestWithParam<int> {};

}  // namespace

INSTANTIATE_TEST_SUITE_P(SpheresAndDisks, CoolingState, ::testing::Values(3, 2),
                         [](const ::testing::TestParamInfo<int>& p) { return p.param == 3 ? "Spheres" : "Disks"; });

TEST_P(CoolingState, HaffLawWithinConfidenceAndSonineError) {
  const CoolingRun& c = cooling_run(GetParam());
  // A relative error delta of the cooling rate moves T(t) by at most 2 delta x / (1 + x), x = zeta0 t / 2
  // (docs/methods/physics.md); delta bounds the start from a Maxwellian and the Sonine truncation.
  const double delta = c.theory.cooling_rate_model_error;
  for (std::size_t k = 0; k < c.result.times.size(); ++k) {
    std::vector<double> ratio;
    for (const ReplicaSeries& rep : c.result.replicas) ratio.push_back(rep.temperature[k] / c.theory.temperature[k]);
    const MeanCI m = replica_mean(ratio);
    const double x = 0.5 * c.theory.cooling_rate0 * c.result.times[k];
    const double model = 2.0 * delta * x / (1.0 + x);
    // Bound: spheres, measured today 0.0015 to 0.0035 over the 41 samples (0.0029 expected at t = 0, from the
    // relative standard error sqrt(2 / (d N)) of a Maxwellian temperature); bound 1.5x the largest, scaled by
    // sqrt(3 / d) for disks.
    EXPECT_TRUE(within_ci("T / T_Haff", m, 1.0, 0.0052 * std::sqrt(3.0 / GetParam()), model))
        << "t = " << c.result.times[k];
  }
  // Sharp enough to fail: T fell 50-fold (disks) to 100-fold (spheres), and a 1% error in zeta would move
  // T(t_end) by about 1.8%.
  const double final_ratio = c.result.replicas[0].temperature.back() / c.result.replicas[0].temperature.front();
  EXPECT_LT(final_ratio, 0.03);
}

TEST_P(CoolingState, A3IsZeroForTheMaxwellianStartAndNegativeInTheCoolingState) {
  const CoolingRun& c = cooling_run(GetParam());
  std::vector<double> start;
  for (const ReplicaSeries& rep : c.result.replicas) start.push_back(rep.species[0].a3.front());
  const MeanCI s = replica_mean(start);
  const MeanCI l = stationary_average(c.result, [](const SpeciesSeries& sp, std::size_t k) { return sp.a3[k]; });
  std::printf("[ measured ] d = %d: a3 at t = 0: %.5f +- %.5f; stationary %.5f +- %.5f (second Sonine %.5f)\n",
              GetParam(), s.mean, s.ci, l.mean, l.ci, c.theory.a3_second_sonine);
  // A Maxwellian start has a3 = 0. Bound: a3 = 1 + 3 a2 - d^2/((d+2)(d+4)) <c^6> / <c^2>^3 from N Maxwellian
  // particles has the standard deviation sqrt(16 / (35 N)) for spheres, sqrt(1 / N) for disks (delta method
  // with the moments of c^2, a Gamma(d/2) variable; spheres measured today 1.04x that).
  const double n = static_cast<double>(c.scene.species[0].particles);
  const double variance = GetParam() == 3 ? 16.0 / 35.0 : 1.0;
  EXPECT_TRUE(within_ci("a3 at t = 0", s, 0.0, expected_ci_bound(std::sqrt(variance / n), c.scene.run.replicas)));
  EXPECT_LT(l.mean + l.ci, 0.0);  // a3 < 0 at alpha = 0.8, as the second-Sonine theory says
}

TEST_P(CoolingState, A2MatchesSonineWithinConfidenceAndModelError) {
  const CoolingRun& c = cooling_run(GetParam());
  const MeanCI m = stationary_average(c.result, [](const SpeciesSeries& sp, std::size_t k) { return sp.a2[k]; });
  std::printf("[ measured ] d = %d: a2 = %.5f +- %.5f (first Sonine %.5f, model error %.5f; second Sonine %.5f)\n",
              GetParam(), m.mean, m.ci, c.theory.a2, c.theory.a2_model_error, c.theory.a2_second_sonine);
  // Bound 0.5 |a2|: the CI resolves a2 from zero (spheres: measured today 0.0011, 0.17 of the bound).
  EXPECT_TRUE(within_ci("stationary a2", m, c.theory.a2, 0.5 * std::fabs(c.theory.a2), c.theory.a2_model_error));
  EXPECT_LT(m.mean + m.ci, 0.0);  // negative at alpha = 0.8, as theory says
}

TEST(CoolingStateStorage, FloatStorageCoolsAsDoubleDoes) {
  const RunResult& spheres = cooling_run(3).result;
  // Same seeds, so the two runs share every random number: they differ only where float rounding first
  // flips an acceptance, and the paired difference resolves a storage bias far below the unpaired CI.
  const RunResult f = run_scene(cooling_scene("float"), {});
  ASSERT_EQ(f.replicas.size(), spheres.replicas.size());
  auto late_mean = [&](const ReplicaSeries& rep, auto value) {
    double sum = 0.0;
    int count = 0;
    for (std::size_t k = 0; k < spheres.times.size(); ++k)
      if (spheres.times[k] >= 5.0) {
        sum += value(rep, k);
        ++count;
      }
    return sum / count;
  };
  auto log_t = [](const ReplicaSeries& rep, std::size_t k) { return rep.log_temperature[k]; };
  auto a2 = [](const ReplicaSeries& rep, std::size_t k) { return rep.species[0].a2[k]; };
  std::vector<double> d_log_t, d_a2;
  for (std::size_t q = 0; q < f.replicas.size(); ++q) {
    d_log_t.push_back(late_mean(f.replicas[q], log_t) - late_mean(spheres.replicas[q], log_t));
    d_a2.push_back(late_mean(f.replicas[q], a2) - late_mean(spheres.replicas[q], a2));
  }
  const MeanCI t = replica_mean(d_log_t), a = replica_mean(d_a2);
  std::printf("[ measured ] float - double, t >= 5: ln T %.2e +- %.2e, a2 %.2e +- %.2e\n", t.mean, t.ci, a.mean, a.ci);
  // Bounds: measured today 9.8e-4 (ln T) and 6.7e-4 (a2); bounds 1.5x.
  EXPECT_TRUE(within_ci("ln T, float - double", t, 0.0, 1.5e-3));
  EXPECT_TRUE(within_ci("a2, float - double", a, 0.0, 1.0e-3));
  // The runs did diverge (the test compares two realizations, not one): rounding is not invisible.
  EXPECT_GT(t.ci, 0.0);
  for (const ReplicaSeries& rep : f.replicas)
    for (double e : rep.temperature) ASSERT_TRUE(std::isfinite(e));
}
