#pragma once
// The pressure tensor of a sheared gas and the reduced shear rate, in the reduced units of 000 Figs. 10-12.
//
// Kinetic part (000 eq. 17): P^k = sum_i (m_i n_i / N_i) sum_k V_k V_k, so with n_i / N_i = n / N and the
// mixture temperature T = sum_i m_i sum_k V_k^2 / dN,
//     P^k / (n T) = d sum_i m_i sum_k V_k V_k / sum_i m_i sum_k V_k^2   (trace d; disks d = 2, n per area),
// with V the peculiar velocity (about the mixture's flow velocity). The collisional transfer part is
// tallied by the collision stage (collide/enskog_shear_shift.hpp, schemes/dsmc.hpp).
#include "kernel/core/scene.hpp"
#include "kernel/core/sym_tensor.hpp"
#include "kernel/schemes/gas_state.hpp"

namespace granmc {

/// P^k / (n T) of `state` (000 eq. 17).
template <class Real>
SymTensor reduced_kinetic_pressure(const Scene& scene, const BasicGasState<Real>& state);

/// The thermal speed v_0 = sqrt(2 T / m) of one species, or sqrt(2 T (m_1 + m_2) / (m_1 m_2)) of a binary
/// mixture (000 sec. 4, with Garzo and Montanero's convention), at mixture temperature T.
double thermal_speed(const Scene& scene, double temperature);

/// The effective collision frequency nu = sqrt(pi) n sigma_12^2 v_0 of 000 Fig. 10 (sigma_12 the
/// cross-diameter; for one species sigma), at mixture temperature T. Disks (run.dimension = 2): nu =
/// (sqrt(pi) / 2) n sigma_12 v_0, the same share 1 / (2 sqrt 2) of the Maxwellian collision frequency of one
/// species as in d = 3 (docs/methods/physics.md, "Uniform shear flow of disks").
double effective_collision_frequency(const Scene& scene, double temperature);

}  // namespace granmc
