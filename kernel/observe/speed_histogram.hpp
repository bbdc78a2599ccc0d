#pragma once
// Histogram of scaled speeds v* = |V| / v0(t) over equal-width shells (001 eq. 37 uses the same shells
// for speeds; 000 eq. 19 needs Phi_i(v*) for Delta_i). v0 = sqrt(2 T / m_hat), m_hat = m_1 m_2 / (m_1 + m_2)
// for two species (000 eq. 7) and m for one. Counts accumulate over the samples of the last half of a run,
// where the scaled state is stationary (gas_series.hpp, first_stationary_sample).
#include <vector>

#include "kernel/core/scene.hpp"
#include "kernel/schemes/gas_state.hpp"

namespace granmc {

/// The reference speed v0 in stored units (divide a stored speed |c| by it to get v*), given the mixture
/// temperature in stored units theta = T / u^2.
double scaled_speed_unit(const Scene& scene, double theta_mixture) noexcept;

/// The unit the histogram's shells are in, in stored units: v0 (scaled_speed_unit) for output.histogram.speed
/// = "scaled", the scene's velocity unit for "velocity". Absent, the time-stepped scheme's is scaled (the
/// scaled states 000 studies) and the event scheme's velocity (001 eq. (37) takes f(|v|) in physical units).
double histogram_speed_unit(const Scene& scene, const VelocityScale& scale, double theta_mixture) noexcept;

/// Adds the stored speeds of one species, divided by `unit`, to `counts` (shells of width radius/shells
/// from 0; speeds at or beyond the radius are not counted).
template <class Real>
void add_speeds(const BasicSpeciesStore<Real>& store, double unit, double radius, std::vector<double>& counts) noexcept;

}  // namespace granmc
