// The post-collision rule (000 eqs. 14-15) conserves momentum to rounding and loses exactly
// (1 - alpha^2) m_i m_j / (2 (m_i + m_j)) (g.sigma)^2 of kinetic energy; the impact direction of an
// accepted pair (collide/impact_direction.hpp) has the density Theta(g.sigma) (g.sigma) / (pi |g|).
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <span>
#include <string>
#include <string_view>
#include <tuple>

#include <gtest/gtest.h>

#include "kernel/collide/enskog_chi.hpp"
#include "kernel/collide/impact_direction.hpp"
#include "kernel/collide/inelastic_rule.hpp"
#include "kernel/collide/isotropic_scattering.hpp"
#include "kernel/collide/pair_coefficients.hpp"
#include "kernel/core/philox_stream.hpp"
#include "kernel/core/sampling.hpp"
#include "tests/test_scenes.hpp"

using namespace granmc;
using granmc::testing::scene_from_toml;

namespace {

/// Two species for pair_coefficients, which reads the species and [collision] only (the run is never made).
Scene two_species(double m1, double m2, double alpha) {
  constexpr std::string_view text = R"(
    [run]
    t_end = 1.0
    dt = 1.0

    [[species]]
    name = "a"
    mass = ${m1}
    particles = 100

    [[species]]
    name = "b"
    mass = ${m2}
    diameter = 2.0
    particles = 100

    [collision]
    restitution = ${alpha}
  )";
  return scene_from_toml(text, {{"m1", m1}, {"m2", m2}, {"alpha", alpha}});
}

}  // namespace

TEST(CollisionRule, ConservesMomentumAndLosesTheRightEnergy) {
  const RandomStream rng(1, 0);
  for (double alpha : {0.0, 0.3, 0.8, 1.0}) {
    for (auto [m1, m2] : {std::pair{1.0, 1.0}, {1.0, 1e3}, {1e-3, 1.0}, {2.0, 0.5}}) {
      const Scene scene = two_species(m1, m2, alpha);
      for (const PairCoefficients& p : pair_coefficients(scene)) {
        const double mi = scene.species[p.i].mass, mj = scene.species[p.j].mass;
        for (int trial = 0; trial < 1000; ++trial) {
          const RandomBlock r = rng.block(RngPurpose::collision_pair, 0, trial, 0);
          const RandomBlock q = rng.block(RngPurpose::collision_pair, 1, trial, 0);
          Vec3 vk{uniform_open(r[0]) - 0.5, uniform_open(r[1]) - 0.5, uniform_open(r[2]) - 0.5};
          Vec3 vl{uniform_open(q[0]) - 0.5, uniform_open(q[1]) - 0.5, uniform_open(q[2]) - 0.5};
          vk *= 1.0 / std::sqrt(mi);
          vl *= 1.0 / std::sqrt(mj);
          const Vec3 sigma = unit_vector(uniform_open(r[3]), uniform_open(q[3]));
          const double g_sigma = dot(vk - vl, sigma);
          const Vec3 p_before = mi * vk + mj * vl;
          const double e_before = 0.5 * (mi * norm2(vk) + mj * norm2(vl));
          inelastic_collision(vk, vl, sigma, g_sigma, p);
          const Vec3 p_after = mi * vk + mj * vl;
          const double e_after = 0.5 * (mi * norm2(vk) + mj * norm2(vl));
          const double p_scale = mi * norm(vk) + mj * norm(vl) + 1e-300;
          const double eps = 8 * std::numeric_limits<double>::epsilon();
          ASSERT_NEAR(p_after.x, p_before.x, eps * p_scale);
          ASSERT_NEAR(p_after.y, p_before.y, eps * p_scale);
          ASSERT_NEAR(p_after.z, p_before.z, eps * p_scale);
          const double loss = p.energy_loss * g_sigma * g_sigma;
          ASSERT_NEAR(e_before - e_after, loss, 16 * std::numeric_limits<double>::epsilon() * e_before);
          // Normal relative velocity reverses and shrinks by alpha: (g'.sigma) = -alpha (g.sigma).
          ASSERT_NEAR(dot(vk - vl, sigma), -alpha * g_sigma, eps * (norm(vk) + norm(vl) + std::fabs(g_sigma)));
        }
      }
    }
  }
}

