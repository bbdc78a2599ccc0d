#pragma once
// Gaussian thermostat F_i = (1/2) m_i zeta V (000 eq. 8): over a step every velocity is multiplied by
// exp(zeta dt / 2), the exact flow of dV/dt = zeta V / 2 (000 eq. 16 is its first-order form, 003 the
// exponential). All velocities share the factor, so it is applied to the velocity scale u (V = u c):
// O(1) per step, whatever the number of particles.
//
// With zeta = "cooling-rate" it compensates the instantaneous cooling rate, measured from the temperature
// before and after the collision stage (000 sec. 3): zeta dt = ln(T_before / T_after), so the temperature
// is restored exactly at the end of every step (HSS; with shear, 000 eq. 10 still holds).
#include <cmath>
#include <string>

#include "kernel/effects/step_context.hpp"

namespace granmc {

struct GaussianThermostat {
  static constexpr StepPhase phase = StepPhase::after_collisions;
  static constexpr const char* name = "gaussian-thermostat";
  static constexpr bool acts_on_particles = false;  // the velocity scale only

  bool compensate_cooling = true;  // zeta = instantaneous cooling rate
  double zeta = 0.0;               // fixed rate (1 / time) when not compensating

  [[nodiscard]] std::string explanation() const {
    return compensate_cooling ? "Gaussian thermostat compensating the cooling rate (O(1) per step)"
                              : "Gaussian thermostat, fixed zeta (O(1) per step)";
  }

  /// Moves only the velocity scale: the stored energy is unchanged (returns 0).
  template <class State>
  double apply(State& state, const StepContext& step) const noexcept {
    if (compensate_cooling) {
      state.scale.log_u += 0.5 * std::log1p(step.twice_energy_loss / step.twice_energy);  // u^2 T stays
    } else {
      state.scale.log_u += 0.5 * zeta * step.dt;  // 000 eq. (16), exact: V -> V exp(zeta dt / 2)
    }
    return 0.0;
  }
};

static_assert(FreeFlightEffect<GaussianThermostat>);

}  // namespace granmc
