// The collision rule of rough particles (collide/rough_rule.hpp) against its defining properties, and the
// collision stage with spins (schemes/collision_stage.hpp):
//  - the contact velocity G: G.sigma -> -alpha G.sigma and G_t -> -beta G_t; momentum conserved; the returned
//    translational loss is the direct difference; alpha = beta = 1 conserves translational plus rotational energy;
//    disks keep their velocities in the plane and their spins along z;
//  - over Maxwellian pairs of a mixture, its mean energy changes are the Maxwellian rates of theory/rough.hpp;
//  - beta = -1 is the smooth rule bit for bit, in the rule and in a whole collision stage;
//  - the stage's result does not depend on its batch size with spins either.
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <string_view>
#include <utility>

#include <gtest/gtest.h>

#include "kernel/analysis/replica_statistics.hpp"
#include "kernel/collide/hard_sphere.hpp"
#include "kernel/collide/impact_direction.hpp"
#include "kernel/collide/inelastic_rule.hpp"
#include "kernel/collide/pair_coefficients.hpp"
#include "kernel/collide/rough_rule.hpp"
#include "kernel/core/philox_stream.hpp"
#include "kernel/core/sampling.hpp"
#include "kernel/schemes/collision_stage.hpp"
#include "kernel/schemes/initial_state.hpp"
#include "kernel/theory/rough.hpp"
#include "tests/statistical_check.hpp"
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

