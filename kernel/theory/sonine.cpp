#include "kernel/theory/sonine.hpp"

#include <cmath>
#include <numbers>

namespace granmc::theory {

double hcs_a2(double alpha, int dimension) noexcept {
  const double d = dimension;
  return 16.0 * (1.0 - alpha) * (1.0 - 2.0 * alpha * alpha) /
         (9.0 + 24.0 * d - alpha * (41.0 - 8.0 * d) + 30.0 * (1.0 - alpha) * alpha * alpha);
}

double white_noise_a2(double alpha, int dimension) noexcept {
  const double d = dimension;
  return 16.0 * (1.0 - alpha) * (1.0 - 2.0 * alpha * alpha) /
         (73.0 + 56.0 * d - 3.0 * alpha * (35.0 + 8.0 * d) + 30.0 * (1.0 - alpha) * alpha * alpha);
}

double collision_frequency(double density, double diameter, double mass, double temperature, double chi,
                           int dimension) noexcept {
  const double line = (dimension == 2 ? 2.0 : 4.0) * std::sqrt(std::numbers::pi) * density * diameter;
  return (dimension == 2 ? line : line * diameter) * chi * std::sqrt(temperature / mass);  // sigma^(d-1)
}

double cooling_rate(double alpha, double density, double diameter, double mass, double temperature, double chi,
                    double a2, int dimension) noexcept {
  const double prefactor = dimension == 2 ? std::sqrt(std::numbers::pi) : 4.0 * std::sqrt(std::numbers::pi) / 3.0;
  const double line = prefactor * density * diameter;
  return (dimension == 2 ? line : line * diameter) * chi * (1.0 - alpha * alpha) * std::sqrt(temperature / mass) *
         (1.0 + 3.0 * a2 / 16.0);  // sigma^(d-1)
}

double white_noise_temperature(double alpha, double density, double diameter, double mass, double chi, double beta,
                               double a2, int dimension) noexcept {
  const double zeta_at_one = cooling_rate(alpha, density, diameter, mass, 1.0, chi, a2, dimension);
  return std::pow(2.0 * beta * mass / zeta_at_one, 2.0 / 3.0);
}

double haff_temperature(double t, double temperature0, double cooling_rate0) noexcept {
  const double s = 1.0 + 0.5 * cooling_rate0 * t;
  return temperature0 / (s * s);
}

}  // namespace granmc::theory
