// The tail-exponent fit (kernel/analysis/tail_fit.hpp) on densities of a known law f = v^gamma exp(-v^b / 2)
// with a known scatter: b comes back within its CI, and the CI is what the scatter allows.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "kernel/analysis/tail_fit.hpp"
#include "kernel/core/philox_stream.hpp"
#include "kernel/core/sampling.hpp"
#include "tests/statistical_check.hpp"

using namespace granmc;
using granmc::testing::within_ci;

namespace {

/// 32 replicas of f on 128 shells of width 0.5, each shell's value times exp(sigma z), z standard normal
/// (the scatter of a weighted run's shell: sigma = 0.05 is about 001 Example 7's per replica).
std::vector<std::vector<double>> noisy_law(double gamma, double b, double sigma, std::vector<double>& edges) {
  edges.clear();
  for (int k = 0; k <= 128; ++k) edges.push_back(0.5 * k);
  const RandomStream rng(17, 0);
  std::vector<std::vector<double>> densities(32, std::vector<double>(128));
  for (std::size_t r = 0; r < densities.size(); ++r)
    for (std::size_t k = 0; k < 128; ++k) {
      const double v = 0.5 * (edges[k] + edges[k + 1]);
      const RandomBlock w = rng.block(RngPurpose::initial_velocity, 0, r, k);
      double z, unused;
      standard_normal_pair(uniform_open(w[0]), uniform_open(w[1]), z, unused);
      densities[r][k] = std::pow(v, gamma) * std::exp(-0.5 * std::pow(v, b) + sigma * z);
    }
  return densities;
}

}  // namespace

TEST(TailFit, RecoversTheExponentOfAKnownLawWithItsPrefactor) {
  for (const double b : {1.0, 1.25, 1.5}) {
    SCOPED_TRACE(b);
    std::vector<double> edges;
    const auto densities = noisy_law(-1.0, b, 0.05, edges);
    const auto fit = fit_tail(edges, densities);
    ASSERT_TRUE(fit.has_value());
    // Bound: measured today 0.0003-0.0080 (b = 1.5 to 1) with the scatter 0.05 over 32 replicas; bound 1.5x the
    // largest.
    std::printf("b = %g: fitted %.4f +- %.4f on [%g, %g]\n", b, fit->exponent.mean, fit->exponent.ci, fit->speed_from,
                fit->speed_to);
    EXPECT_TRUE(within_ci("b", fit->exponent, b, 0.012));
    EXPECT_GT(fit->speed_to, 2.0 * fit->speed_from);
    // The profile moves its inner edge outwards and stays on the law.
    const auto profile = tail_exponent_profile(edges, densities);
    ASSERT_GE(profile.size(), 2u);
    for (std::size_t i = 1; i < profile.size(); ++i) EXPECT_GT(profile[i].speed_from, profile[i - 1].speed_from);
    for (const TailWindow& w : profile) EXPECT_LE(std::fabs(w.exponent.mean - b), w.exponent.ci) << w.speed_from;
  }
}

TEST(TailFit, NoFitWithoutATail) {
  std::vector<double> edges{0.0, 1.0, 2.0, 3.0};
  const std::vector<std::vector<double>> densities{{1.0, 0.5, 0.0}, {1.0, 0.4, 0.1}};
  EXPECT_EQ(tail_reach(densities), 2u);
  EXPECT_FALSE(fit_tail(edges, densities).has_value());
  EXPECT_TRUE(tail_exponent_profile(edges, densities).empty());
}
