#pragma once
// Exact results for the 1D intruder in a bath of point particles of mass m = 1 (002 sec. 3.1).
#include <optional>

#include "kernel/core/scene.hpp"

namespace granmc::theory {

/// T_B = m <v^2> of the bath: 1 / (2a) for the Gaussian (002 eq. 18), 1 / a for the power law (eq. 23).
double bath_temperature(const IntruderConfig& intruder) noexcept;

/// The stationary T/T_B of the 1D intruder in a Gaussian bath (Martin and Piasecki, 002 eq. 22):
/// (1 + alpha) / (2 + (1 - alpha) / M), any M and alpha; the reference line of 002 Fig. 4 for other baths too.
double gaussian_bath_temperature_ratio(const IntruderConfig& intruder) noexcept;

/// The stationary T/T_B where it is known exactly: the Gaussian bath, any M and alpha (Martin and
/// Piasecki, 002 eq. 22): (1 + alpha) / (2 + (1 - alpha) / M); the power-law bath with M = alpha: alpha, the
/// intruder's law then being the bath's (002 sec. 3.1). Nothing otherwise.
std::optional<double> intruder_temperature_ratio(const IntruderConfig& intruder) noexcept;

}  // namespace granmc::theory
