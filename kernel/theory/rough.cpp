#include "kernel/theory/rough.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <stdexcept>
#include <string>

namespace granmc::theory {

namespace {

/// d_r = d (d - 1) / 2, the rotational degrees of freedom (3 spheres, 1 disks).
double rotational_dimensions(double d) noexcept { return d * (d - 1.0) / 2.0; }

/// The Maxwellian collision frequency of one particle with the particles of species j (n_j chi_ij given), at
/// V2 = T_i / m_i + T_j / m_j: n chi sigma^2 sqrt(8 pi V2) for spheres, n chi sigma sqrt(2 pi V2) for disks.
double pair_frequency(double n_chi, double sigma, double v2, int dimension) noexcept {
  const double pi = std::numbers::pi;
  return dimension == 3 ? n_chi * sigma * sigma * std::sqrt(8.0 * pi * v2) : n_chi * sigma * std::sqrt(2.0 * pi * v2);
}

/// The collision frequency of species 0 plus that of species 1 at these temperatures: the unit of the residuals
/// below, so that they are of order 1 at any temperature.
double frequency_scale(const RoughMixture& m, const RoughTemperatures& t) noexcept {
  const MixtureParameters& g = m.gas;
  double nu = 0.0;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      const double v2 = t.translation[i] / g.mass[i] + t.translation[j] / g.mass[j];
      nu += pair_frequency(g.density[j] * g.chi[i][j], 0.5 * (g.diameter[i] + g.diameter[j]), v2, g.dimension);
    }
  return nu;
}

/// Solves residual(z) = 0 for n log-temperatures z, residual = dz/dt over frequency_scale: first by following
/// the relaxation dz/dtau = residual (the physical approach to the steady state, so it heads for the state the
/// simulation reaches) until the residual is small, then by Newton's method with a finite-difference Jacobian,
/// each step halved until it reduces the residual (near beta = -1 the slowest relaxation rate is of order b^2,
/// too slow to follow to the end, and theta of order 1 / b^2 is far from the start).
template <std::size_t n, class Residual>
std::array<double, n> steady_logs(const Residual& residual, std::array<double, n> z) {
  auto largest = [](const std::array<double, n>& r) {
    double x = 0.0;
    for (double v : r) x = std::max(x, std::fabs(v));
    return x;
  };
  std::array<double, n> r = residual(z);
  for (int k = 0; k < 1000000 && largest(r) > 1e-6; ++k) {
    for (std::size_t a = 0; a < n; ++a) z[a] += 0.05 * r[a];
    r = residual(z);
  }
  for (int k = 0; k < 200 && largest(r) > 1e-15; ++k) {
    double jacobian[n][n + 1];
    for (std::size_t b = 0; b < n; ++b) {  // central differences: the slow direction's entries are of order b^2
      constexpr double h = 1e-5;
      std::array<double, n> up = z, down = z;
      up[b] += h;
      down[b] -= h;
      const std::array<double, n> ru = residual(up), rd = residual(down);
      for (std::size_t a = 0; a < n; ++a) jacobian[a][b] = (ru[a] - rd[a]) / (2.0 * h);
    }
    for (std::size_t a = 0; a < n; ++a) jacobian[a][n] = -r[a];
    for (std::size_t c = 0; c < n; ++c) {  // Gaussian elimination with partial pivoting
      std::size_t pivot = c;
      for (std::size_t a = c + 1; a < n; ++a)
        if (std::fabs(jacobian[a][c]) > std::fabs(jacobian[pivot][c])) pivot = a;
      for (std::size_t b = 0; b <= n; ++b) std::swap(jacobian[c][b], jacobian[pivot][b]);
      for (std::size_t a = c + 1; a < n; ++a) {
        const double f = jacobian[a][c] / jacobian[c][c];
        for (std::size_t b = c; b <= n; ++b) jacobian[a][b] -= f * jacobian[c][b];
      }
    }
    for (std::size_t c = n; c-- > 0;) {
      double x = jacobian[c][n];
      for (std::size_t b = c + 1; b < n; ++b) x -= jacobian[c][b] * jacobian[b][n];
      jacobian[c][n] = x / jacobian[c][c];
    }
    double step = 1.0;
    for (int halving = 0; halving < 40; ++halving, step *= 0.5) {
      std::array<double, n> trial = z;
      for (std::size_t a = 0; a < n; ++a) trial[a] += step * jacobian[a][n];
      const std::array<double, n> rt = residual(trial);
      if (largest(rt) < largest(r) || halving == 39) {
        z = trial;
        r = rt;
        break;
      }
    }
  }
  if (!(largest(r) < 1e-12))
    throw std::runtime_error("theory of rough mixtures: no steady state found (residual " + std::to_string(largest(r)) +
                             ")");
  return z;
}

RoughMixtureState state_of(const RoughTemperatures& t) noexcept {
  return {t.translation[0] / t.translation[1], {t.rotation[0] / t.translation[0], t.rotation[1] / t.translation[1]}};
}

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

RoughTemperatures rough_mixture_collision_rates(const RoughMixture& m, const RoughTemperatures& t) noexcept {
  const MixtureParameters& g = m.gas;
  const double d = g.dimension, kappa = m.kappa;
  RoughTemperatures rate;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      const double mi = g.mass[i], mj = g.mass[j], alpha = g.alpha[i][j];
      const double mu = mi * mj / (mi + mj);
      const double tangential = (1.0 + m.beta) / (1.0 + mu * (1.0 / (kappa * mi) + 1.0 / (kappa * mj)));
      const double v2 = t.translation[i] / mi + t.translation[j] / mj;
      const double w2 = (t.rotation[i] / mi + t.rotation[j] / mj) / kappa;
      const double slip2 = (d - 1.0) * (v2 + w2);  // <|G_t|^2> over the collisions
      const double nu =
          pair_frequency(g.density[j] * g.chi[i][j], 0.5 * (g.diameter[i] + g.diameter[j]), v2, g.dimension);
      const double translational =
          -(mu * t.translation[i] / mi) * (2.0 * (1.0 + alpha) + (d - 1.0) * tangential) +
          (mu * mu / (2.0 * mi)) * (2.0 * (1.0 + alpha) * (1.0 + alpha) * v2 + tangential * tangential * slip2);
      const double rotational =
          (mu * tangential / (kappa * mi)) * (-(d - 1.0) * t.rotation[i] + 0.5 * mu * tangential * slip2);
      rate.translation[i] += (2.0 / d) * nu * translational;
      rate.rotation[i] += (2.0 / rotational_dimensions(d)) * nu * rotational;
    }
  return rate;
}

