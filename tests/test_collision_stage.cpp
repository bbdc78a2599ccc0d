// The collision stage's batching only reorders memory loads: candidates act in sequence, so the result
// is the same bits for every batch size, including batches in which candidates share a particle. The
// screen of a batch's candidates in SIMD leaves out only candidates that the full test would reject, and
// the impact directions it computes ahead for those that share no particle are the ones the full test
// would compute: the same bits as the stage without it.
#include <omp.h>

#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "kernel/collide/hard_sphere.hpp"
#include "kernel/collide/variable_hard_spheres.hpp"
#include "kernel/core/pinned_thread.hpp"
#include "kernel/core/spin_barrier.hpp"
#include "kernel/schemes/collision_stage.hpp"
#include "kernel/schemes/concurrent_rounds.hpp"
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
  std::vector<std::uint64_t> candidates{1001, 400, 300, 77};  // per step, interleaved at random

  explicit Gas(Scene s = gas_scene(few_particles)) : scene(std::move(s)) {
    pairs = pair_coefficients(scene);
    state = maxwellian_state(scene, rng);
    omega_max.assign(pairs.size(), 1.0);  // low on purpose: the majorant update runs too
    tallies.resize(pairs.size());
    candidates.resize(pairs.size());
  }

  template <std::uint64_t batch, class Kernel = HardSphere, class Shift = NoCollisionShift>
  void run(int steps, const Shift& shift = {}) {
    for (int s = 0; s < steps; ++s, ++state.step)
      collide_step<Kernel, batch, Shift>(state, pairs, omega_max, candidates, rng, tallies, Kernel{}, shift);
  }
};

/// Hard spheres with every candidate taken through the full test, one after the other.
struct HardSphereUnscreened : HardSphere {
  static constexpr bool screen_candidates = false;
};

/// Hard disks the same way.
struct HardDiskUnscreened : HardDisk {
  static constexpr bool screen_candidates = false;
};

/// Variable hard disks (the isotropic law: sigma-hat uniform on the half circle) the same way.
struct VariableHardDisksUnscreened : VariableHardDisks {
  static constexpr bool screen_candidates = false;
};

/// The mixture of few_particles as disks (run.dimension = 2).
Scene disk_scene() {
  Scene scene = gas_scene(few_particles);
  scene.run.dimension = 2;  // set after parsing: the stage reads only the pairs and the store
  return scene;
}

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
      if (!one.state.species[i].has_spins()) continue;
      const Vec3 a = one.state.species[i].spin(k), b = other.state.species[i].spin(k);
      ASSERT_EQ(a.x, b.x);
      ASSERT_EQ(a.y, b.y);
      ASSERT_EQ(a.z, b.z);
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

