#pragma once
// Stored velocities are dimensionless: V = u c, with u a velocity scale kept near the thermal speed.
// A cooling run rescales c and u together whenever the stored energy drifts, so the stored values stay
// of order one however many decades T falls; u is carried as log u, so T = exp(2 log u) theta never
// has to be formed when it would underflow (docs/methods/physics.md, "Scaled velocities: cooling over any
// number of decades").
#include <cmath>

namespace granmc {

/// A cooling run's stored temperature (or energy) may drift by this factor before the velocities are
/// rescaled to unit stored temperature (schemes/dsmc.hpp, schemes/swpm_scheme.hpp).
inline constexpr double rescale_factor = 1.25;

struct VelocityScale {
  double log_u = 0.0;  // log of the velocity scale u (scene velocity units)

  [[nodiscard]] double u() const noexcept { return std::exp(log_u); }
  /// Physical temperature of a stored "temperature" theta = m <c^2> / d: log T = 2 log u + log theta.
  [[nodiscard]] double log_temperature(double theta) const noexcept { return 2.0 * log_u + std::log(theta); }
};

}  // namespace granmc
