#pragma once
// White-noise heating dV = sqrt(2 beta) dW (001 eq. 1, the stochastic thermostat of Montanero and Santos)
// in the time-stepped scheme: after each collision stage every velocity gets the Brownian increment of
// the step, V += sqrt(2 beta dt) xi (001 eq. 23), a first-order splitting of noise and collisions (001
// sec. 4 describes it; the event scheme, schemes/event_scheme.hpp, has no splitting error).
// Random words: purpose white_noise_kick, sub = species, step = time step, index = particle; the normals
// of 16 particles at a time in SIMD (core/batch_variates.hpp).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "kernel/core/batch_variates.hpp"
#include "kernel/core/philox_stream.hpp"
#include "kernel/effects/step_context.hpp"
#include "kernel/observe/compensated_sum.hpp"

namespace granmc {

struct WhiteNoise {
  static constexpr StepPhase phase = StepPhase::after_collisions;
  static constexpr const char* name = "white-noise";
  static constexpr bool acts_on_particles = true;

  double beta = 0.0;           // velocity diffusion coefficient (velocity^2 / time)
  std::vector<double> masses;  // m_i of the species, in scene order
  int dimension = 3;           // 2: disks, kicked in the (x, y) plane only

  [[nodiscard]] std::string explanation() const {
    return "white noise after each collision stage (splitting, O(N) per step)";
  }

  static constexpr std::size_t batch = 64;  // particles whose normals are computed together

  /// Returns the change of sum_i m_i sum_k |c_k|^2 (stored units).
  template <class State>
  double apply(State& state, const StepContext& step) const noexcept {
    CompensatedSum change;
    for (std::size_t i = 0; i < state.species.size(); ++i)
      apply_range(state.species[i], 0, state.species[i].size(), 0, static_cast<std::uint16_t>(i), state, step, change);
    return change.value();
  }

  /// Kicks particles [from, to) of the store of species i, whose particle k is particle `offset` + k of the
  /// species (a part of a system spread over ranks, schemes/rank_wave_backend.hpp; `from` and `offset`
  /// multiples of `batch`), and adds the change of m sum |c|^2 to `change`.
  template <class Store, class State>
  void apply_range(Store& store, std::size_t from, std::size_t to, std::uint64_t offset, std::uint16_t i,
                   const State& state, const StepContext& step, CompensatedSum& change) const noexcept {
    const double width = std::sqrt(2.0 * beta * step.dt) / state.scale.u();  // stored units
    const double width_z = dimension == 3 ? width : 0.0;                     // disks: no kick along z
    const double mass = masses[i];
    for_each_particle_normal<batch>(*step.rng, RngPurpose::white_noise_kick, i, state.step, offset + from, to - from,
                                    [&](std::size_t k, const Vec3& xi) {
                                      const Vec3 c = store.velocity(from + k);
                                      const Vec3 kicked = c + Vec3{width * xi.x, width * xi.y, width_z * xi.z};
                                      store.set_velocity(from + k, kicked);
                                      change.add(mass * (norm2(kicked) - norm2(c)));
                                    });
  }
};

static_assert(FreeFlightEffect<WhiteNoise>);

}  // namespace granmc
