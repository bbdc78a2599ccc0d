// Instructions per candidate of the collision stage, counted rather than timed (the shared host's noise
// does not enter): collide_step<HardSphere> and the hand-specialised kernel (perf/hand_specialised_hcs.hpp)
// each run 20 steps of 10^5 candidates on the same gas of 10^5 particles (alpha = 0.8), each inside a
// function of its own, so that callgrind's inclusive count of that function divided by 2 10^6 is the
// count per candidate. The commands (docs/notebook/2026-12-06-performance-history.md, "Instructions per
// candidate", has the counts they gave):
//
//   cmake -S . -B build-vg -DCMAKE_BUILD_TYPE=Release -DGRANMC_BENCH=ON -DGRANMC_NATIVE=OFF
//         -DCMAKE_CXX_FLAGS="-march=x86-64-v3 -g"          (one line; valgrind does not run AVX-512 code)
//   cmake --build build-vg --target count_stage
//   valgrind --tool=callgrind --callgrind-out-file=cg.out build-vg/bin/count_stage
//   callgrind_annotate --inclusive=yes cg.out | grep -E "count_(library|hand)"
//
// It prints the final majorants of both, which must be equal (the same bits, as bench_effects checks).
#include <cstdint>
#include <cstdio>
#include <vector>

#include "kernel/collide/hard_sphere.hpp"
#include "kernel/collide/pair_coefficients.hpp"
#include "kernel/core/aligned_buffer.hpp"
#include "kernel/core/philox_stream.hpp"
#include "kernel/core/scene.hpp"
#include "kernel/schemes/collision_stage.hpp"
#include "kernel/schemes/initial_state.hpp"
#include "perf/hand_specialised_hcs.hpp"

namespace {

using namespace granmc;

constexpr std::int64_t kParticles = 100'000;
constexpr std::uint64_t kCandidates = 100'000;  // per step
constexpr int kSteps = 20;
constexpr double kRestitution = 0.8;

__attribute__((noinline)) void count_library(GasState& state, const std::vector<PairCoefficients>& pairs,
                                             double& omega_max, const RandomStream& rng) {
  for (int s = 0; s < kSteps; ++s, ++state.step) {
    CollisionTally tally;
    collide_step<HardSphere>(state, pairs, {&omega_max, 1}, {&kCandidates, 1}, rng, {&tally, 1});
  }
}

__attribute__((noinline)) void count_hand(perf::HandRecord* v, std::size_t n, double& omega_max,
                                          const RandomStream& rng, const perf::HandConstants& c) {
  for (int s = 0; s < kSteps; ++s)
    perf::hand_collide(v, n, omega_max, kCandidates, rng, static_cast<std::uint64_t>(s), c);
}

}  // namespace

int main() {
  Scene scene;
  scene.run.seed = 5;
  scene.run.t_end = 1.0;
  scene.run.dt = 0.01;
  scene.species.push_back({"grains", 1.0, 1.0, 1.0, kParticles});
  scene.collision.kernel = CollisionKernel::hard_sphere;
  scene.collision.restitution = {{{kRestitution, kRestitution}, {kRestitution, kRestitution}}};
  scene.initial_temperature = 1.0;
  const RandomStream rng(scene.run.seed, 0);
  GasState state = maxwellian_state(scene, rng);
  const std::vector<PairCoefficients> pairs = pair_coefficients(scene);
  AlignedBuffer<perf::HandRecord> hand(state.species[0].size());
  for (std::size_t k = 0; k < hand.size(); ++k) {
    const Vec3 v = state.species[0].velocity(k);
    hand[k] = {v.x, v.y, v.z, 0.0};
  }
  double omega_library = majorant_bound<NoCollisionShift>(HardSphere{}, pairs[0], 11.0);  // about 2 max |c|
  double omega_hand = omega_library;
  count_library(state, pairs, omega_library, rng);
  count_hand(hand.data(), hand.size(), omega_hand, rng, perf::HandConstants::of(kRestitution, 1.0, 1.0, 1.0));
  std::printf("majorants: library %.17g, hand %.17g (%s)\n", omega_library, omega_hand,
              omega_library == omega_hand ? "equal" : "DIFFERENT");
  return omega_library == omega_hand ? 0 : 1;
}