TEST(CollisionRule, PairCoefficientsFollowThePaper) {
  Scene s = two_species(1.0, 3.0, 0.5);
  // Set after parsing: n_0/n_1 = 4 with N_0 = N_1 = 100, which the scene file refuses (each simulated particle
  // must carry the same weight); pair_coefficients reads the densities and not the particle numbers.
  s.species[0].density = 2.0;
  s.species[1].density = 0.5;
  const auto pairs = pair_coefficients(s);
  ASSERT_EQ(pairs.size(), 4u);
  const PairCoefficients& p = pairs[1];  // (i, j) = (0, 1)
  EXPECT_EQ(p.i, 0);
  EXPECT_EQ(p.j, 1);
  EXPECT_DOUBLE_EQ(p.mu_ji, 0.75);
  EXPECT_DOUBLE_EQ(p.mu_ij, 0.25);
  EXPECT_DOUBLE_EQ(p.rate_prefactor, 4.0 * M_PI * 1.5 * 1.5 * 0.5);         // 4 pi sigma_12^2 n_2
  EXPECT_DOUBLE_EQ(pairs[2].rate_prefactor, 4.0 * M_PI * 1.5 * 1.5 * 2.0);  // (1, 0): n_1
  EXPECT_DOUBLE_EQ(p.energy_loss, 0.5 * 0.75 * 3.0 / 4.0);
}

// Given g, cos(theta) = g-hat.sigma-hat has the density 2 cos(theta) on (0, 1], so cos^2(theta) is uniform,
// and the azimuth about g-hat is uniform: chi-square tests of both (20 bins each, 10^6 draws, the 0.999
// quantile at 19 degrees of freedom), and g.sigma = |g| cos(theta), |sigma-hat| = 1 to rounding. Three g: along
// an axis, a generic direction, and a short one (the scale of g must not matter).
TEST(ImpactDirection, HasTheDensityOfTheCollisionKernel) {
  constexpr int bins = 20, n = 1'000'000;
  constexpr double chi2_999_19 = 43.8202;
  const RandomStream rng(20261201, 3);
  for (const Vec3 g : {Vec3{0.0, 0.0, 2.5}, Vec3{-1.3, 0.4, 0.9}, Vec3{3e-9, -2e-9, 1e-9}}) {
    SCOPED_TRACE(::testing::Message() << "g = (" << g.x << ", " << g.y << ", " << g.z << ")");
    const double g_norm = norm(g);
    const Vec3 e3 = (1.0 / g_norm) * g;  // a frame about g-hat for the azimuth
    const Vec3 helper = std::abs(e3.x) < 0.9 ? Vec3{1.0, 0.0, 0.0} : Vec3{0.0, 1.0, 0.0};
    const Vec3 t = helper - dot(helper, e3) * e3;
    const Vec3 e1 = (1.0 / norm(t)) * t;
    const Vec3 e2{e3.y * e1.z - e3.z * e1.y, e3.z * e1.x - e3.x * e1.z, e3.x * e1.y - e3.y * e1.x};
    std::array<int, bins> cos2_counts{}, azimuth_counts{};
    double worst_norm = 0.0, worst_g_sigma = 0.0;
    for (int k = 0; k < n; ++k) {
      const RandomBlock r = rng.block(RngPurpose::collision_pair, 0, 0, static_cast<std::uint64_t>(k));
      const ImpactDirection d = impact_direction(g, g_norm, unit_vector(uniform_open(r[0]), uniform_open(r[1])));
      ASSERT_GT(d.g_sigma, 0.0);
      const double c = dot(d.sigma, e3);
      worst_norm = std::max(worst_norm, std::abs(norm(d.sigma) - 1.0));
      worst_g_sigma = std::max(worst_g_sigma, std::abs(d.g_sigma - g_norm * c) / g_norm);
      ++cos2_counts[std::min(static_cast<int>(c * c * bins), bins - 1)];
      const double phi = std::atan2(dot(d.sigma, e2), dot(d.sigma, e1));  // (-pi, pi]
      ++azimuth_counts[std::min(static_cast<int>((phi / (2.0 * std::numbers::pi) + 0.5) * bins), bins - 1)];
    }
    const auto chi2 = [&](const std::array<int, bins>& counts) {
      double sum = 0.0;
      for (int c : counts) sum += (c - n / bins) * (c - n / bins) / static_cast<double>(n / bins);
      return sum;
    };
    EXPECT_LT(chi2(cos2_counts), chi2_999_19) << "cos^2 of the angle to g";
    EXPECT_LT(chi2(azimuth_counts), chi2_999_19) << "azimuth about g";
    // sigma-hat = h / |h| is a unit vector to rounding; near grazing incidence the rounding of h = g + |g| n
    // is divided by |h| (|h| / |g| = (2 (1 + g-hat.n))^1/2 with 1 + g-hat.n uniform on (0, 2): its smallest
    // value in 10^6 draws is about 2e-6, so |h| / |g| about 2e-3), where g.sigma is itself near zero.
    EXPECT_LT(worst_norm, 1e-15);
    EXPECT_LT(worst_g_sigma, 1e-12);
  }
}