RoughMixtureState rough_mixture_hcs(const RoughMixture& m) {
  if (!(m.beta > -1.0)) return {temperature_ratio_maxwell(m.gas), {0.0, 0.0}};
  // z = the logs of T_2 / T_1, T_r,1 / T_1, T_r,2 / T_1 (T_1 = 1); their rates are the differences of the
  // cooling rates, zero when all four temperatures decay at one rate.
  auto temperatures = [](const std::array<double, 3>& z) {
    return RoughTemperatures{{1.0, std::exp(z[0])}, {std::exp(z[1]), std::exp(z[2])}};
  };
  auto residual = [&](const std::array<double, 3>& z) {
    const RoughTemperatures t = temperatures(z), r = rough_mixture_collision_rates(m, t);
    const double nu = frequency_scale(m, t), first = r.translation[0] / t.translation[0];
    return std::array<double, 3>{(r.translation[1] / t.translation[1] - first) / nu,
                                 (r.rotation[0] / t.rotation[0] - first) / nu,
                                 (r.rotation[1] / t.rotation[1] - first) / nu};
  };
  return state_of(temperatures(steady_logs(residual, std::array<double, 3>{})));
}

RoughMixtureState rough_mixture_white_noise(const RoughMixture& m, double rotational_share) {
  if (!(m.beta > -1.0)) throw std::invalid_argument("rough_mixture_white_noise: beta = -1 has no rotational state");
  const double d = m.gas.dimension;
  auto temperatures = [](const std::array<double, 4>& z) {
    return RoughTemperatures{{std::exp(z[0]), std::exp(z[1])}, {std::exp(z[2]), std::exp(z[3])}};
  };
  auto residual = [&](const std::array<double, 4>& z) {  // d ln T / dt over the frequency scale, beta_wn = 1
    const RoughTemperatures t = temperatures(z), r = rough_mixture_collision_rates(m, t);
    const double nu = frequency_scale(m, t);
    std::array<double, 4> out{};
    for (int i = 0; i < 2; ++i) {
      const double heat = 2.0 * m.gas.mass[i];
      out[i] = (heat * (1.0 - rotational_share) + r.translation[i]) / (t.translation[i] * nu);
      out[2 + i] = (heat * rotational_share * d / rotational_dimensions(d) + r.rotation[i]) / (t.rotation[i] * nu);
    }
    return out;
  };
  return state_of(temperatures(steady_logs(residual, std::array<double, 4>{})));
}

}  // namespace granmc::theory
