// SonineMaxwellian (kernel/core/sonine_maxwellian.hpp): moments, isotropy and the speed distribution of
// Philox samples against Simpson quadrature of max(phi, 0); the truncated mass against a direct integral.
// Statistical tolerances are 5 standard errors from the sample variance; the chi-square test is at p = 0.001.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <gtest/gtest.h>

#include "kernel/core/philox_stream.hpp"
#include "kernel/core/sampling.hpp"
#include "kernel/core/sonine_maxwellian.hpp"

using namespace granmc;

namespace {

// Uniforms on (0, 1) from consecutive blocks (initial_velocity, sub, step 0, index 0, 1, ...).
class PhiloxUniforms {
 public:
  PhiloxUniforms(std::uint64_t seed, std::uint16_t sub) : rng_(seed, 0), sub_(sub) {}
  double operator()() {
    if (word_ == 4) {
      block_ = rng_.block(RngPurpose::initial_velocity, sub_, 0, index_++);
      word_ = 0;
    }
    return uniform_open(block_[word_++]);
  }

 private:
  RandomStream rng_;
  std::uint16_t sub_;
  std::uint64_t index_ = 0;
  RandomBlock block_{};
  int word_ = 4;
};

double s2(double x) { return 0.5 * x * x - 2.5 * x + 1.875; }
double bracket(double a2, double x) { return 1.0 + a2 * s2(x); }

// Speed density of phi, 4 pi c^2 phi(c) = (4 / sqrt(pi)) c^2 e^(-c^2) [1 + a2 S2(c^2)], unit mass.
double speed_density(double a2, double c) {
  return 4.0 / std::sqrt(std::numbers::pi) * c * c * std::exp(-c * c) * bracket(a2, c * c);
}

constexpr double c_max = 8.0;  // the density beyond is below e^(-64)

// c* where the bracket turns negative (a2 < 0: it decreases for c^2 > 5/2), by bisection; c_max if none.
double sign_change(double a2) {
  if (a2 >= 0.0) return c_max;
  double lo = std::sqrt(2.5), hi = 10.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (bracket(a2, mid * mid) > 0.0)
      lo = mid;
    else
      hi = mid;
  }
  return std::fmin(lo, c_max);
}

template <class F>
double simpson(F f, double a, double b, int n = 20000) {
  const double h = (b - a) / n;
  double s = f(a) + f(b);
  for (int i = 1; i < n; ++i) s += (i % 2 ? 4.0 : 2.0) * f(a + i * h);
  return s * h / 3.0;
}

// int_a^b h(c^2) max(speed_density, 0) dc, split at c* so that Simpson sees smooth integrands.
template <class H>
double positive_part_integral(double a2, H h, double a, double b) {
  const double cs = sign_change(a2);
  const auto g = [&](double c) { return h(c * c) * speed_density(a2, c); };
  if (b <= cs) return simpson(g, a, b);
  return a < cs ? simpson(g, a, cs) : 0.0;
}

// Exact expectations of x = c^2, x^2 and S2(x) under the sampled density max(phi, 0) / (1 + m).
struct Expected {
  double mass, x, x2, s2;
};
Expected truncated_expectations(double a2) {
  const auto e = [&](auto h) { return positive_part_integral(a2, h, 0.0, c_max); };
  const double mass = e([](double) { return 1.0; });
  return {mass, e([](double x) { return x; }) / mass, e([](double x) { return x * x; }) / mass,
          e([](double x) { return s2(x); }) / mass};
}

// Mean and standard error of a sample from its sums.
struct Sum {
  double s = 0.0, ss = 0.0;
  void add(double y) { s += y, ss += y * y; }
  double mean(double n) const { return s / n; }
  double se(double n) const { return std::sqrt((ss / n - mean(n) * mean(n)) / (n - 1.0)); }
};

void expect_mean(const Sum& sum, double n, double expected, const char* what) {
  EXPECT_NEAR(sum.mean(n), expected, 5.0 * sum.se(n)) << what << ", standard error " << sum.se(n);
}

constexpr int n_bins = 20;
constexpr double bin_width = 0.15;       // bins [0.15 k, 0.15 (k + 1)), the last one [2.85, infinity)
constexpr double chi2_999_19 = 43.8202;  // chi-square quantile 0.999 at 20 - 1 degrees of freedom

