// The collision stage's batching only reorders memory loads: candidates act in sequence, so the result
// is the same bits for every batch size, including batches in which candidates share a particle.
#include <gtest/gtest.h>

#include "kernel/collide/hard_sphere.hpp"
#include "kernel/schemes/collision_stage.hpp"
#include "kernel/schemes/initial_state.hpp"

using namespace granmc;

namespace {

struct Gas {
  Scene scene;
  RandomStream rng{77, 0};
  std::vector<PairCoefficients> pairs;
  GasState state;
  std::vector<double> omega_max;
  CollisionTally tally;

  Gas() {
    // Few particles and many candidates: batches of 64 are full of shared particles.
    scene.species = {{"a", 1.0, 1.0, 1.0, 40}, {"b", 3.0, 1.5, 0.5, 20}};
    scene.collision.restitution = {{{0.7, 0.8}, {0.8, 0.9}}};
    pairs = pair_coefficients(scene);
    state = maxwellian_state(scene, rng);
    omega_max.assign(pairs.size(), 1.0);  // low on purpose: the majorant update runs too
  }

  template <std::uint64_t batch>
  void run(int steps) {
    for (int s = 0; s < steps; ++s, ++state.step)
      for (std::size_t q = 0; q < pairs.size(); ++q)
        collide_pair<HardSphere, batch>(state, pairs[q], omega_max[q], 1001, rng, tally);
  }
};

}  // namespace

TEST(CollisionStage, ResultDoesNotDependOnTheBatchSize) {
  Gas one, many;
  one.run<1>(5);
  many.run<64>(5);
  EXPECT_EQ(one.tally.collisions, many.tally.collisions);
  EXPECT_GT(one.tally.collisions, 1000u);
  EXPECT_GT(one.tally.majorant_updates, 0u);
  EXPECT_EQ(one.tally.majorant_updates, many.tally.majorant_updates);
  EXPECT_EQ(one.tally.twice_energy_loss, many.tally.twice_energy_loss);
  EXPECT_EQ(one.omega_max, many.omega_max);
  for (std::size_t i = 0; i < 2; ++i)
    for (std::size_t k = 0; k < one.state.species[i].size(); ++k) {
      const Vec3 u = one.state.species[i].velocity(k), v = many.state.species[i].velocity(k);
      ASSERT_EQ(u.x, v.x);
      ASSERT_EQ(u.y, v.y);
      ASSERT_EQ(u.z, v.z);
    }
}
