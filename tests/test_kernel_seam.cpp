// The seam a new collision kernel goes through (docs/developer-guide/architecture.md, "Adding things"): a kernel is
// one struct with the time-stepped and the event face of collide/collision_kernel.hpp. This test writes Maxwell's law
// again as a new kernel would be written, outside the library, and runs it through the one time stepper and the event
// scheme: both give the bits of the library's MaxwellPseudomolecules. A kernel that misses a member of either face
// fails the static_asserts below at compile time.
#include <cmath>
#include <cstddef>
#include <cstring>
#include <span>
#include <vector>

#include <gtest/gtest.h>

#include "kernel/collide/collision_kernel.hpp"
#include "kernel/collide/maxwell_pseudomolecules.hpp"
#include "kernel/effects/white_noise.hpp"
#include "kernel/schemes/dsmc.hpp"
#include "kernel/schemes/event_scheme.hpp"
#include "tests/test_scenes.hpp"

using namespace granmc;
using granmc::testing::scene_from_toml;

namespace {

/// B = rate (001 eq. 7), the example kernel of docs/developer-guide/architecture.md.
struct ConstantRate {
  static constexpr const char* name = "constant-rate";
  static constexpr int dimension = 3;
  static constexpr ImpactLaw impact_law = ImpactLaw::isotropic;  // e uniform (001 eq. 4)
  static constexpr const char* explanation = "a constant rate, written as a new kernel";
  static constexpr double lambda = 0.0;  // omega ~ |g|^0
  template <class Scene>
  static ConstantRate from_scene(const Scene&) noexcept {
    return {};
  }
  // Time-stepped face: omega_kl = prefactor Theta(g.sigma) (g.sigma) / |g|, whose mean over sigma-hat is 1/4.
  static double rate(double g_sigma, double g2) noexcept { return g_sigma / std::sqrt(g2); }
  static double bound(double) noexcept { return 1.0; }
  static constexpr bool screen_candidates = false;
  static double mean_rate(double) noexcept { return 0.25; }
  static double mean_bound(double) noexcept { return 0.25; }
  // Event face: every candidate collides.
  static constexpr bool constant_rate = true;
  template <std::size_t N>
  static void acceptance_thresholds(std::span<double, N>) noexcept {}
};

static_assert(SteppedKernel<ConstantRate>);
static_assert(EventKernel<ConstantRate>);

const Scene scene = scene_from_toml(R"(
  [run]
  seed = 5
  t_end = 1.0
  dt = 0.01
  samples = 4
  [[species]]
  particles = 2000
  [collision]
  kernel = "maxwell"
  rate = 0.3
  restitution = 0.7
  [thermostat]
  kind = "white-noise"
  beta = 0.5
)");

template <class Sim>
std::vector<double> temperatures(Sim& sim) {
  std::vector<double> out;
  for (double t : {0.25, 0.5, 1.0}) {
    sim.advance_to(t);
    double sum = 0.0;
    sim.state().species[0].for_each_velocity([&](const Vec3& c) { sum += norm2(c); });
    out.push_back(sum);
  }
  return out;
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

}  // namespace

TEST(KernelSeam, ANewKernelRunsThroughTheTimeStepper) {
  const WhiteNoise noise{0.5, {1.0}};
  Dsmc<ConstantRate, WhiteNoise> written(scene, 0, noise);
  Dsmc<MaxwellPseudomolecules, WhiteNoise> library(scene, 0, noise);
  const std::vector<double> a = temperatures(written), b = temperatures(library);
  EXPECT_TRUE(same_bits(a, b));
  EXPECT_EQ(written.tally().collisions, library.tally().collisions);
  EXPECT_GT(written.tally().collisions, 1000u);
}

TEST(KernelSeam, ANewKernelRunsThroughTheEventScheme) {
  EventScheme<ConstantRate> written(scene, 0, ConstantRate{});
  EventScheme<MaxwellPseudomolecules> library(scene, 0, MaxwellPseudomolecules{});
  const std::vector<double> a = temperatures(written), b = temperatures(library);
  EXPECT_TRUE(same_bits(a, b));
  EXPECT_EQ(written.tally().collisions, library.tally().collisions);
  EXPECT_GT(written.tally().collisions, 1000u);
}