TEST(CollisionStage, VariableHardDisksKeepTheBitsOverBatchSizesAndTheScreen) {
  // The isotropic law in the plane (collide/impact_direction.hpp: half_circle_vectors in SIMD, the scalar
  // half_circle_vector for candidates sharing a particle): batch sizes 1 and 64, screened and not.
  Gas one(disk_scene()), many(disk_scene()), full(disk_scene());
  one.run<1, VariableHardDisks>(5);
  many.run<64, VariableHardDisks>(5);
  full.run<64, VariableHardDisksUnscreened>(5);
  for (std::size_t q = 0; q < 4; ++q) EXPECT_GT(one.tallies[q].collisions, 10u);
  expect_same_bits(one, many);
  expect_same_bits(many, full);
  for (const SpeciesStore& store : many.state.species)
    for (std::size_t k = 0; k < store.size(); ++k) ASSERT_EQ(store.velocity(k).z, 0.0);  // in the plane
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

TEST(CollisionStage, TheScreenLeavesOutOnlyRejectedCandidatesOfDisksWithTheEnskogShift) {
  // Disks: sigma-hat uniform on the circle first (core/batch_variates.hpp, unit_circle_vectors).
  const EnskogShearShift shift{0.7};
  Gas screened(disk_scene()), full(disk_scene()), one(disk_scene());
  screened.run<64, HardDisk, EnskogShearShift>(5, shift);
  full.run<64, HardDiskUnscreened, EnskogShearShift>(5, shift);
  one.run<1, HardDisk, EnskogShearShift>(5, shift);
  for (std::size_t q = 0; q < 4; ++q) EXPECT_GT(screened.tallies[q].collisions, 10u);
  EXPECT_NE(screened.tallies[0].twice_energy_shear_work, 0.0);
  expect_same_bits(screened, full);
  expect_same_bits(one, screened);
  for (const BasicSpeciesStore<double>& store : screened.state.species)
    for (std::size_t k = 0; k < store.size(); ++k) ASSERT_EQ(store.velocity(k).z, 0.0);
}

namespace {

/// Steps of the stage in concurrent rounds (schemes/concurrent_rounds.hpp) on `threads` threads.
template <class Kernel = HardSphere, class Shift = NoCollisionShift>
ConcurrentRounds run_in_rounds(Gas& gas, int steps, int threads, const Shift& shift = {}) {
  ConcurrentRounds rounds;
  rounds.threads = threads;
  for (int s = 0; s < steps; ++s, ++gas.state.step)
    collide_step_in_rounds<Kernel, 64, Shift>(gas.state, gas.pairs, gas.omega_max, gas.candidates, gas.rng, gas.tallies,
                                              rounds, Kernel{}, shift);
  return rounds;
}

/// A gas of `particles` of one species, or a mixture of 3/4 and 1/4 of them, with `per_particle` candidates per
/// particle and step (in the mixture's four pairs as in Gas).
Gas large_gas(int particles, bool mixture, int per_particle, int dimension = 3, bool rough = false) {
  Scene scene = mixture ? gas_scene(R"(
    [[species]]
    name = "a"
    particles = 2

    [[species]]
    name = "b"
    mass = 3.0
    diameter = 1.5
    density = 0.5
    particles = 1
  )")
                        : gas_scene("[[species]]\nparticles = 1\n");
  // Set after parsing, as in the large-gas screen test: the stage runs on any particle numbers.
  if (mixture) {
    scene.species[0].particles = static_cast<std::uint64_t>(3 * particles / 4);
    scene.species[1].particles = static_cast<std::uint64_t>(particles / 4);
  } else {
    scene.species[0].particles = static_cast<std::uint64_t>(particles);
  }
  scene.run.dimension = dimension;
  if (rough) {  // collide/rough_rule.hpp: the spins start Maxwellian (schemes/initial_state.cpp)
    scene.collision.tangential_restitution = 0.3;
    scene.collision.reduced_inertia = dimension == 2 ? 0.5 : 0.4;
  }
  Gas gas(scene);
  for (std::uint64_t& c : gas.candidates) c = c * static_cast<std::uint64_t>(particles * per_particle) / 1778;
  return gas;
}

/// Runs `steps` steps of a gas in order and in rounds on 2, 4 and 8 threads, from the majorants of `warm_up`
/// steps in order, and expects the same bits; returns the rounds of the 2-thread run.
template <class Kernel = HardSphere, class Shift = NoCollisionShift>
ConcurrentRounds expect_rounds_keep_the_bits(int particles, bool mixture, int warm_up, const Shift& shift = {}) {
  ConcurrentRounds two;
  constexpr int dimension = Kernel::dimension;
  constexpr bool rough = rough_kernel<Kernel>;
  Gas in_order = large_gas(particles, mixture, 4, dimension, rough);
  in_order.run<64, Kernel, Shift>(warm_up + 6, shift);
  for (int threads : {2, 4, 8}) {
    Gas in_rounds = large_gas(particles, mixture, 4, dimension, rough);
    in_rounds.run<64, Kernel, Shift>(warm_up, shift);
    const ConcurrentRounds rounds = run_in_rounds<Kernel, Shift>(in_rounds, 6, threads, shift);
    EXPECT_GT(rounds.counts.rounds, 10u);
    EXPECT_GT(rounds.counts.deferred, 0u);
    expect_same_bits(in_order, in_rounds);
    if (threads == 2) two = rounds;
  }
  return two;
}

}  // namespace

TEST(ConcurrentRounds, TheFilterKnowsEveryParticleOfAChunk) {
  // The 16384 particles of a leader's chunk of 4 x 2048 candidates among 10^7 records: the filter answers
  // "maybe" for each of them, and for about 1 in 545 of the others (core/address_filter.hpp); the bound below is
  // 1.5 times that, 20 times the binomial spread of 10^6 queries (SE 0.004 %) above it.
  SpeciesStore store(10'000'000);
  std::mt19937_64 rng(2024);
  AddressFilter filter;
  std::vector<std::size_t> chunk(16384);
  std::vector<bool> in_chunk(store.size(), false);
  for (std::size_t& k : chunk) {
    k = rng() % store.size();
    in_chunk[k] = true;
    filter.insert(AddressFilter::key(store.particle(k).address()));
  }
  for (std::size_t k : chunk) EXPECT_TRUE(filter.may_contain(store.particle(k).address()));
  std::uint64_t maybe = 0, others = 0;
  for (std::size_t k = 0; k < store.size(); k += 10) {
    if (in_chunk[k]) continue;
    ++others;
    maybe += filter.may_contain(store.particle(k).address()) ? 1 : 0;
  }
  EXPECT_LT(static_cast<double>(maybe) / static_cast<double>(others), 1.5 / 545.0);
  filter.clear();
  for (std::size_t k : chunk) EXPECT_FALSE(filter.may_contain(store.particle(k).address()));
}

TEST(ConcurrentRounds, TheBarrierShowsEveryThreadWhatTheOthersWroteBeforeIt) {
  // The rounds' barrier (core/spin_barrier.hpp), 2, 3 and 8 threads (more than the cores, so it yields): in each
  // of 2000 rounds every thread writes its slot, passes the barrier, and reads every other slot of that round.
  for (const int threads : {2, 3, 8}) {
    std::optional<SpinBarrier> barrier;
    std::vector<int> slots;
    int wrong = 0;
#pragma omp parallel num_threads(threads) reduction(+ : wrong)
    {
      const auto t = static_cast<std::size_t>(omp_get_thread_num());
#pragma omp single
      {
        barrier.emplace(omp_get_num_threads());
        slots.assign(static_cast<std::size_t>(omp_get_num_threads()), -1);
      }
      for (int round = 0; round < 2000; ++round) {
        slots[t] = round;
        barrier->arrive_and_wait();
        for (const int seen : slots) wrong += seen == round ? 0 : 1;
        barrier->arrive_and_wait();  // nobody writes the next round's slot before all have read this one's
      }
    }
    EXPECT_EQ(wrong, 0) << threads << " threads";
  }
}

#if defined(__linux__)
TEST(ConcurrentRounds, APinnedThreadRunsOnOneCpuAndGetsItsCpusBack) {
  cpu_set_t before;
  ASSERT_EQ(pthread_getaffinity_np(pthread_self(), sizeof(before), &before), 0);
  if (CPU_COUNT(&before) < 2 || omp_get_proc_bind() != omp_proc_bind_false) GTEST_SKIP() << "one CPU, or bound";
  {
    const PinnedThread pinned(1);
    cpu_set_t during;
    ASSERT_EQ(pthread_getaffinity_np(pthread_self(), sizeof(during), &during), 0);
    EXPECT_EQ(CPU_COUNT(&during), 1);
  }
  cpu_set_t after;
  ASSERT_EQ(pthread_getaffinity_np(pthread_self(), sizeof(after), &after), 0);
  EXPECT_TRUE(CPU_EQUAL(&before, &after));
}
#endif

TEST(ConcurrentRounds, KeepTheBitsWhenAMajorantIsRaised) {
  // From the low majorant of Gas: nearly every round raises it and runs again in order.
  const ConcurrentRounds rounds = expect_rounds_keep_the_bits(8000, false, 0);
  EXPECT_GT(rounds.counts.in_order, 0u);
}

TEST(ConcurrentRounds, KeepTheBitsOfOneSpecies) {
  // After warm-up steps the majorant rarely moves: most rounds run concurrently, many of the followers'
  // candidates deferred (a leader's chunk of 2048 candidates names about 40 % of 8000 particles).
  const ConcurrentRounds rounds = expect_rounds_keep_the_bits(8000, false, 4);
  EXPECT_LT(rounds.counts.in_order, rounds.counts.rounds / 2);
}

TEST(ConcurrentRounds, KeepTheBitsOfAMixture) {
  const ConcurrentRounds rounds = expect_rounds_keep_the_bits(8000, true, 4);
  EXPECT_LT(rounds.counts.in_order, rounds.counts.rounds / 2);
}

TEST(ConcurrentRounds, KeepTheBitsWithoutTheScreen) {
  const ConcurrentRounds rounds = expect_rounds_keep_the_bits<HardSphereUnscreened>(8000, true, 4);
  EXPECT_LT(rounds.counts.in_order, rounds.counts.rounds / 2);
}

TEST(ConcurrentRounds, KeepTheBitsWithTheEnskogShift) {
  const ConcurrentRounds rounds =
      expect_rounds_keep_the_bits<HardSphere, EnskogShearShift>(8000, false, 4, EnskogShearShift{0.7});
  EXPECT_LT(rounds.counts.in_order, rounds.counts.rounds / 2);
}

TEST(ConcurrentRounds, KeepTheBitsOfDisksWithTheEnskogShift) {
  const ConcurrentRounds rounds =
      expect_rounds_keep_the_bits<HardDisk, EnskogShearShift>(8000, false, 4, EnskogShearShift{0.7});
  EXPECT_LT(rounds.counts.in_order, rounds.counts.rounds / 2);
}

TEST(ConcurrentRounds, KeepTheBitsOfRoughParticles) {
  // Rough spheres and disks, one species and a mixture: the spins are kept and restored with the velocities.
  for (const bool mixture : {false, true}) {
    const ConcurrentRounds spheres = expect_rounds_keep_the_bits<RoughHardSphere>(8000, mixture, 4);
    EXPECT_LT(spheres.counts.in_order, spheres.counts.rounds / 2);
    expect_rounds_keep_the_bits<RoughHardDisk>(8000, mixture, 4);
  }
}

TEST(ConcurrentRounds, KeepTheBitsOfRoughParticlesWhenAMajorantIsRaised) {
  // From the low majorant of Gas: rounds are undone, spins with velocities, and run again in order.
  const ConcurrentRounds rounds = expect_rounds_keep_the_bits<RoughHardSphere>(8000, false, 0);
  EXPECT_GT(rounds.counts.in_order, 0u);
}
