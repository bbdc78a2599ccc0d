// The collision rule of rough particles (collide/rough_rule.hpp) against its defining properties, and the
// collision stage with spins (schemes/collision_stage.hpp):
//  - the contact velocity G: G.sigma -> -alpha G.sigma and G_t -> -beta G_t; momentum conserved; the returned
//    translational loss is the direct difference; alpha = beta = 1 conserves translational plus rotational energy;
//    disks keep their velocities in the plane and their spins along z;
//  - beta = -1 is the smooth rule bit for bit, in the rule and in a whole collision stage;
//  - the stage's result does not depend on its batch size with spins either.
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <string_view>
#include <utility>

#include <gtest/gtest.h>

#include "kernel/collide/hard_sphere.hpp"
#include "kernel/collide/inelastic_rule.hpp"
#include "kernel/collide/pair_coefficients.hpp"
#include "kernel/collide/rough_rule.hpp"
#include "kernel/core/philox_stream.hpp"
#include "kernel/core/sampling.hpp"
#include "kernel/schemes/collision_stage.hpp"
#include "kernel/schemes/initial_state.hpp"
#include "tests/test_scenes.hpp"

using namespace granmc;
using granmc::testing::scene_from_toml;

namespace {

/// One species of rough particles in `dimension` d (collision keys given), for pair_coefficients and the stage.
Scene rough_gas(double alpha, double beta, int dimension, int particles = 100) {
  constexpr std::string_view text = R"(
    [run]
    t_end = 1.0
    dt = 1.0
    dimension = ${d}

    [[species]]
    name = "grains"
    mass = 1.5
    particles = ${n}

    [collision]
    restitution = ${alpha}
    tangential_restitution = ${beta}
  )";
  return scene_from_toml(text, {{"d", dimension}, {"n", particles}, {"alpha", alpha}, {"beta", beta}});
}

Vec3 random_vector(const RandomBlock& r, int dimension) {
  return {uniform_open(r[0]) - 0.5, uniform_open(r[1]) - 0.5, dimension == 3 ? uniform_open(r[2]) - 0.5 : 0.0};
}

/// A random pre-collision pair with sigma-hat such that g.sigma > 0, for trial t.
struct Pair {
  Vec3 vk, vl, sk, sl, sigma;
  double g_sigma;
};
Pair random_pair(int t, int dimension) {
  const RandomStream rng(5, 0);
  const auto block = [&](std::uint16_t sub) { return rng.block(RngPurpose::collision_pair, sub, t, 0); };
  Pair p{random_vector(block(0), dimension),
         random_vector(block(1), dimension),
         random_vector(block(2), dimension),
         random_vector(block(3), dimension),
         {},
         0.0};
  if (dimension == 2) p.sk = {0.0, 0.0, p.sk.x}, p.sl = {0.0, 0.0, p.sl.y};
  const RandomBlock d = block(4);
  const double turn = 2.0 * std::numbers::pi * uniform_open(d[0]);
  p.sigma =
      dimension == 3 ? unit_vector(uniform_open(d[0]), uniform_open(d[1])) : Vec3{std::cos(turn), std::sin(turn), 0.0};
  p.g_sigma = dot(p.vk - p.vl, p.sigma);
  if (p.g_sigma < 0.0) p.sigma = -1.0 * p.sigma, p.g_sigma = -p.g_sigma;
  return p;
}

Vec3 contact_velocity(const Pair& p) { return p.vk - p.vl - cross(p.sigma, p.sk + p.sl); }

}  // namespace

TEST(RoughRule, ReversesTheContactVelocityAndKeepsMomentum) {
  for (int d : {3, 2}) {
    for (double alpha : {0.5, 0.9, 1.0}) {
      for (double beta : {-0.7, 0.0, 0.6, 1.0}) {
        const Scene scene = rough_gas(alpha, beta, d);
        const PairCoefficients c = pair_coefficients(scene).front();
        const double m = scene.species[0].mass, kappa = scene.collision.reduced_inertia;
        for (int t = 0; t < 200; ++t) {
          Pair p = random_pair(t, d);
          const Vec3 contact = contact_velocity(p);
          const Vec3 slip = contact - p.g_sigma * p.sigma;
          const Vec3 momentum = m * (p.vk + p.vl);
          const double twice_translational = m * (norm2(p.vk) + norm2(p.vl));
          const double twice_rotational = kappa * m * (norm2(p.sk) + norm2(p.sl));  // I omega^2 = kappa m s^2
          const double loss = rough_collision(p.vk, p.vl, p.sk, p.sl, p.sigma, p.g_sigma, c);
          const Vec3 after = contact_velocity(p);
          const double eps = 64 * std::numeric_limits<double>::epsilon();
          ASSERT_NEAR(dot(after, p.sigma), -alpha * p.g_sigma, eps);
          const Vec3 slip_after = after - dot(after, p.sigma) * p.sigma;
          ASSERT_NEAR(slip_after.x, -beta * slip.x, eps);
          ASSERT_NEAR(slip_after.y, -beta * slip.y, eps);
          ASSERT_NEAR(slip_after.z, -beta * slip.z, eps);
          const Vec3 momentum_after = m * (p.vk + p.vl);
          ASSERT_NEAR(norm(momentum_after - momentum), 0.0, eps);
          ASSERT_NEAR(loss, twice_translational - m * (norm2(p.vk) + norm2(p.vl)), eps);
          if (alpha == 1.0 && beta == 1.0) {
            ASSERT_NEAR(twice_translational + twice_rotational,
                        m * (norm2(p.vk) + norm2(p.vl)) + kappa * m * (norm2(p.sk) + norm2(p.sl)), eps);
          }
          if (d == 2) {  // in the plane, spinning about z
            ASSERT_EQ(p.vk.z, 0.0);
            ASSERT_EQ(p.vl.z, 0.0);
            ASSERT_EQ(p.sk.x, 0.0);
            ASSERT_EQ(p.sk.y, 0.0);
            ASSERT_EQ(p.sl.x, 0.0);
            ASSERT_EQ(p.sl.y, 0.0);
          }
        }
      }
    }
  }
}

