#pragma once
// White-noise heating dV = sqrt(2 beta) dW (001 eq. 1, the stochastic thermostat of Montanero and Santos)
// in the time-stepped scheme: after each collision stage every velocity gets the Brownian increment of
// the step, V += sqrt(2 beta dt) xi (001 eq. 23), a first-order splitting of noise and collisions (001
// sec. 4 describes it; the event scheme, schemes/event_scheme.hpp, has no splitting error).
// Random words: purpose white_noise_kick, sub = species, step = time step, index = particle; the normals
// of 16 particles at a time in SIMD (core/batch_variates.hpp).
//
// Rough particles (collide/rough_rule.hpp) can have a share epsilon of the injected power go into rotation, the
// splitting thermostat of Megias and Santos, Front. Phys. 10 (2022) 971671: the velocities get
// sqrt(2 beta (1 - epsilon) dt) xi, a power (d/2) m 2 beta (1 - epsilon) per particle, and the spins
// s = (sigma/2) omega get sqrt(2 beta epsilon (d / d_r) dt / kappa) xi per rotational component (d_r = 3 for spheres,
// the z component for disks), whose power kappa m (d_r / 2) (2 beta epsilon d / (d_r kappa)) = d m beta epsilon
// makes up the rest. Their words: purpose white_noise_spin_kick, as for the velocities.
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

  double beta = 0.0;              // velocity diffusion coefficient (velocity^2 / time)
  std::vector<double> masses;     // m_i of the species, in scene order
  int dimension = 3;              // 2: disks, kicked in the (x, y) plane only
  double rotational_share = 0.0;  // epsilon: the share of the power that kicks the spins (rough particles)
  double reduced_inertia = 0.4;   // kappa of the rough particles

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
    const double width = std::sqrt(2.0 * beta * (1.0 - rotational_share) * step.dt) / state.scale.u();  // stored
    const double width_z = dimension == 3 ? width : 0.0;  // disks: no kick along z
    const double mass = masses[i];
    for_each_particle_normal<batch>(*step.rng, RngPurpose::white_noise_kick, i, state.step, offset + from, to - from,
                                    [&](std::size_t k, const Vec3& xi) {
                                      const Vec3 c = store.velocity(from + k);
                                      const Vec3 kicked = c + Vec3{width * xi.x, width * xi.y, width_z * xi.z};
                                      store.set_velocity(from + k, kicked);
                                      change.add(mass * (norm2(kicked) - norm2(c)));
                                    });
    if (rotational_share > 0.0) kick_spins(store, from, to, offset, i, state, step);
  }

  /// The spins' share of the noise (rough particles): it leaves the translational energy as it is.
  template <class Store, class State>
  void kick_spins(Store& store, std::size_t from, std::size_t to, std::uint64_t offset, std::uint16_t i,
                  const State& state, const StepContext& step) const noexcept {
    const double rotations = dimension == 3 ? 3.0 : 1.0;
    const double width =
        std::sqrt(2.0 * beta * rotational_share * (dimension / rotations) * step.dt / reduced_inertia) /
        state.scale.u();
    const bool disks = dimension == 2;  // spinning about z
    for_each_particle_normal<batch>(*step.rng, RngPurpose::white_noise_spin_kick, i, state.step, offset + from,
                                    to - from, [&](std::size_t k, const Vec3& xi) {
                                      const Vec3 kick = disks ? Vec3{0.0, 0.0, xi.x} : xi;
                                      store.set_spin(from + k, store.spin(from + k) + width * kick);
                                    });
  }
};

static_assert(FreeFlightEffect<WhiteNoise>);

}  // namespace granmc
