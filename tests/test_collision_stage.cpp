// The collision stage's batching only reorders memory loads: candidates act in sequence, so the result
// is the same bits for every batch size, including batches in which candidates share a particle. The
// screen of a batch's candidates in SIMD leaves out only candidates that the full test would reject, and
// the impact directions it computes ahead for those that share no particle are the ones the full test
// would compute: the same bits as the stage without it.
#include <string>
#include <string_view>
#include <utility>

#include <gtest/gtest.h>

#include "kernel/collide/hard_sphere.hpp"
#include "kernel/schemes/collision_stage.hpp"
#include "kernel/schemes/initial_state.hpp"
#include "tests/test_scenes.hpp"

using namespace granmc;
using granmc::testing::scene_from_toml;

namespace {

/// A gas of the `species` tables (TOML) for the collision stage alone: the tests call collide_step
/// themselves, so the run (t_end, dt) is never read; the parser needs it all the same.
Scene gas_scene(std::string_view species) {
  constexpr std::string_view text = R"(
    [run]
    t_end = 1.0
    dt = 1.0

    [collision]
    restitution = [[0.7, 0.8], [0.8, 0.9]]
  )";
  return scene_from_toml(std::string(text) + std::string(species));
}

/// By default few particles and many candidates: batches of 64 are full of shared particles.
constexpr std::string_view few_particles = R"(
  [[species]]
  name = "a"
  particles = 40

  [[species]]
  name = "b"
  mass = 3.0
  diameter = 1.5
  density = 0.5
  particles = 20
)";

struct Gas {
  Scene scene;
  RandomStream rng{77, 0};
  std::vector<PairCoefficients> pairs;
  GasState state;
  std::vector<double> omega_max;
  std::vector<CollisionTally> tallies;

  explicit Gas(Scene s = gas_scene(few_particles)) : scene(std::move(s)) {
    pairs = pair_coefficients(scene);
    state = maxwellian_state(scene, rng);
    omega_max.assign(pairs.size(), 1.0);  // low on purpose: the majorant update runs too
    tallies.resize(pairs.size());
  }

  template <std::uint64_t batch, class Kernel = HardSphere, class Shift = NoCollisionShift>
  void run(int steps, const Shift& shift = {}) {
    std::vector<std::uint64_t> candidates{1001, 400, 300, 77};  // interleaved at random
    candidates.resize(pairs.size());
    for (int s = 0; s < steps; ++s, ++state.step)
      collide_step<Kernel, batch, Shift>(state, pairs, omega_max, candidates, rng, tallies, Kernel{}, shift);
  }
};

/// Hard spheres with every candidate taken through the full test, one after the other.
struct HardSphereUnscreened : HardSphere {
  static constexpr bool screen_candidates = false;
};

void expect_same_bits(const Gas& one, const Gas& other) {
  for (std::size_t q = 0; q < one.pairs.size(); ++q) {
    EXPECT_EQ(one.tallies[q].collisions, other.tallies[q].collisions);
    EXPECT_EQ(one.tallies[q].majorant_updates, other.tallies[q].majorant_updates);
    EXPECT_EQ(one.tallies[q].twice_energy_loss, other.tallies[q].twice_energy_loss);
    EXPECT_EQ(one.tallies[q].twice_energy_shear_work, other.tallies[q].twice_energy_shear_work);
  }
  EXPECT_EQ(one.omega_max, other.omega_max);
  for (std::size_t i = 0; i < one.state.species.size(); ++i)
    for (std::size_t k = 0; k < one.state.species[i].size(); ++k) {
      const Vec3 u = one.state.species[i].velocity(k), v = other.state.species[i].velocity(k);
      ASSERT_EQ(u.x, v.x);
      ASSERT_EQ(u.y, v.y);
      ASSERT_EQ(u.z, v.z);
    }
}

}  // namespace

TEST(CollisionStage, ResultDoesNotDependOnTheBatchSize) {
  Gas one, many;
  one.run<1>(5);
  many.run<64>(5);
  for (std::size_t q = 0; q < 4; ++q) {
    EXPECT_GT(one.tallies[q].collisions, 10u);
    EXPECT_GT(one.tallies[q].majorant_updates, 0u);
  }
  EXPECT_EQ(one.tallies[0].candidates, 5u * 1001u);
  EXPECT_EQ(one.tallies[3].candidates, 5u * 77u);
  expect_same_bits(one, many);
}

TEST(CollisionStage, TheScreenLeavesOutOnlyRejectedCandidates) {
  // 60 particles: nearly every batch of 64 has candidates sharing a particle with an earlier one.
  Gas screened, full;
  screened.run<64>(5);
  full.run<64, HardSphereUnscreened>(5);
  expect_same_bits(screened, full);
  // and with a majorant that starts far too high, so that most candidates are screened out
  Gas high, high_full;
  high.omega_max.assign(4, 50.0);
  high_full.omega_max.assign(4, 50.0);
  high.run<64>(5);
  high_full.run<64, HardSphereUnscreened>(5);
  EXPECT_GT(high.tallies[0].collisions, 10u);
  expect_same_bits(high, high_full);
}

TEST(CollisionStage, TheScreenLeavesOutOnlyRejectedCandidatesInALargeGas) {
  // Thousands of particles: most candidates that pass the screen share no particle with an earlier one of
  // their batch, and their impact directions are computed a register at a time before the batch collides.
  // A mixture and one species (the stage's one-pair form).
  Scene mixture = gas_scene(R"(
    [[species]]
    name = "a"
    particles = 3000

    [[species]]
    name = "b"
    mass = 3.0
    diameter = 1.5
    density = 0.5
    particles = 1500
  )");
  // Set after parsing: N_0/N_1 = 3 with n_0/n_1 = 2, which the scene file refuses (unequal particle weights);
  // the stage runs on any particle numbers, and these are the ones the test has always used.
  mixture.species[1].particles = 1000;
  const Scene one_species = gas_scene(R"(
    [[species]]
    particles = 4000
  )");
  for (const Scene& gas : {mixture, one_species}) {
    Gas screened(gas), full(gas), one(gas);
    screened.run<64>(5);
    full.run<64, HardSphereUnscreened>(5);
    one.run<1>(5);
    EXPECT_GT(screened.tallies[0].collisions, 100u);
    EXPECT_GT(screened.tallies[0].majorant_updates, 0u);
    expect_same_bits(screened, full);
    expect_same_bits(screened, one);
  }
}

TEST(CollisionStage, TheScreenLeavesOutOnlyRejectedCandidatesWithTheEnskogShift) {
  // The paper's order (sigma-hat first, omega = prefactor Theta(g.sigma) g.sigma with the shifted g): half
  // the candidates separate along sigma-hat, and the screen must leave out only those and the rejected.
  const EnskogShearShift shift{0.7};
  Gas screened, full;
  screened.run<64, HardSphere, EnskogShearShift>(5, shift);
  full.run<64, HardSphereUnscreened, EnskogShearShift>(5, shift);
  EXPECT_GT(screened.tallies[0].collisions, 10u);
  EXPECT_NE(screened.tallies[0].twice_energy_shear_work, 0.0);
  expect_same_bits(screened, full);
  Gas one;
  one.run<1, HardSphere, EnskogShearShift>(5, shift);
  expect_same_bits(one, screened);
}