TEST(RoughRule, TheTangentialImpulseIsTheTheorysFactor) {
  // Equal masses: the impulse on k along G_t is -m b G_t, b = kappa (1 + beta) / (2 (1 + kappa)) (theory/rough.hpp).
  const Scene scene = rough_gas(0.9, 0.3, 3);
  const PairCoefficients c = pair_coefficients(scene).front();
  const double kappa = scene.collision.reduced_inertia;
  EXPECT_DOUBLE_EQ(c.tangential_k, kappa * 1.3 / (2.0 * (1.0 + kappa)));
  EXPECT_DOUBLE_EQ(c.spin_k, c.tangential_k / kappa);
}

TEST(RoughRule, SmoothLimitIsTheSmoothRuleBitForBit) {
  for (int d : {3, 2}) {
    Scene scene = rough_gas(0.8, -1.0, d);
    const PairCoefficients c = pair_coefficients(scene).front();
    ASSERT_EQ(c.tangential, 0.0);
    for (int t = 0; t < 200; ++t) {
      Pair rough = random_pair(t, d);
      Pair smooth = rough;
      const double loss = rough_collision(rough.vk, rough.vl, rough.sk, rough.sl, rough.sigma, rough.g_sigma, c);
      inelastic_collision(smooth.vk, smooth.vl, smooth.sigma, smooth.g_sigma, c);
      ASSERT_EQ(loss, 2.0 * c.energy_loss * smooth.g_sigma * smooth.g_sigma);
      for (auto [a, b] :
           {std::pair{rough.vk, smooth.vk}, {rough.vl, smooth.vl}, {rough.sk, smooth.sk}, {rough.sl, smooth.sl}}) {
        ASSERT_EQ(a.x, b.x);
        ASSERT_EQ(a.y, b.y);
        ASSERT_EQ(a.z, b.z);
      }
    }
  }
}

namespace {

/// A rough gas's collision stage, run for a few steps with many candidates per particle.
template <class Kernel, std::uint64_t batch>
GasState stage_after_steps(const Scene& scene, CollisionTally& tally) {
  const RandomStream rng(41, 0);
  GasState state = maxwellian_state(scene, rng);
  if (!state.species[0].has_spins()) state.species[0].enable_spins();  // beta = -1: spins of zero
  const auto pairs = pair_coefficients(scene);
  std::vector<double> omega_max{1.0};
  std::vector<std::uint64_t> candidates{900};
  std::vector<CollisionTally> tallies(1);
  for (int s = 0; s < 4; ++s, ++state.step)
    collide_step<Kernel, batch>(state, pairs, omega_max, candidates, rng, tallies, Kernel{});
  tally = tallies[0];
  return state;
}

void expect_same_state(const GasState& a, const GasState& b, bool spins) {
  for (std::size_t k = 0; k < a.species[0].size(); ++k) {
    const Vec3 u = a.species[0].velocity(k), v = b.species[0].velocity(k);
    ASSERT_EQ(u.x, v.x);
    ASSERT_EQ(u.y, v.y);
    ASSERT_EQ(u.z, v.z);
    if (!spins) continue;
    const Vec3 s = a.species[0].spin(k), w = b.species[0].spin(k);
    ASSERT_EQ(s.x, w.x);
    ASSERT_EQ(s.y, w.y);
    ASSERT_EQ(s.z, w.z);
  }
}

}  // namespace

TEST(RoughStage, SmoothLimitGivesTheSmoothStagesBits) {
  const Scene scene = rough_gas(0.8, -1.0, 3, 60);
  CollisionTally rough_tally, smooth_tally;
  const GasState rough = stage_after_steps<RoughHardSphere, 64>(scene, rough_tally);
  const GasState smooth = stage_after_steps<HardSphere, 64>(scene, smooth_tally);
  ASSERT_GT(rough_tally.collisions, 400u);  // about 12 per particle
  EXPECT_EQ(rough_tally.collisions, smooth_tally.collisions);
  EXPECT_EQ(rough_tally.twice_energy_loss, smooth_tally.twice_energy_loss);
  expect_same_state(rough, smooth, false);
}

TEST(RoughStage, ResultDoesNotDependOnTheBatchSize) {
  for (int d : {3, 2}) {
    const Scene scene = rough_gas(0.7, 0.4, d, 60);
    CollisionTally one_tally, many_tally;
    const GasState one = d == 3 ? stage_after_steps<RoughHardSphere, 1>(scene, one_tally)
                                : stage_after_steps<RoughHardDisk, 1>(scene, one_tally);
    const GasState many = d == 3 ? stage_after_steps<RoughHardSphere, 64>(scene, many_tally)
                                 : stage_after_steps<RoughHardDisk, 64>(scene, many_tally);
    ASSERT_GT(one_tally.collisions, 400u);
    EXPECT_EQ(one_tally.collisions, many_tally.collisions);
    EXPECT_EQ(one_tally.twice_energy_loss, many_tally.twice_energy_loss);
    expect_same_state(one, many, true);
  }
}
