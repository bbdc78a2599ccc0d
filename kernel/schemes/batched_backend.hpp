#pragma once
// The collision backend of one process: every particle of the replica is held here, the collision stage
// is the batched stage of schemes/collision_stage.hpp, on the replica's threads in concurrent rounds
// (schemes/concurrent_rounds.hpp, the same bits for any thread count), and sums over particles run over all of
// them at once.
// The time stepper (schemes/dsmc.hpp) asks its backend for the initial state, the sums, the collisions of a
// step, the effects and the observations; schemes/rank_wave_backend.hpp is the other backend.
#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "kernel/collide/pair_coefficients.hpp"
#include "kernel/core/philox_stream.hpp"
#include "kernel/core/scene.hpp"
#include "kernel/effects/step_context.hpp"
#include "kernel/observe/gas_observation.hpp"
#include "kernel/schemes/collision_stage.hpp"
#include "kernel/schemes/concurrent_rounds.hpp"
#include "kernel/schemes/gas_state.hpp"
#include "kernel/schemes/initial_state.hpp"

namespace granmc {

class BatchedBackend {
 public:
  /// `threads`: the replica's threads for its collision stage.
  explicit BatchedBackend(const Scene&, int threads = 1) noexcept { rounds_.threads = threads; }

  /// The Maxwellian start (000 eq. 13) with zero momentum per species, on the replica's threads.
  template <class Real>
  BasicGasState<Real> initial_state(const Scene& scene, const RandomStream& rng) const {
    return maxwellian_state<Real>(scene, rng, rounds_.threads);
  }

  /// The moments of every species about the origin.
  template <class Real>
  std::vector<SpeciesMoments> moments(const BasicGasState<Real>& state) const {
    return gas_moments(state);
  }

  /// The largest |c|^2 of the store.
  template <class Store>
  double largest_speed2(const Store& store) const {
    double max2 = 0.0;
    store.for_each_velocity([&](const Vec3& c) { max2 = std::max(max2, norm2(c)); });
    return max2;
  }

  /// The step's candidates of every ordered pair, in batches (schemes/collision_stage.hpp), in rounds over the
  /// replica's threads.
  template <class Kernel, class Shift, class Real>
  void collide(BasicGasState<Real>& state, std::span<const PairCoefficients> pairs, std::span<double> omega_max,
               std::span<const std::uint64_t> candidates, const RandomStream& rng, std::span<CollisionTally> tallies,
               const Kernel& kernel, const Shift& shift) {
    collide_step_in_rounds<Kernel>(state, pairs, omega_max, candidates, rng, tallies, rounds_, kernel, shift);
  }

  /// The rounds so far and how many ran again in order.
  [[nodiscard]] const ConcurrentRounds& rounds() const noexcept { return rounds_; }

  /// An effect over the step, on all particles.
  template <class Effect, class Real>
  double apply(const Effect& effect, BasicGasState<Real>& state, const StepContext& step) const noexcept {
    return effect.apply(state, step);
  }

  /// Appends one observation; returns the totals it summed.
  template <class Real>
  GasTotals observe(const Scene& scene, const BasicGasState<Real>& state, ReplicaSeries& series, bool histogram) const {
    return observe_gas(scene, state, series, histogram);
  }

 private:
  ConcurrentRounds rounds_;
};

}  // namespace granmc
