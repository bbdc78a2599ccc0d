#include "kernel/theory/white_noise.hpp"

#include <cmath>
#include <numbers>

#include "kernel/collide/collision_kernel.hpp"

namespace granmc::theory {

double maxwell_relaxation_rate(double rate, double alpha, int dimension) noexcept {
  // 001 eq. (16) with gamma C_0 = rate; |S^1| / 4 = pi / 2 for disks
  return (dimension == 3 ? 1.0 : 0.5) * std::numbers::pi * rate * (1.0 - alpha * alpha);
}

double maxwell_temperature(double t, double temperature0, double beta, double rate, double alpha,
                           int dimension) noexcept {
  const double kappa = maxwell_relaxation_rate(rate, alpha, dimension);
  const double decay = std::exp(-kappa * t);
  return temperature0 * decay - 2.0 * beta / kappa * std::expm1(-kappa * t);  // 001 eqs. (16-17)
}

double maxwell_temperature_particles(double t, double temperature0, double beta, double rate, double alpha,
                                     double particles, int dimension) noexcept {
  return (1.0 - 1.0 / particles) * maxwell_temperature(t, temperature0, beta, rate, alpha, dimension);
}

double maxwell_temperature_uncentred(double t, double temperature0, double beta, double rate, double alpha,
                                     double particles, double mass, bool zero_momentum, int dimension) noexcept {
  const double bulk = (zero_momentum ? 0.0 : temperature0) + 2.0 * mass * beta * t;
  return maxwell_temperature_particles(t, temperature0, beta, rate, alpha, particles, dimension) + bulk / particles;
}

double maxwell_temperature_splitting(double t, double dt, double temperature0, double beta, double rate, double alpha,
                                     double particles, int dimension) noexcept {
  const double kappa = maxwell_relaxation_rate(rate, alpha, dimension);
  const double steady = beta == 0.0 ? 0.0 : -2.0 * beta * dt / std::expm1(-kappa * dt);
  return (1.0 - 1.0 / particles) * (steady + (temperature0 - steady) * std::exp(-kappa * t));
}

double maxwell_white_noise_a2(double alpha, int dimension) noexcept {
  const double a = alpha, d = dimension, k = d + 1.0;
  return 2.0 * k * (1.0 - a) * (1.0 - a) * (1.0 + a) /
         (19.0 * d - 5.0 - (11.0 * d + 3.0) * a + k * a * a - k * a * a * a);
}

double maxwellian_relative_speed_moment(double p, double temperature, int dimension) noexcept {
  const double d = dimension;
  return std::pow(4.0 * temperature, 0.5 * p) * std::tgamma(0.5 * (d + p)) / std::tgamma(0.5 * d);
}

double white_noise_steady_temperature(double lambda, double rate, double alpha, double beta, double a2,
                                      int dimension) noexcept {
  // 2 beta = |S^(d-1)| rate (1 - alpha^2) <1 - mu> <|u|^{2 + lambda}> / (8 d), <|u|^{2+lambda}> = c T^{1 + lambda/2}
  // with the first-Sonine factor (1 + lambda (lambda + 2) a2 / 16) of <|u|^{2+lambda}> (3/16 for hard cores)
  const bool hard_core = lambda == 1.0;
  const double c =
      maxwellian_relative_speed_moment(2.0 + lambda, 1.0, dimension) * (1.0 + lambda * (lambda + 2.0) * a2 / 16.0);
  const double one_minus_mu = dimension == 2 && hard_core ? 4.0 / 3.0 : 1.0;
  const double loss = (1.0 - alpha * alpha) * one_minus_mu / (8.0 * dimension) * unit_sphere_area(dimension) * rate * c;
  return std::pow(2.0 * beta / loss, 1.0 / (1.0 + 0.5 * lambda));
}

double isotropic_white_noise_a2(double alpha, double lambda, int dimension) noexcept {
  // docs/derivations/vhs_white_noise_a2.py: a2 = 16 (1 - alpha) N / D with
  //   N = (d + 1)(d + 2 + lambda) alpha^2 - (d + 1)(d + 2) + (3 d - 1) lambda,
  //   D = D0 + lambda D1 + lambda^2 D2 + lambda^3 D3 (below).
  const double a = alpha, a2 = a * a, a3 = a2 * a, d = dimension, l = lambda;
  const double n = (d + 1.0) * (d + 2.0 + l) * a2 - (d + 1.0) * (d + 2.0) + (3.0 * d - 1.0) * l;
  const double d0 = 80.0 + 48.0 * a - 16.0 * a2 + 16.0 * a3 + d * d * (8.0 * a3 - 8.0 * a2 + 88.0 * a - 152.0) +
                    d * (24.0 * a3 - 24.0 * a2 + 200.0 * a - 264.0);
  const double d1 = (6.0 * d * d + 26.0 * d + 20.0) * (a3 - a2) + (26.0 * d * d + 134.0 * d + 12.0) * a - 26.0 * d * d -
                    198.0 * d + 52.0;
  const double d2 = (a - 1.0) * ((d + 1.0) * (d + 8.0) * a2 - (d * d - 15.0 * d + 8.0));
  const double d3 = (a - 1.0) * ((d + 1.0) * a2 + 3.0 * d - 1.0);
  return -16.0 * (a - 1.0) * n / (d0 + l * (d1 + l * (d2 + l * d3)));
}

double tail_exponent(double lambda) noexcept { return 1.0 + 0.5 * lambda; }

double free_cooling_tail_exponent(double lambda) noexcept { return lambda; }

}  // namespace granmc::theory
