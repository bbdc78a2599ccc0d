// The post-collision rule (000 eqs. 14-15) conserves momentum to rounding and loses exactly
// (1 - alpha^2) m_i m_j / (2 (m_i + m_j)) (g.sigma)^2 of kinetic energy.
#include <gtest/gtest.h>

#include <cmath>

#include "kernel/collide/inelastic_rule.hpp"
#include "kernel/collide/pair_coefficients.hpp"
#include "kernel/core/philox_stream.hpp"
#include "kernel/core/sampling.hpp"

using namespace granmc;

namespace {

Scene two_species(double m1, double m2, double alpha) {
  Scene s;
  s.species = {{"a", m1, 1.0, 1.0, 100}, {"b", m2, 2.0, 1.0, 100}};
  s.collision.restitution = {{{alpha, alpha}, {alpha, alpha}}};
  return s;
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
  s.species[0].density = 2.0;
  s.species[1].density = 0.5;
  const auto pairs = pair_coefficients(s);
  ASSERT_EQ(pairs.size(), 4u);
  const PairCoefficients& p = pairs[1];  // (i, j) = (0, 1)
  EXPECT_EQ(p.i, 0);
  EXPECT_EQ(p.j, 1);
  EXPECT_DOUBLE_EQ(p.mu_ji, 0.75);
  EXPECT_DOUBLE_EQ(p.mu_ij, 0.25);
  EXPECT_DOUBLE_EQ(p.rate_prefactor, 4.0 * M_PI * 1.5 * 1.5 * 0.5);  // 4 pi sigma_12^2 n_2
  EXPECT_DOUBLE_EQ(pairs[2].rate_prefactor, 4.0 * M_PI * 1.5 * 1.5 * 2.0);  // (1, 0): n_1
  EXPECT_DOUBLE_EQ(p.energy_loss, 0.5 * 0.75 * 3.0 / 4.0);
}
