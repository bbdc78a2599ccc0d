// The same scene and seed give bit-identical results with 1 and 2 OpenMP threads: random numbers are
// addressed by (seed, replica, step, purpose), never by thread, and replica statistics sum in order.
#include <cstring>
#include <string>

#include <gtest/gtest.h>

#include "kernel/setup/run_scene.hpp"

using namespace granmc;

namespace {

Scene small_cooling_scene() {
  Scene s;
  s.run.seed = 12345;
  s.run.replicas = 5;  // odd, so the two threads get unequal shares
  s.run.t_end = 2.0;
  s.run.dt = 0.01;
  s.run.samples = 10;
  s.species.push_back({"a", 1.0, 1.0, 1.0, 3000});
  s.collision.restitution = {{{0.7, 0.7}, {0.7, 0.7}}};
  return s;
}

template <class T>
bool bit_identical(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

/// The time-step-free white-noise scheme (hard spheres, with the majorant) and the time-stepped one with
/// white noise.
Scene small_heated_scene(Method method) {
  Scene s = small_cooling_scene();
  s.run.method = method;
  s.collision.rate = 0.3;
  s.thermostat.kind = ThermostatKind::white_noise;
  s.thermostat.beta = 0.5;
  return s;
}

/// Enskog uniform shear flow with 003's relaxation term (shift, pressure tensor, replacements).
Scene small_sheared_scene() {
  Scene s = small_cooling_scene();
  s.species[0].density = 6.0 * 0.2 / std::numbers::pi;  // phi = pi n sigma^3 / 6 = 0.2
  s.collision.packing_fraction = 0.2;
  s.thermostat.kind = ThermostatKind::gaussian;
  s.shear_rate = 0.5;
  s.relaxation = true;
  return s;
}

std::string scheme_name(int which) {
  const char* names[] = {"Cooling", "EventWhiteNoise", "DsmcWhiteNoise", "EnskogShearRelaxation"};
  return names[which];
}

}  // namespace

class ThreadIdentity : public ::testing::TestWithParam<int> {};

INSTANTIATE_TEST_SUITE_P(Schemes, ThreadIdentity, ::testing::Values(0, 1, 2, 3),
                         [](const auto& info) { return scheme_name(info.param); });

namespace {

Scene scene_for(int which) {
  if (which == 1) return small_heated_scene(Method::event);
  if (which == 2) return small_heated_scene(Method::dsmc);
  if (which == 3) return small_sheared_scene();
  return small_cooling_scene();
}

}  // namespace

TEST_P(ThreadIdentity, OneAndTwoThreadsGiveTheSameBits) {
  const Scene scene = scene_for(GetParam());
  RunOptions one, two;
  one.threads = 1;
  two.threads = 2;
  const RunResult a = run_scene(scene, one);
  const RunResult b = run_scene(scene, two);
  ASSERT_EQ(a.replicas.size(), b.replicas.size());
  for (std::size_t r = 0; r < a.replicas.size(); ++r) {
    const ReplicaSeries& x = a.replicas[r];
    const ReplicaSeries& y = b.replicas[r];
    EXPECT_TRUE(bit_identical(x.temperature, y.temperature)) << "replica " << r;
    EXPECT_TRUE(bit_identical(x.species[0].a2, y.species[0].a2)) << "replica " << r;
    EXPECT_TRUE(bit_identical(x.momentum, y.momentum)) << "replica " << r;
    EXPECT_TRUE(bit_identical(x.collisions, y.collisions)) << "replica " << r;
    EXPECT_EQ(x.candidates, y.candidates);
    ASSERT_EQ(x.pressure_collisional.size(), y.pressure_collisional.size());
    EXPECT_EQ(std::memcmp(x.pressure_collisional.data(), y.pressure_collisional.data(),
                          x.pressure_collisional.size() * sizeof(SymTensor)),
              0);
  }
  // Replicas are different realisations, not copies.
  EXPECT_NE(a.replicas[0].temperature.back(), a.replicas[1].temperature.back());
}

TEST(SeedIdentity, SeedChangesTheRealisation) {
  Scene scene = small_cooling_scene();
  const RunResult a = run_scene(scene, {});
  scene.run.seed = 12346;
  const RunResult b = run_scene(scene, {});
  EXPECT_NE(a.replicas[0].temperature.back(), b.replicas[0].temperature.back());
}
