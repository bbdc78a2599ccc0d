// The same scene and seed give bit-identical results with 1, 2 and 4 OpenMP threads (2 and 4 each against
// 1): random numbers are addressed by (seed, replica, step, purpose), never by thread, and replica
// statistics sum in order.
#include <cstdint>
#include <cstring>
#include <numbers>
#include <string>
#include <string_view>

#include <gtest/gtest.h>

#include "kernel/schemes/replica_runner.hpp"
#include "kernel/setup/run_scene.hpp"
#include "tests/test_scenes.hpp"

using namespace granmc;
using granmc::testing::scene_from_toml;

namespace {

Scene small_cooling_scene(std::uint64_t seed = 12345) {
  constexpr std::string_view text = R"(
    [run]
    seed = ${seed}
    replicas = 5  # odd, so that 2 and 4 threads get unequal shares
    t_end = 2.0
    dt = 0.01
    samples = 10

    [[species]]
    particles = 3000

    [collision]
    restitution = 0.7
  )";
  return scene_from_toml(text, {{"seed", seed}});
}

/// The same bytes; two empty vectors are identical (memcmp must not see their null data pointers).
template <class T>
bool bit_identical(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

/// The time-step-free white-noise scheme (hard spheres, with the majorant) and the time-stepped one with
/// white noise; `method` is "event" or "dsmc".
Scene small_heated_scene(const char* method) {
  constexpr std::string_view text = R"(
    [run]
    method = "${method}"
    seed = 12345
    replicas = 5
    t_end = 2.0
    dt = 0.01
    samples = 10

    [[species]]
    particles = 3000

    [collision]
    rate = 0.3
    restitution = 0.7

    [thermostat]
    kind = "white-noise"
    beta = 0.5
  )";
  return scene_from_toml(text, {{"method", method}});
}

/// Weighted particles (SWPM) with white noise and hard spheres: splitting, weight transfers and reductions.
Scene small_weighted_scene() {
  constexpr std::string_view text = R"(
    [run]
    method = "event"
    seed = 12345
    replicas = 5
    t_end = 1.0
    samples = 10

    [[species]]
    particles = 1000

    [collision]
    kernel = "hard-sphere"
    rate = 0.3
    restitution = 0.7

    [thermostat]
    kind = "white-noise"
    beta = 0.5

    [output]
    histogram = { shells = 24, radius = 12.0 }

    [weights]
    scheme = "swpm"
    particles_per_shell = 16
  )";
  return scene_from_toml(text, {});
}

/// Enskog uniform shear flow with 003's relaxation term (shift, pressure tensor, replacements).
Scene small_sheared_scene() {
  constexpr std::string_view text = R"(
    [run]
    seed = 12345
    replicas = 5
    t_end = 2.0
    dt = 0.01
    samples = 10

    [[species]]
    density = ${density}  # phi = pi n sigma^3 / 6 = 0.2
    particles = 3000

    [collision]
    restitution = 0.7
    packing_fraction = 0.2

    [thermostat]
    kind = "gaussian"

    [shear]
    rate = 0.5

    [relaxation]
    enabled = true
  )";
  return scene_from_toml(text, {{"density", 6.0 * 0.2 / std::numbers::pi}});
}

/// Rough disks under white noise split with the spins (collide/rough_rule.hpp, effects/white_noise.hpp).
Scene small_rough_scene() {
  constexpr std::string_view text = R"(
    [run]
    dimension = 2
    seed = 2718
    replicas = 5
    t_end = 1.5
    dt = 0.005
    samples = 6

    [[species]]
    density = 4.0  # disks collide less often than spheres: enough candidates per step for 4 threads' rounds
    particles = 3000

    [collision]
    restitution = 0.8
    tangential_restitution = 0.2

    [thermostat]
    kind = "white-noise"
    beta = 1.0
    rotational_share = 0.5
  )";
  return scene_from_toml(text, {});
}

