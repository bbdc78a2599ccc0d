// The tests' own helpers: scene_from_toml (tests/test_scenes.hpp) writes numbers that read back as the same
// value and refuses a placeholder without a value; within_ci (tests/statistical_check.hpp) fails outside the CI
// and when the CI exceeds its bound, and says which.
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "tests/statistical_check.hpp"
#include "tests/test_scenes.hpp"

using namespace granmc;
using granmc::testing::expected_ci_bound;
using granmc::testing::fill_toml;
using granmc::testing::scene_from_toml;
using granmc::testing::TomlValue;
using granmc::testing::within_ci;

TEST(TestScenes, NumbersReadBackAsTheSameDouble) {
  const double values[] = {1.0 / std::numbers::pi,
                           16.0 / (4.0 * std::numbers::pi),
                           6.0 * 0.2 / std::numbers::pi,
                           0.5 / 0.8,
                           1e21,
                           1e-14,
                           0.1,
                           20000.0,
                           std::nextafter(1.0, 2.0)};
  for (const double v : values) {
    const Scene s = scene_from_toml("[run]\nt_end = ${v}\ndt = 1e-300\n[[species]]\nparticles = 1\n", {{"v", v}});
    EXPECT_EQ(s.run.t_end, v) << TomlValue(v).text();
  }
  EXPECT_EQ(TomlValue(20000.0).text(), "20000.0");  // a float in TOML, not an integer
  EXPECT_EQ(TomlValue(std::int64_t{20000}).text(), "20000");
  EXPECT_EQ(TomlValue(true).text(), "true");
}

TEST(TestScenes, EveryPlaceholderNeedsAValueAndEveryValueAPlaceholder) {
  EXPECT_EQ(fill_toml("a = ${x}\nb = \"${y}\"\n", {{"x", 2}, {"y", "z"}}), "a = 2\nb = \"z\"\n");
  EXPECT_THROW(fill_toml("a = ${x}\n", {}), std::invalid_argument);
  EXPECT_THROW(fill_toml("a = 1\n", {{"x", 2}}), std::invalid_argument);
  EXPECT_THROW(fill_toml("a = ${x\n", {{"x", 2}}), std::invalid_argument);
}

TEST(TestScenes, TheParserChecksTheScene) {
  try {
    scene_from_toml("[run]\nt_end = 1.0\ndt = 0.1\ntypo = 1\n[[species]]\nparticles = 1\n");
    ADD_FAILURE() << "an unknown key must be refused";
  } catch (const SceneError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("test_helpers.cpp:"), std::string::npos) << what;  // the path names the test
    EXPECT_NE(what.find("TestScenes.TheParserChecksTheScene"), std::string::npos) << what;
    EXPECT_NE(what.find("run.typo"), std::string::npos) << what;
  }
}

TEST(StatisticalCheck, FailsOutsideTheIntervalAndAboveTheBound) {
  EXPECT_TRUE(within_ci("x", 1.05, 0.1, 1.0, 0.2));
  EXPECT_TRUE(within_ci("x", MeanCI{1.05, 0.1}, 1.0, 0.2));
  EXPECT_TRUE(within_ci("x", 1.15, 0.1, 1.0, 0.2, 0.05));  // the model error widens the tolerance
  const ::testing::AssertionResult outside = within_ci("x", 1.15, 0.1, 1.0, 0.2);
  EXPECT_FALSE(outside);
  EXPECT_NE(std::string(outside.message()).find("> ci + model error"), std::string::npos) << outside.message();
  const ::testing::AssertionResult noisy = within_ci("x", 1.05, 0.3, 1.0, 0.2);  // inside its CI, but the CI is wide
  EXPECT_FALSE(noisy);
  EXPECT_NE(std::string(noisy.message()).find("> its bound"), std::string::npos) << noisy.message();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(within_ci("x", nan, 0.1, 1.0, 0.2));
  EXPECT_FALSE(within_ci("x", 1.0, nan, 1.0, 0.2));
}

TEST(StatisticalCheck, ExpectedBoundIsLambdaPTimesTheStandardErrorTimesTheQuantile) {
  // 0.999 quantiles of sqrt(chi^2_{R-1} / R): 24.32 / 8 for R = 8, 37.70 / 16 for R = 16 (tables); the
  // Wilson-Hilferty form is within 1 % of them.
  EXPECT_NEAR(expected_ci_bound(1.0, 8) / (confidence_lambda_p / std::sqrt(8.0)), std::sqrt(24.32 / 8.0), 0.01);
  EXPECT_NEAR(expected_ci_bound(1.0, 16) / (confidence_lambda_p / std::sqrt(16.0)), std::sqrt(37.70 / 16.0), 0.01);
  EXPECT_NEAR(expected_ci_bound(2.0, 1000) / expected_ci_bound(1.0, 1000), 2.0, 1e-15);
}
