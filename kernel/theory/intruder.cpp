#include "kernel/theory/intruder.hpp"

#include <cmath>

namespace granmc::theory {

double bath_temperature(const IntruderConfig& intruder) noexcept {
  return intruder.bath == BathKind::gaussian ? 0.5 / intruder.bath_a : 1.0 / intruder.bath_a;
}

double gaussian_bath_temperature_ratio(const IntruderConfig& intruder) noexcept {
  const double alpha = intruder.restitution, mass = intruder.mass;
  return (1.0 + alpha) / (2.0 + (1.0 - alpha) / mass);  // 002 eq. (22)
}

std::optional<double> intruder_temperature_ratio(const IntruderConfig& intruder) noexcept {
  if (intruder.dimension != 1) return std::nullopt;
  const double alpha = intruder.restitution, mass = intruder.mass;
  if (intruder.bath == BathKind::gaussian) return gaussian_bath_temperature_ratio(intruder);
  if (std::fabs(mass - alpha) <= 1e-12 * mass) return alpha;  // 002 sec. 3.1, M = alpha
  return std::nullopt;
}

}  // namespace granmc::theory