// Draws n velocities at a2 and checks moments and isotropy; with chi_square, the speed histogram too.
void check_sampler(double a2, std::uint16_t sub, int n, bool chi_square) {
  SCOPED_TRACE(testing::Message() << "a2 = " << a2);
  const SonineMaxwellian sampler(a2);
  PhiloxUniforms next_uniform(20240611, sub);
  Sum x, x2, sonine;
  std::array<Sum, 3> mean;
  std::array<std::array<Sum, 3>, 3> second;
  std::array<int, n_bins> counts{};
  for (int k = 0; k < n; ++k) {
    const Vec3 c = sampler.sample(next_uniform);
    const double c2 = norm2(c);
    x.add(c2);
    x2.add(c2 * c2);
    sonine.add(s2(c2));
    const std::array<double, 3> ci = {c.x, c.y, c.z};
    for (int i = 0; i < 3; ++i) {
      mean[i].add(ci[i]);
      for (int j = i; j < 3; ++j) second[i][j].add(ci[i] * ci[j]);
    }
    ++counts[std::min(static_cast<int>(std::sqrt(c2) / bin_width), n_bins - 1)];
  }

  const Expected ex = truncated_expectations(a2);
  expect_mean(x, n, ex.x, "<c^2>");
  expect_mean(x2, n, ex.x2, "<c^4>");
  expect_mean(sonine, n, ex.s2, "<S2(c^2)> = (15/8) a2_hat");
  for (int i = 0; i < 3; ++i) {
    expect_mean(mean[i], n, 0.0, "<c_i>");
    for (int j = i; j < 3; ++j) expect_mean(second[i][j], n, i == j ? ex.x / 3.0 : 0.0, "<c_i c_j>");
  }

  if (!chi_square) return;
  const auto one = [](double) { return 1.0; };
  double chi2 = 0.0, total = 0.0;
  for (int b = 0; b < n_bins; ++b) {
    const double hi = b + 1 < n_bins ? (b + 1) * bin_width : c_max;
    const double p = positive_part_integral(a2, one, b * bin_width, hi) / ex.mass;
    total += p;
    chi2 += (counts[b] - n * p) * (counts[b] - n * p) / (n * p);
  }
  EXPECT_NEAR(total, 1.0, 1e-12);
  EXPECT_LT(chi2, chi2_999_19);
}

}  // namespace

TEST(SonineMaxwellian, QuadratureReproducesTheMomentsOfPhi) {
  // Untruncated phi: unit mass, <c^2> = 3/2, <c^4> = (15/4)(1 + a2), <S2> = (15/8) a2. So for a2 >= 0 the
  // references of check_sampler are these exact moments; for a2 < 0 the truncation shifts them.
  for (double a2 : {0.0, 0.1, -0.05, 0.0146, -0.0146}) {
    const auto e = [&](auto h) {
      return simpson([&](double c) { return h(c * c) * speed_density(a2, c); }, 0.0, c_max);
    };
    EXPECT_NEAR(e([](double) { return 1.0; }), 1.0, 1e-12);
    EXPECT_NEAR(e([](double x) { return x; }), 1.5, 1e-12);
    EXPECT_NEAR(e([](double x) { return x * x; }), 3.75 * (1.0 + a2), 1e-12);
    EXPECT_NEAR(e([](double x) { return s2(x); }), 1.875 * a2, 1e-12);
  }
}

TEST(SonineMaxwellian, ZeroA2IsTheMaxwellian) { check_sampler(0.0, 10, 1000000, false); }

TEST(SonineMaxwellian, PositiveA2) { check_sampler(0.1, 11, 1000000, true); }

// m = 1.7e-4 only, but it sits at c^2 > 9: the sampled density has <c^4> = 3.58396 against (15/4)(1 + a2) =
// 3.5625 and a2_eff = (8/15) <S2> = -0.04650, 3.7 and 6.3 standard errors away from the untruncated values.
TEST(SonineMaxwellian, NegativeA2IsTruncated) { check_sampler(-0.05, 12, 1000000, true); }

TEST(SonineMaxwellian, HcsA2NearAlphaPointNine) {
  check_sampler(0.0146, 13, 1000000, false);
  check_sampler(-0.0146, 14, 1000000, false);
}

