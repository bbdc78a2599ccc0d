#pragma once
// What every free-flight effect sees, and what an effect is (the concept FreeFlightEffect below). An effect is
// an evaluator struct (docs/developer-guide/architecture.md, "Adding things"), an aggregate of its parameters that the
// run plan (setup/run_plan.cpp) fills from the scene:
//
//   struct MyEffect {
//     static constexpr StepPhase phase = StepPhase::...;   // when in the step it acts
//     static constexpr const char* name = "my-effect";     // in the instantiation name
//     static constexpr bool acts_on_particles = ...;       // false: only the velocity scale u
//     double parameter = 0.0;                              // its parameters, with units
//     template <class State>  // GasState or FloatGasState (gas_state.hpp)
//     double apply(State& state, const StepContext& step) const noexcept;
//     std::string explanation() const;                     // what `--explain` prints
//   };
//
// An effect on particles that can act on a part of a species (particles [from, to), the first of them
// particle `offset` of the species) also has apply_range; the rank-wave backend needs it
// (schemes/rank_wave_backend.hpp, effects/white_noise.hpp).
//
// apply returns the change it made to sum_i m_i sum_k |c_k|^2 in stored units (0 for an effect that only
// moves the velocity scale u), so the step's energy bookkeeping, which drives the rescaling and the
// thermal time step, stays exact without a pass over the particles.
//
// BasicDsmc<Backend, Real, Kernel, Effects...> (schemes/dsmc.hpp) runs, in each step, the free_flight effects, the
// collision stage, then the after_collisions effects, each in the order of the pack. An effect the scene does not name
// is not in the pack: it costs nothing.
#include <concepts>
#include <string>

#include "kernel/core/philox_stream.hpp"
#include "kernel/schemes/gas_state.hpp"

namespace granmc {

// in_collision: an evaluator the collision stage itself uses (collide/enskog_shear_shift.hpp); it has no apply.
// around_collisions: a free-flight effect applied in two halves, dt/2 before the collision stage and dt/2
// after it (Strang splitting: the steady-state error of the step becomes O(dt^2) instead of O(dt); for
// the shear stress of the first-order split it is -nu_eta dt / 2, docs/methods/physics.md). Consecutive halves are
// fused into one apply per step (schemes/dsmc.hpp), so apply(dt) must compose: apply(s) then apply(t) is
// apply(s + t).
enum class StepPhase { free_flight, after_collisions, in_collision, around_collisions };

struct StepContext {
  double dt = 0.0;                    // step length, scene time
  double twice_energy = 0.0;          // sum_i m_i sum_k |c_k|^2 (stored units) now
  double twice_energy_loss = 0.0;     // lost in this step's collision stage (0 in the free_flight phase):
                                      // before the collisions the stored energy was twice_energy + this
  const RandomStream* rng = nullptr;  // the replica's stream, for effects that draw (state.step is the step)
};

template <class E>
concept FreeFlightEffect = requires(const E& effect, GasState& state, FloatGasState& float_state,
                                    const StepContext& step) {
  { E::phase } -> std::convertible_to<StepPhase>;
  { E::name } -> std::convertible_to<const char*>;
  { E::acts_on_particles } -> std::convertible_to<bool>;
  { effect.apply(state, step) } -> std::same_as<double>;
  { effect.apply(float_state, step) } -> std::same_as<double>;
  { effect.explanation() } -> std::convertible_to<std::string>;
  requires E::phase != StepPhase::in_collision;
};

/// An evaluator the collision stage itself uses (collide/enskog_shear_shift.hpp): the relative velocity at
/// contact, in stored units for the step.
template <class E>
concept CollisionShift = requires(const E& shift, double u) {
  { E::name } -> std::convertible_to<const char*>;
  { E::active } -> std::convertible_to<bool>;
  { shift.in_stored_units(u) } -> std::same_as<E>;
  { shift.explanation() } -> std::convertible_to<std::string>;
  requires E::phase == StepPhase::in_collision;
};

/// What the time stepper's effect pack holds.
template <class E>
concept StepEffect = FreeFlightEffect<E> || CollisionShift<E>;

}  // namespace granmc
