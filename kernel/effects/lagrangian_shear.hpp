#pragma once
// The inertial force of uniform shear flow in the Lagrangian frame (000 sec. 3): with u_x = a y, the
// peculiar velocities obey dV/dt = -a.V, a_{xy} = a, so over a step V_x -> V_x - a V_y dt with V_y and V_z
// unchanged. The map is linear and a.a = 0, so this first-order form is the exact flow (no splitting error
// inside the free-flight stage). It is linear in V, so it acts on the stored velocities c = V / u alike,
// and it commutes with the Gaussian thermostat's scaling.
// Dilute (Boltzmann) shear needs only this effect; the Enskog shift of the relative velocity at contact
// lives in collide/enskog_shear_shift.hpp.
#include <string>
#include <vector>

#include "kernel/effects/step_context.hpp"
#include "kernel/observe/compensated_sum.hpp"

namespace granmc {

struct LagrangianShear {
  // Half the step before the collision stage and half after (Strang): with the whole step before it, the
  // stationary shear stress is low by nu_eta dt / 2 (docs/methods/physics.md: 1.1 % at dt = 0.03 mean free times).
  // The step fuses each second half with the next first half: one pass per step.
  static constexpr StepPhase phase = StepPhase::around_collisions;
  static constexpr const char* name = "lagrangian-shear";
  static constexpr bool acts_on_particles = true;

  double rate = 0.0;           // a (1 / time)
  std::vector<double> masses;  // m_i of the species, in scene order

  [[nodiscard]] std::string explanation() const {
    return "uniform shear flow: inertial force V_x -= a V_y dt in free flight (O(N) per step), pressure tensor "
           "P^k at each sample";
  }

  /// Returns the change of sum_i m_i sum_k |c_k|^2 (stored units): the viscous heating of the kinetic
  /// part, -2 a dt sum m c_x c_y + (a dt)^2 sum m c_y^2.
  template <class State>
  double apply(State& state, const StepContext& step) const noexcept {
    const double a_dt = rate * step.dt;
    CompensatedSum change;
    for (std::size_t i = 0; i < state.species.size(); ++i) {
      const double mass = masses[i];
      double species_change = 0.0;
      state.species[i].for_each_velocity([&](Vec3& c) {
        const double x = c.x - a_dt * c.y;  // 000 sec. 3: V_x -> V_x - a V_y dt
        species_change += (x - c.x) * (x + c.x);
        c.x = x;
      });
      change.add(mass * species_change);
    }
    return change.value();
  }
};

static_assert(FreeFlightEffect<LagrangianShear>);

}  // namespace granmc
