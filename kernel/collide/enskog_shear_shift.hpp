#pragma once
// Uniform shear flow inside the Enskog collision (000 eq. 2 and sec. 3, step 2). At contact the partner l
// of particle k sits at r_k + sigma_ij sigma-hat, where the flow velocity differs by a.(sigma_ij sigma-hat),
// so in the Lagrangian frame the relative velocity that decides and drives the collision is
//     g_kl = V_k - V_l - sigma_ij a.sigma-hat,   a.sigma-hat = a sigma-hat_y x-hat,
// used in the acceptance Theta(g.sigma) omega_kl / omega_max and in the update (000 eqs. 14-15)
// (docs/methods/physics.md derives the sign). The collision then changes the peculiar kinetic energy by
//     -(1 - alpha^2) mu (g.sigma)^2 - 2 (1 + alpha) mu (g.sigma) s,   s = sigma_ij a sigma-hat_x sigma-hat_y,
// (mu = m_i m_j / (m_i + m_j)): the inelastic loss, and the collisional part of the viscous heating, equal
// to -a sigma_ij J sigma-hat_x sigma-hat_y with the impulse J = (1 + alpha) mu (g.sigma). Every accepted
// collision transfers the momentum J sigma-hat across sigma_ij sigma-hat: the collisional transfer
// contribution J sigma_ij sigma-hat sigma-hat to the pressure tensor (000 eq. 18).
//
// In the Boltzmann limit (packing_fraction = 0) the shift vanishes with sigma_ij a / v_0 ~ a* phi, and
// the collision stage runs with NoCollisionShift: dilute runs and runs without shear pay nothing.
#include <string>

#include "kernel/collide/pair_coefficients.hpp"
#include "kernel/core/sym_tensor.hpp"
#include "kernel/core/vec3.hpp"
#include "kernel/effects/step_context.hpp"

namespace granmc {

/// No shift: the relative velocity is V_k - V_l and no pressure-tensor transfer is tallied.
struct NoCollisionShift {
  static constexpr bool active = false;
};

/// The Enskog shear shift for one step, in stored velocity units.
struct EnskogShearShift {
  static constexpr bool active = true;
  static constexpr StepPhase phase = StepPhase::in_collision;
  static constexpr const char* name = "enskog-shear-shift";

  double rate = 0.0;  // a (1 / time)

  [[nodiscard]] std::string explanation() const {
    return "Enskog shear shift of the contact velocity, collisional transfer P^c tallied";
  }

  /// The step's shift per unit diameter in stored units, a / u, for a velocity scale u.
  [[nodiscard]] EnskogShearShift in_stored_units(double u) const noexcept { return {rate / u}; }

  /// g_kl = V_k - V_l - sigma_ij a sigma-hat_y x-hat (000 sec. 3, step 2).
  [[nodiscard]] Vec3 relative_velocity(const Vec3& vk, const Vec3& vl, const Vec3& sigma,
                                       const PairCoefficients& p) const noexcept {
    Vec3 g = vk - vl;
    g.x -= p.diameter * rate * sigma.y;
    return g;
  }
};

static_assert(CollisionShift<EnskogShearShift>);

}  // namespace granmc