// Disks: given g in the plane, the angle theta from g-hat to sigma-hat has the density cos(theta) / 2 on
// (-pi/2, pi/2), so sin(theta) = (g-hat x sigma-hat)_z is uniform on (-1, 1): a chi-square test (20 bins,
// 10^6 draws, the 0.999 quantile at 19 degrees of freedom); sigma-hat stays in the plane, is a unit vector and
// g.sigma = |g| cos(theta) to rounding. The lanes of impact_variates are the bits of impact_variate.
TEST(ImpactDirection, HasTheDensityOfTheCollisionKernelForDisks) {
  constexpr int bins = 20, n = 1'000'000;
  constexpr double chi2_999_19 = 43.8202;
  const RandomStream rng(2, 3);
  for (const Vec3 g : {Vec3{2.5, 0.0, 0.0}, Vec3{-1.3, 0.4, 0.0}, Vec3{3e-9, -2e-9, 0.0}}) {
    SCOPED_TRACE(::testing::Message() << "g = (" << g.x << ", " << g.y << ")");
    const double g_norm = norm(g);
    const Vec3 e = (1.0 / g_norm) * g;
    std::array<int, bins> sin_counts{};
    double worst_norm = 0.0, worst_g_sigma = 0.0;
    for (int k = 0; k < n; ++k) {
      const RandomBlock r = rng.block(RngPurpose::collision_pair, 0, 0, static_cast<std::uint64_t>(k));
      const ImpactDirection d =
          impact_direction<2>(g, g_norm, impact_variate<2>(uniform_open(r[0]), uniform_open(r[1])));
      ASSERT_GT(d.g_sigma, 0.0);
      ASSERT_EQ(d.sigma.z, 0.0);
      const double sin_theta = e.x * d.sigma.y - e.y * d.sigma.x;
      worst_norm = std::max(worst_norm, std::abs(norm(d.sigma) - 1.0));
      worst_g_sigma = std::max(worst_g_sigma, std::abs(d.g_sigma - dot(g, d.sigma)) / g_norm);
      ++sin_counts[std::min(static_cast<int>((0.5 * sin_theta + 0.5) * bins), bins - 1)];
    }
    double chi2 = 0.0;
    for (int c : sin_counts) chi2 += (c - n / bins) * (c - n / bins) / static_cast<double>(n / bins);
    EXPECT_LT(chi2, chi2_999_19) << "sin of the angle to g";
    EXPECT_LT(worst_norm, 1e-15);
    EXPECT_LT(worst_g_sigma, 1e-15);
  }
  constexpr std::size_t lanes = 16;
  std::array<double, lanes> u1, u2, x, y, z;
  for (std::size_t k = 0; k < lanes; ++k) u1[k] = (k + 0.5) / lanes, u2[k] = 1.0 - u1[k];
  impact_variates<2>(std::span<const double, lanes>(u1), std::span<const double, lanes>(u2), std::span(x), std::span(y),
                     std::span(z));
  for (std::size_t k = 0; k < lanes; ++k) {
    const Vec3 one = impact_variate<2>(u1[k], u2[k]);
    EXPECT_EQ(x[k], one.x);
    EXPECT_EQ(y[k], one.y);
    EXPECT_EQ(z[k], one.z);
  }
}