std::string scheme_name(int which) {
  const char* names[] = {
      "Cooling", "EventWhiteNoise", "DsmcWhiteNoise", "EnskogShearRelaxation", "WeightedWhiteNoise", "RoughWhiteNoise"};
  return names[which];
}

}  // namespace

class ThreadIdentity : public ::testing::TestWithParam<int> {};

INSTANTIATE_TEST_SUITE_P(Schemes, ThreadIdentity, ::testing::Values(0, 1, 2, 3, 4, 5),
                         [](const auto& info) { return scheme_name(info.param); });

namespace {

Scene scene_for(int which) {
  if (which == 1) return small_heated_scene("event");
  if (which == 2) return small_heated_scene("dsmc");
  if (which == 3) return small_sheared_scene();
  if (which == 4) return small_weighted_scene();
  if (which == 5) return small_rough_scene();
  return small_cooling_scene();
}

}  // namespace

TEST_P(ThreadIdentity, TwoAndFourThreadsGiveTheBitsOfOne) {
  const Scene scene = scene_for(GetParam());
  RunOptions one;
  one.threads = 1;
  const RunResult a = run_scene(scene, one);
  // 4 threads on fewer cores too: OpenMP runs the 4 (num_threads), time-sliced, and the 5 replicas are
  // shared 2-1-1-1 in an order that depends on the scheduling.
  for (const int threads : {2, 4}) {
    SCOPED_TRACE(std::to_string(threads) + " threads against 1");
    RunOptions many;
    many.threads = threads;
    const RunResult b = run_scene(scene, many);
    EXPECT_EQ(b.threads, threads);
    ASSERT_EQ(a.replicas.size(), b.replicas.size());
    for (std::size_t r = 0; r < a.replicas.size(); ++r) {
      const ReplicaSeries& x = a.replicas[r];
      const ReplicaSeries& y = b.replicas[r];
      EXPECT_TRUE(bit_identical(x.temperature, y.temperature)) << "replica " << r;
      EXPECT_TRUE(bit_identical(x.species[0].a2, y.species[0].a2)) << "replica " << r;
      EXPECT_TRUE(bit_identical(x.species[0].rotational_temperature, y.species[0].rotational_temperature))
          << "replica " << r;
      EXPECT_TRUE(bit_identical(x.momentum, y.momentum)) << "replica " << r;
      EXPECT_TRUE(bit_identical(x.collisions, y.collisions)) << "replica " << r;
      EXPECT_EQ(x.candidates, y.candidates);
      ASSERT_EQ(x.shear.has_value(), y.shear.has_value());
      if (x.shear) {
        EXPECT_TRUE(bit_identical(x.shear->pressure_collisional, y.shear->pressure_collisional)) << "replica " << r;
      }
      EXPECT_TRUE(bit_identical(x.species[0].speed_counts, y.species[0].speed_counts)) << "replica " << r;
      ASSERT_EQ(x.weighted.has_value(), y.weighted.has_value());
      if (x.weighted) {
        EXPECT_TRUE(bit_identical(x.weighted->particles, y.weighted->particles)) << "replica " << r;
        EXPECT_EQ(x.weighted->reductions, y.weighted->reductions);
      }
    }
  }
  // Replicas are different realisations, not copies.
  EXPECT_NE(a.replicas[0].temperature.back(), a.replicas[1].temperature.back());
}

TEST(SeedIdentity, SeedChangesTheRealisation) {
  const RunResult a = run_scene(small_cooling_scene(12345), {});
  const RunResult b = run_scene(small_cooling_scene(12346), {});
  EXPECT_NE(a.replicas[0].temperature.back(), b.replicas[0].temperature.back());
}

// One replica, so the threads go inside it: the concurrent rounds of the time-stepped scheme's collision stage
// (schemes/concurrent_rounds.hpp) and of the event scheme's candidates (schemes/event_rounds.hpp), on enough
// particles that the rounds run rather than fall back to one thread.
class OneReplicaThreadIdentity : public ::testing::TestWithParam<int> {};

