#include "kernel/theory/white_noise.hpp"

#include <cmath>
#include <numbers>

namespace granmc::theory {

double maxwell_relaxation_rate(double rate, double alpha) noexcept {
  return std::numbers::pi * rate * (1.0 - alpha * alpha);  // 001 eq. (16) with gamma C_0 = rate
}

double maxwell_temperature(double t, double temperature0, double beta, double rate, double alpha) noexcept {
  const double kappa = maxwell_relaxation_rate(rate, alpha);
  const double decay = std::exp(-kappa * t);
  return temperature0 * decay - 2.0 * beta / kappa * std::expm1(-kappa * t);  // 001 eqs. (16-17)
}

double maxwell_temperature_particles(double t, double temperature0, double beta, double rate, double alpha,
                                     double particles) noexcept {
  return (1.0 - 1.0 / particles) * maxwell_temperature(t, temperature0, beta, rate, alpha);
}

double maxwell_temperature_uncentred(double t, double temperature0, double beta, double rate, double alpha,
                                     double particles, double mass, bool zero_momentum) noexcept {
  const double bulk = (zero_momentum ? 0.0 : temperature0) + 2.0 * mass * beta * t;
  return maxwell_temperature_particles(t, temperature0, beta, rate, alpha, particles) + bulk / particles;
}

double maxwell_temperature_splitting(double t, double dt, double temperature0, double beta, double rate, double alpha,
                                     double particles) noexcept {
  const double kappa = maxwell_relaxation_rate(rate, alpha);
  const double steady = beta == 0.0 ? 0.0 : -2.0 * beta * dt / std::expm1(-kappa * dt);
  return (1.0 - 1.0 / particles) * (steady + (temperature0 - steady) * std::exp(-kappa * t));
}

double maxwell_white_noise_a2(double alpha) noexcept {
  const double a = alpha;
  return 2.0 * (1.0 - a) * (1.0 - a) * (1.0 + a) / (13.0 - 9.0 * a + a * a - a * a * a);
}

double maxwellian_relative_speed_moment(double p, double temperature) noexcept {
  return std::pow(4.0 * temperature, 0.5 * p) * std::tgamma(0.5 * (3.0 + p)) / std::tgamma(1.5);
}

double white_noise_steady_temperature(double lambda, double rate, double alpha, double beta, double a2) noexcept {
  // 2 beta = (1 - alpha^2)/24 4 pi rate <|u|^{2 + lambda}>, <|u|^{2+lambda}> = c T^{1 + lambda/2}.
  const double c = maxwellian_relative_speed_moment(2.0 + lambda, 1.0) * (lambda == 1.0 ? 1.0 + 3.0 * a2 / 16.0 : 1.0);
  const double loss = (1.0 - alpha * alpha) / 24.0 * 4.0 * std::numbers::pi * rate * c;
  return std::pow(2.0 * beta / loss, 1.0 / (1.0 + 0.5 * lambda));
}

double tail_exponent(double lambda) noexcept { return 1.0 + 0.5 * lambda; }

double free_cooling_tail_exponent(double lambda) noexcept { return lambda; }

}  // namespace granmc::theory
