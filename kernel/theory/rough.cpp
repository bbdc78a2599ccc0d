#include "kernel/theory/rough.hpp"

#include <cmath>

namespace granmc::theory {

namespace {

/// d_r = d (d - 1) / 2, the rotational degrees of freedom (3 spheres, 1 disks).
double rotational_dimensions(double d) noexcept { return d * (d - 1.0) / 2.0; }

}  // namespace

double rough_tangential_factor(double beta, double kappa) noexcept {
  return (1.0 + beta) * kappa / (2.0 * (1.0 + kappa));
}

RoughCoolingRates rough_cooling_rates(double alpha, double beta, double kappa, double theta, int dimension) noexcept {
  const double b = rough_tangential_factor(beta, kappa);
  const double d = dimension, rotations = rotational_dimensions(d), c = 2.0 * (d - 1.0);
  return {((1.0 - alpha * alpha) + c * (b - b * b * (1.0 + theta / kappa))) / d,
          c * (b / kappa) * (1.0 - b * (1.0 / theta + 1.0 / kappa)) / rotations};
}

double rough_hcs_theta(double alpha, double beta, double kappa, int dimension) noexcept {
  const double b = rough_tangential_factor(beta, kappa);
  if (b == 0.0) return 0.0;
  const double d = dimension, rotations = rotational_dimensions(d), c = 2.0 * (d - 1.0);
  // theta (zeta_tr - zeta_rot) = q2 theta^2 + q1 theta + q0 = 0, with q2 < 0 < q0: one positive root.
  const double q2 = -c * b * b / (kappa * d);
  const double q1 = ((1.0 - alpha * alpha) + c * (b - b * b)) / d - c * (b / kappa) * (1.0 - b / kappa) / rotations;
  const double q0 = c * b * b / (kappa * rotations);
  return (-q1 - std::sqrt(q1 * q1 - 4.0 * q2 * q0)) / (2.0 * q2);
}

double rough_white_noise_theta(double beta, double kappa) noexcept {
  const double b = rough_tangential_factor(beta, kappa);
  return b * kappa / (kappa - b);
}

double rough_split_noise_theta(double alpha, double beta, double kappa, double rotational_share,
                               int dimension) noexcept {
  if (rotational_share == 0.0) return rough_white_noise_theta(beta, kappa);
  const double d = dimension, rotations = rotational_dimensions(d);
  const auto imbalance = [&](double theta) {  // grows with theta (rough.hpp)
    const RoughCoolingRates z = rough_cooling_rates(alpha, beta, kappa, theta, dimension);
    return (1.0 - rotational_share) * rotations * theta * z.rotation - rotational_share * d * z.translation;
  };
  double low = 0.0, high = 1.0;
  while (imbalance(high) < 0.0) high *= 2.0;
  for (int k = 0; k < 200 && high - low > 1e-15 * high; ++k) {
    const double mid = 0.5 * (low + high);
    (imbalance(mid) < 0.0 ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

}  // namespace granmc::theory