TEST(SonineMaxwellian, TruncatedMassIsTheNegativePart) {
  for (double a2 : {0.0, 0.0146, 0.1, 0.5}) EXPECT_EQ(SonineMaxwellian(a2).truncated_mass(), 0.0);
  for (double a2 : {-0.0146, -0.05, -0.2, -0.5}) {
    const double cs = sign_change(a2);
    const double negative = simpson([&](double c) { return -speed_density(a2, c); }, cs, c_max);
    EXPECT_GT(negative, 0.0);
    EXPECT_NEAR(SonineMaxwellian(a2).truncated_mass(), negative, 1e-9 * negative) << "a2 = " << a2;
  }
}

TEST(SonineMaxwellian, AcceptanceIsMassOverEnvelope) {
  EXPECT_DOUBLE_EQ(SonineMaxwellian(0.0).acceptance(), 1.0);
  EXPECT_DOUBLE_EQ(SonineMaxwellian(0.1).acceptance(), 1.0 / 1.375);
  const SonineMaxwellian negative(-0.05);
  EXPECT_DOUBLE_EQ(negative.acceptance(), (1.0 + negative.truncated_mass()) / 1.09375);
}

TEST(SonineMaxwellian, RejectsA2OutsideHalf) {
  for (double a2 : {0.51, -0.51, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
    EXPECT_THROW(SonineMaxwellian{a2}, std::invalid_argument);
  EXPECT_EQ(SonineMaxwellian(-0.5).a2(), -0.5);
}

TEST(SonineMaxwellian, DisksSampleTheirPhiInThePlane) {
  // d = 2: in x = c^2 the density is max(e^(-x) [1 + a2 (x^2/2 - 2x + 1)], 0) / (1 + m), untruncated moments
  // <x> = 1, <x^2> = 2 (1 + a2). The references are Simpson integrals of that density over x; every sample lies
  // in the plane (z = 0 exactly) and its direction is uniform (<c_x> = <c_y> = <c_x c_y> = 0, <c_x^2> = <c_y^2>).
  const auto bracket2 = [](double a2, double x) { return 1.0 + a2 * (0.5 * x * x - 2.0 * x + 1.0); };
  std::uint16_t sub = 20;
  for (double a2 : {0.0, 0.1, -0.05}) {
    SCOPED_TRACE(testing::Message() << "a2 = " << a2);
    const SonineMaxwellian sampler(a2, 2);
    const auto moment = [&](auto h) {
      return simpson([&](double x) { return h(x) * std::exp(-x) * std::fmax(bracket2(a2, x), 0.0); }, 0.0, 64.0,
                     200000);
    };
    const double mass = moment([](double) { return 1.0; });
    EXPECT_NEAR(mass, 1.0 + sampler.truncated_mass(), 1e-9);
    if (a2 < 0.0) {
      EXPECT_GT(sampler.truncated_mass(), 0.0);
    }
    PhiloxUniforms next_uniform(20240611, sub++);
    const int n = 1000000;
    Sum x, x2, cx, cy, cxx, cyy, cxy;
    for (int k = 0; k < n; ++k) {
      const Vec3 c = sampler.sample(next_uniform);
      ASSERT_EQ(c.z, 0.0);
      const double c2 = norm2(c);
      x.add(c2);
      x2.add(c2 * c2);
      cx.add(c.x), cy.add(c.y), cxx.add(c.x * c.x), cyy.add(c.y * c.y), cxy.add(c.x * c.y);
    }
    const double mean_x = moment([](double v) { return v; }) / mass;
    expect_mean(x, n, mean_x, "<c^2>");
    expect_mean(x2, n, moment([](double v) { return v * v; }) / mass, "<c^4>");
    expect_mean(cx, n, 0.0, "<c_x>");
    expect_mean(cy, n, 0.0, "<c_y>");
    expect_mean(cxy, n, 0.0, "<c_x c_y>");
    expect_mean(cxx, n, mean_x / 2.0, "<c_x^2>");
    expect_mean(cyy, n, mean_x / 2.0, "<c_y^2>");
  }
  EXPECT_DOUBLE_EQ(SonineMaxwellian(0.1, 2).acceptance(), 1.0 / 1.2);  // W+ = 1 + 2 a2
}