INSTANTIATE_TEST_SUITE_P(Schemes, OneReplicaThreadIdentity, ::testing::Values(0, 1, 2, 3, 5),
                         [](const auto& info) { return scheme_name(info.param); });

TEST_P(OneReplicaThreadIdentity, TwoAndFourThreadsInsideTheReplicaGiveTheBitsOfOne) {
  Scene scene = scene_for(GetParam());
  scene.run.replicas = 1;
  scene.run.t_end = 0.5;
  scene.run.dt = 0.02;
  scene.species[0].particles = 20000;
  RunOptions one;
  one.threads = 1;
  const RunResult a = run_scene(scene, one);
  EXPECT_EQ(a.threads_per_replica, 1);
  for (const int threads : {2, 4}) {
    SCOPED_TRACE(std::to_string(threads) + " threads against 1");
    RunOptions many;
    many.threads = threads;
    many.threads_per_replica = threads;
    const RunResult b = run_scene(scene, many);
    EXPECT_EQ(b.threads_per_replica, threads);
    EXPECT_GT(b.rounds.rounds, 0u) << "the rounds ran, not only the in-order fallback";
    const ReplicaSeries& x = a.replicas[0];
    const ReplicaSeries& y = b.replicas[0];
    EXPECT_TRUE(bit_identical(x.temperature, y.temperature));
    EXPECT_TRUE(bit_identical(x.species[0].a2, y.species[0].a2));
    EXPECT_TRUE(bit_identical(x.species[0].rotational_temperature, y.species[0].rotational_temperature));
    EXPECT_TRUE(bit_identical(x.momentum, y.momentum));
    EXPECT_TRUE(bit_identical(x.collisions, y.collisions));
    EXPECT_EQ(x.candidates, y.candidates);
    ASSERT_EQ(x.shear.has_value(), y.shear.has_value());
    if (x.shear) {
      EXPECT_TRUE(bit_identical(x.shear->pressure_collisional, y.shear->pressure_collisional));
    }
  }
}

TEST(ThreadShare, ByDefaultThreadsGoInsideOnlyReplicasLargeEnoughForTheRounds) {
  Scene scene = small_cooling_scene();
  scene.run.replicas = 1;
  RunOptions options;
  options.threads = 4;
  const auto inside = [&](std::int64_t particles, const ThreadsInside& rule) {
    scene.species[0].particles = particles;
    return share_threads(scene, options, rule).inside;
  };
  const auto least = static_cast<std::int64_t>(stepped_rounds_inside.least_particles);
  EXPECT_EQ(inside(least - 1, stepped_rounds_inside), 1);
  EXPECT_EQ(inside(least, stepped_rounds_inside), 4);
  EXPECT_EQ(inside(least, one_thread_inside), 1);
  const auto event_least = static_cast<std::int64_t>(event_rounds_inside.least_particles);
  EXPECT_EQ(inside(event_least - 1, event_rounds_inside), 1);
  EXPECT_EQ(inside(event_least, event_rounds_inside), 4);
  // Two species count together; the replicas take their threads first.
  scene.species.push_back(scene.species[0]);
  scene.species[0].particles = scene.species[1].particles = least / 2;
  EXPECT_EQ(share_threads(scene, options, stepped_rounds_inside).inside, 4);
  scene.run.replicas = 2;
  EXPECT_EQ(share_threads(scene, options, stepped_rounds_inside).concurrent, 2);
  EXPECT_EQ(share_threads(scene, options, stepped_rounds_inside).inside, 2);
  // Asked for: that many (at most what is left over), whatever the size.
  scene.species.pop_back();
  scene.species[0].particles = 1000;
  options.threads_per_replica = 2;
  EXPECT_EQ(share_threads(scene, options, stepped_rounds_inside).inside, 2);
  options.threads_per_replica = 1;
  scene.species[0].particles = least;
  EXPECT_EQ(share_threads(scene, options, stepped_rounds_inside).inside, 1);
}
