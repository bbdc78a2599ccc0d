#include "kernel/theory/sonine.hpp"

#include <cmath>
#include <numbers>

namespace granmc::theory {

namespace {
constexpr double d = 3.0;
}

double hcs_a2(double alpha) noexcept {
  return 16.0 * (1.0 - alpha) * (1.0 - 2.0 * alpha * alpha) /
         (9.0 + 24.0 * d - alpha * (41.0 - 8.0 * d) + 30.0 * (1.0 - alpha) * alpha * alpha);
}

double white_noise_a2(double alpha) noexcept {
  return 16.0 * (1.0 - alpha) * (1.0 - 2.0 * alpha * alpha) /
         (73.0 + 56.0 * d - 3.0 * alpha * (35.0 + 8.0 * d) + 30.0 * (1.0 - alpha) * alpha * alpha);
}

double cooling_rate(double alpha, double density, double diameter, double mass, double temperature, double chi,
                    double a2) noexcept {
  return 4.0 * std::sqrt(std::numbers::pi) / 3.0 * density * diameter * diameter * chi * (1.0 - alpha * alpha) *
         std::sqrt(temperature / mass) * (1.0 + 3.0 * a2 / 16.0);
}

double haff_temperature(double t, double temperature0, double cooling_rate0) noexcept {
  const double s = 1.0 + 0.5 * cooling_rate0 * t;
  return temperature0 / (s * s);
}

}  // namespace granmc::theory