TEST(RoughRule, MixtureMeansAreTheMaxwellianRatesOfTheTheory) {
  // Pairs drawn from Maxwellians at four unequal temperatures (T_i, T_r,i of two species of unequal masses and
  // diameters, unequal alpha_ij), sigma-hat drawn as the stage draws it (density Theta(g.sigma) g.sigma), each
  // collision weighted by its rate n_j chi_ij sigma_ij^(d-1) c_d |g| (c_d = pi for spheres, 2 for disks): the
  // Monte Carlo mean of the energy changes of the rule, (2/d) sum_j rate x dK_tr,i and (2/d_r) sum_j rate x
  // dK_rot,i, is theory::rough_mixture_collision_rates exactly in expectation (its Maxwellian averages are exact
  // for Maxwellian pairs). Tolerance: lambda_p standard errors of the mean over 10^6 pairs per species pair.
  constexpr int samples = 1000000;
  for (int d : {3, 2}) {
    constexpr std::string_view text = R"(
      [run]
      t_end = 1.0
      dt = 1.0
      dimension = ${d}

      [[species]]
      name = "light"
      density = 0.6
      particles = 100

      [[species]]
      name = "heavy"
      mass = 3.0
      diameter = 1.6
      density = 0.3
      particles = 50

      [collision]
      restitution = [[0.9, 0.8], [0.8, 0.7]]
      tangential_restitution = 0.3
    )";
    const Scene scene = scene_from_toml(text, {{"d", d}});
    const double kappa = scene.collision.reduced_inertia;
    theory::RoughMixture mixture;
    mixture.gas.dimension = d;
    mixture.beta = scene.collision.tangential_restitution;
    mixture.kappa = kappa;
    for (int i = 0; i < 2; ++i) {
      mixture.gas.mass[i] = scene.species[i].mass;
      mixture.gas.diameter[i] = scene.species[i].diameter;
      mixture.gas.density[i] = scene.species[i].density;
      for (int j = 0; j < 2; ++j)
        mixture.gas.alpha[i][j] = scene.collision.restitution[i][j], mixture.gas.chi[i][j] = 1.0;
    }
    const theory::RoughTemperatures temperature{{1.0, 1.7}, {0.6, 1.3}};
    const theory::RoughTemperatures expected = theory::rough_mixture_collision_rates(mixture, temperature);
    const double rotations = d == 3 ? 3.0 : 1.0, c_d = d == 3 ? std::numbers::pi : 2.0;
    const RandomStream rng(17, 0);
    double mean[2][2] = {}, variance[2][2] = {};  // species i, [translation, rotation]: the estimate and its SE^2
    for (const PairCoefficients& pair : pair_coefficients(scene)) {
      const int i = pair.i, j = pair.j;
      const double mi = scene.species[i].mass, mj = scene.species[j].mass;
      const double rate = scene.species[j].density * c_d * std::pow(pair.diameter, d - 1);
      double sum[2] = {0.0, 0.0}, sum2[2] = {0.0, 0.0};  // rate x dK_tr,i and rate x dK_rot,i
      for (int t = 0; t < samples; ++t) {
        const auto normals = [&](std::uint16_t sub) {
          const RandomBlock w = rng.block(RngPurpose::collision_pair, sub, static_cast<std::uint64_t>(t),
                                          static_cast<std::uint64_t>(2 * i + j));
          Vec3 z;
          double spare = 0.0;
          standard_normal_pair(uniform_open(w[0]), uniform_open(w[1]), z.x, z.y);
          standard_normal_pair(uniform_open(w[2]), uniform_open(w[3]), z.z, spare);
          return z;
        };
        const auto planar = [&](Vec3 v) { return d == 3 ? v : Vec3{v.x, v.y, 0.0}; };
        const auto spin = [&](Vec3 s) { return d == 3 ? s : Vec3{0.0, 0.0, s.z}; };
        Vec3 vk = std::sqrt(temperature.translation[i] / mi) * planar(normals(0));
        Vec3 vl = std::sqrt(temperature.translation[j] / mj) * planar(normals(1));
        Vec3 sk = std::sqrt(temperature.rotation[i] / (kappa * mi)) * spin(normals(2));
        Vec3 sl = std::sqrt(temperature.rotation[j] / (kappa * mj)) * spin(normals(3));
        const RandomBlock u = rng.block(RngPurpose::collision_pair, 4, static_cast<std::uint64_t>(t),
                                        static_cast<std::uint64_t>(2 * i + j));
        const Vec3 g = vk - vl;
        const double g_norm = norm(g);
        const ImpactDirection id =
            d == 3 ? impact_direction<3>(
                         g, g_norm, impact_variate<3, ImpactLaw::hard_core>(uniform_open(u[0]), uniform_open(u[1])))
                   : impact_direction<2>(
                         g, g_norm, impact_variate<2, ImpactLaw::hard_core>(uniform_open(u[0]), uniform_open(u[1])));
        if (!(id.g_sigma > 0.0)) continue;  // a zero of measure zero: the sample counts with no change
        const double translational = 0.5 * mi * norm2(vk), rotational = 0.5 * kappa * mi * norm2(sk);
        rough_collision(vk, vl, sk, sl, id.sigma, id.g_sigma, pair);
        const double change[2] = {rate * g_norm * (0.5 * mi * norm2(vk) - translational),
                                  rate * g_norm * (0.5 * kappa * mi * norm2(sk) - rotational)};
        for (int a = 0; a < 2; ++a) sum[a] += change[a], sum2[a] += change[a] * change[a];
      }
      for (int a = 0; a < 2; ++a) {  // (2/d) or (2/d_r) times the mean over the pairs
        const double scale = 2.0 / (a == 0 ? d : rotations), m = sum[a] / samples;
        mean[i][a] += scale * m;
        variance[i][a] += scale * scale * (sum2[a] / samples - m * m) / samples;
      }
    }
    for (int i = 0; i < 2; ++i) {
      const double theory_rate[2] = {expected.translation[i], expected.rotation[i]};
      for (int a = 0; a < 2; ++a) {
        const double ci = confidence_lambda_p * std::sqrt(variance[i][a]);
        SCOPED_TRACE("d = " + std::to_string(d) + ", species " + std::to_string(i) +
                     (a == 0 ? ", dT/dt" : ", dT_r/dt"));
        // The bound: the CI measured today over |rate| (spheres 0.021, 0.021, 0.0073, 0.0073; disks 0.036, 0.037,
        // 0.0087, 0.0116 for species 0 and 1, translation and rotation), times 1.5.
        constexpr double relative_ci_today[2][2][2] = {{{0.0358, 0.0365}, {0.0087, 0.0116}},
                                                       {{0.0210, 0.0208}, {0.0073, 0.0073}}};
        const double bound = 1.5 * relative_ci_today[d - 2][i][a] * std::fabs(theory_rate[a]);
        EXPECT_TRUE(granmc::testing::within_ci("rate", mean[i][a], ci, theory_rate[a], bound));
      }
    }
  }
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