// Disks with the isotropic law (Maxwell and VHS kernels): sigma-hat at an angle theta uniform on (-pi/2, pi/2),
// so that the scattering direction e = g-hat - 2 (g-hat.sigma) sigma-hat, at angle pi - 2 theta to g-hat, is
// uniform on the circle (001 eq. 4): a chi-square test of e's angle (20 bins, 10^6 draws). The lanes of
// impact_variates are the bits of impact_variate.
TEST(ImpactDirection, MakesTheScatteringOfDisksIsotropicWithTheIsotropicLaw) {
  constexpr int bins = 20, n = 1'000'000;
  constexpr double chi2_999_19 = 43.8202;
  constexpr ImpactLaw law = ImpactLaw::isotropic;
  const RandomStream rng(2, 4);
  for (const Vec3 g : {Vec3{2.5, 0.0, 0.0}, Vec3{-1.3, 0.4, 0.0}}) {
    const double g_norm = norm(g);
    const Vec3 h = (1.0 / g_norm) * g;
    std::array<int, bins> counts{};
    for (int k = 0; k < n; ++k) {
      const RandomBlock r = rng.block(RngPurpose::collision_pair, 0, 0, static_cast<std::uint64_t>(k));
      const ImpactDirection d =
          impact_direction<2>(g, g_norm, impact_variate<2, law>(uniform_open(r[0]), uniform_open(r[1])));
      ASSERT_GT(d.g_sigma, 0.0);
      const Vec3 e = h - (2.0 * dot(h, d.sigma)) * d.sigma;
      const double angle = std::atan2(h.x * e.y - h.y * e.x, dot(h, e));  // in (-pi, pi]
      ++counts[std::min(static_cast<int>((angle / (2.0 * std::numbers::pi) + 0.5) * bins), bins - 1)];
    }
    double chi2 = 0.0;
    for (int c : counts) chi2 += (c - n / bins) * (c - n / bins) / static_cast<double>(n / bins);
    EXPECT_LT(chi2, chi2_999_19) << "angle of e to g-hat, g = (" << g.x << ", " << g.y << ")";
  }
  constexpr std::size_t lanes = 16;
  std::array<double, lanes> u1, u2, x, y, z;
  for (std::size_t k = 0; k < lanes; ++k) u1[k] = (k + 0.5) / lanes, u2[k] = 1.0 - u1[k];
  impact_variates<2, law>(std::span<const double, lanes>(u1), std::span<const double, lanes>(u2), std::span(x),
                          std::span(y), std::span(z));
  for (std::size_t k = 0; k < lanes; ++k) {
    const Vec3 one = impact_variate<2, law>(u1[k], u2[k]);
    EXPECT_EQ(x[k], one.x);
    EXPECT_EQ(y[k], one.y);
    EXPECT_EQ(z[k], one.z);
  }
}

