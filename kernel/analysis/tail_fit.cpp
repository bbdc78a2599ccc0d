#include "kernel/analysis/tail_fit.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace granmc {

namespace {

/// The least-squares misfit of y = c + gamma x1 - a x2 over the points (x1 = ln v, x2 = v^b), by the normal
/// equations of the three coefficients (Cramer's rule).
double misfit(const std::vector<double>& log_v, const std::vector<double>& v, const std::vector<double>& y,
              double b) noexcept {
  std::array<std::array<double, 3>, 3> m{};
  std::array<double, 3> rhs{};
  std::vector<std::array<double, 3>> rows(v.size());
  for (std::size_t k = 0; k < v.size(); ++k) {
    rows[k] = {1.0, log_v[k], -std::pow(v[k], b)};
    for (std::size_t i = 0; i < 3; ++i) {
      rhs[i] += rows[k][i] * y[k];
      for (std::size_t j = 0; j < 3; ++j) m[i][j] += rows[k][i] * rows[k][j];
    }
  }
  auto det = [](const std::array<std::array<double, 3>, 3>& a) {
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
  };
  const double d = det(m);
  if (!(std::fabs(d) > 0.0)) return std::numeric_limits<double>::infinity();
  std::array<double, 3> coef{};
  for (std::size_t c = 0; c < 3; ++c) {
    auto mc = m;
    for (std::size_t i = 0; i < 3; ++i) mc[i][c] = rhs[i];
    coef[c] = det(mc) / d;
  }
  double sum = 0.0;
  for (std::size_t k = 0; k < v.size(); ++k) {
    const double r = y[k] - (coef[0] * rows[k][0] + coef[1] * rows[k][1] + coef[2] * rows[k][2]);
    sum += r * r;
  }
  return sum;
}

/// The b of least misfit on a grid of `step` over [lo, hi].
double best_exponent(const std::vector<double>& log_v, const std::vector<double>& v, const std::vector<double>& y,
                     double lo, double hi, double step) noexcept {
  double best = lo, least = std::numeric_limits<double>::infinity();
  const auto n = static_cast<int>(std::lround((hi - lo) / step));
  for (int i = 0; i <= n; ++i) {
    const double b = lo + step * i;
    const double m = misfit(log_v, v, y, b);
    if (m < least) least = m, best = b;
  }
  return best;
}

}  // namespace

/// b fitted to the density f over shells [first, last] (the shells with f > 0; NaN with fewer than 4).
double fit_exponent(const std::vector<double>& edges, const std::vector<double>& f, std::size_t first,
                    std::size_t last) noexcept {
  std::vector<double> log_v, v, y;
  for (std::size_t k = first; k <= last; ++k) {
    if (!(f[k] > 0.0)) continue;
    const double centre = 0.5 * (edges[k] + edges[k + 1]);
    v.push_back(centre);
    log_v.push_back(std::log(centre));
    y.push_back(std::log(f[k]));
  }
  if (v.size() < 4) return std::numeric_limits<double>::quiet_NaN();
  const double coarse = best_exponent(log_v, v, y, 0.2, 3.0, 0.005);
  if (coarse <= 0.2 || coarse >= 3.0) return std::numeric_limits<double>::quiet_NaN();  // no minimum inside
  return best_exponent(log_v, v, y, coarse - 0.005, coarse + 0.005, 1e-4);
}

TailWindow fit_tail_window(const std::vector<double>& edges, const std::vector<std::vector<double>>& densities,
                           std::size_t first, std::size_t last) {
  TailWindow w;
  w.first = first;
  w.last = last;
  w.speed_from = edges[first];
  w.speed_to = edges[last + 1];
  const std::size_t replicas = densities.size(), shells = densities.front().size();
  std::vector<double> total(shells, 0.0);
  for (const std::vector<double>& f : densities)
    for (std::size_t k = 0; k < shells; ++k) total[k] += f[k];
  auto mean_without = [&](std::size_t left_out) {
    std::vector<double> mean(shells);
    const double n = static_cast<double>(replicas - (left_out < replicas ? 1 : 0));
    for (std::size_t k = 0; k < shells; ++k)
      mean[k] = (total[k] - (left_out < replicas ? densities[left_out][k] : 0.0)) / n;
    return mean;
  };
  w.exponent.mean = fit_exponent(edges, mean_without(replicas), first, last);
  if (replicas < 2) return w;
  // The jackknife over replicas: b of the mean density without replica r, for each r; the variance of b is
  // (R - 1)/R sum_r (b_r - mean b_r)^2, and ci = lambda_p times its square root (001 eq. 31).
  std::vector<double> leave_one(replicas);
  double sum = 0.0;
  for (std::size_t r = 0; r < replicas; ++r) sum += leave_one[r] = fit_exponent(edges, mean_without(r), first, last);
  const double centre = sum / static_cast<double>(replicas);
  double squares = 0.0;
  for (double b : leave_one) squares += (b - centre) * (b - centre);
  w.exponent.ci =
      confidence_lambda_p * std::sqrt(static_cast<double>(replicas - 1) / static_cast<double>(replicas) * squares);
  return w;
}

std::size_t tail_reach(const std::vector<std::vector<double>>& densities) noexcept {
  if (densities.empty()) return 0;
  std::size_t reach = densities.front().size();
  for (const std::vector<double>& f : densities) {
    std::size_t k = 0;
    while (k < f.size() && f[k] > 0.0) ++k;
    reach = std::min(reach, k);
  }
  return reach;
}

namespace {

/// The first shell beyond the density's maximum where the replica mean falls below `fraction` of it (the
/// reach if none), with the shells [0, reach) every replica has weight in.
std::size_t first_below(const std::vector<std::vector<double>>& densities, std::size_t reach, double fraction) {
  std::vector<double> mean(reach, 0.0);
  for (const std::vector<double>& f : densities)
    for (std::size_t k = 0; k < reach; ++k) mean[k] += f[k];
  const std::size_t top = static_cast<std::size_t>(std::max_element(mean.begin(), mean.end()) - mean.begin());
  std::size_t k = top;
  while (k < reach && !(mean[k] < fraction * mean[top])) ++k;
  return k;
}

}  // namespace

std::optional<TailWindow> fit_tail(const std::vector<double>& edges,
                                   const std::vector<std::vector<double>>& densities) {
  const std::size_t reach = tail_reach(densities);
  const std::size_t first = first_below(densities, reach, tail_density_fraction);
  if (first + tail_min_shells > reach) return std::nullopt;
  return fit_tail_window(edges, densities, first, reach - 1);
}

std::vector<TailWindow> tail_exponent_profile(const std::vector<double>& edges,
                                              const std::vector<std::vector<double>>& densities) {
  std::vector<TailWindow> profile;
  const std::size_t reach = tail_reach(densities);
  for (double fraction = 0.1;; fraction *= 0.1) {
    const std::size_t first = first_below(densities, reach, fraction);
    if (first + tail_min_shells > reach || edges[reach] < 2.0 * edges[first]) break;
    if (!profile.empty() && first == profile.back().first) continue;  // a decade within one shell
    profile.push_back(fit_tail_window(edges, densities, first, reach - 1));
  }
  return profile;
}

}  // namespace granmc