// Hard disks scatter anisotropically: with sigma-hat by the hard-disk law (impact_direction<2>, the event
// scheme's hard disks as the time-stepped scheme's), 000's rule for unit masses is 001 eq. (4) with e =
// u-hat - 2 (u-hat.sigma) sigma-hat, a unit vector in the plane (to rounding), and the mean of mu = u-hat.e is
// -1/3 (a midpoint sum over the variate, error O(1/N^2)), the <1 - mu> = 4/3 of theory/white_noise.hpp.
TEST(HardDiskScattering, IsTheReflectionOfTheHardDiskLaw) {
  const Vec3 v{0.7, -1.2, 0.0}, w{-0.4, 0.3, 0.0};
  const Vec3 u = v - w;
  const double u_norm = norm(u), alpha = 0.6;
  const Vec3 h = (1.0 / u_norm) * u;
  PairCoefficients unit_masses;
  unit_masses.one_plus_alpha = 1.0 + alpha;
  unit_masses.mu_ij = unit_masses.mu_ji = 0.5;
  constexpr int points = 10000;
  double mean_mu = 0.0, worst = 0.0;
  for (int k = 0; k < points; ++k) {
    const ImpactDirection d = impact_direction<2>(u, u_norm, impact_variate<2>((k + 0.5) / points, 0.5));
    const Vec3 e = h - (2.0 * dot(h, d.sigma)) * d.sigma;
    Vec3 a = v, b = w, rule_a = v, rule_b = w;
    isotropic_scattering(a, b, e, alpha);
    inelastic_collision(rule_a, rule_b, d.sigma, d.g_sigma, unit_masses);
    worst = std::max({worst, std::abs(norm(e) - 1.0), norm(a - rule_a), norm(b - rule_b)});
    ASSERT_EQ(e.z, 0.0);
    mean_mu += dot(h, e) / points;
  }
  EXPECT_LT(worst, 1e-14);
  EXPECT_NEAR(mean_mu, -1.0 / 3.0, 1e-7);
}

// 001's kernel form (collision.rate > 0) in the plane: the pair prefactor times the kernel's mean angular weight
// is 2 pi rate, the total rate per pair over |g|^lambda, for each law (4 pi rate on the sphere).
TEST(PairCoefficients, TheRateFormGivesEveryPairTheRateOfTheKernel) {
  for (const auto& [kernel, law, d] :
       {std::tuple{"hard-sphere", ImpactLaw::hard_core, 2}, std::tuple{"maxwell", ImpactLaw::isotropic, 2},
        std::tuple{"vhs", ImpactLaw::isotropic, 2}, std::tuple{"hard-sphere", ImpactLaw::hard_core, 3},
        std::tuple{"maxwell", ImpactLaw::isotropic, 3}}) {
    const Scene s = granmc::testing::scene_from_toml(R"(
      [run]
      t_end = 1.0
      dt = 0.01
      dimension = ${d}
      [[species]]
      particles = 100
      [collision]
      kernel = "${kernel}"
      lambda = ${lambda}
      rate = 0.3
      restitution = 0.9
    )",
                                                     {{"d", d},
                                                      {"kernel", kernel},
                                                      {"lambda", std::string(kernel) == "maxwell" ? 0.0
                                                                 : std::string(kernel) == "vhs"   ? 0.5
                                                                                                  : 1.0}});
    const double sphere = d == 2 ? 2.0 * std::numbers::pi : 4.0 * std::numbers::pi;
    EXPECT_NEAR(pair_coefficients(s)[0].rate_prefactor * mean_angular_weight(d, law), sphere * 0.3, 1e-14)
        << kernel << ", d = " << d;
  }
}

// Disks and spheres collide at the rate of their pair constant: 2 pi sigma_ij n_j chi_ij for disks, with
// Henderson's chi when the scene has a packing fraction.
TEST(PairCoefficients, DisksHaveThePrefactorOfTheCircle) {
  const Scene s = granmc::testing::scene_from_toml(R"(
    [run]
    t_end = 1.0
    dt = 0.01
    dimension = 2
    [[species]]
    diameter = 1.5
    density = 0.7
    particles = 100
    [collision]
    restitution = 0.9
    packing_fraction = 0.3
  )");
  const std::vector<PairCoefficients> pairs = pair_coefficients(s);
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_DOUBLE_EQ(pairs[0].rate_prefactor, 2.0 * M_PI * 1.5 * 0.7 * enskog_chi_disks(0.3));
}
