// Bath laws of the Gillespie intruder (002 eqs. 5-6, 14, 17-19, 23): the closed-form fluxes against
// quadrature, and the rejection samplers of g_+(v; v1) against the exact law for intruder velocities from
// the far left tail to the far right tail (Kolmogorov-Smirnov at p = 0.999 and the mean).
#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "kernel/collide/bath_gaussian.hpp"
#include "kernel/collide/bath_power_law.hpp"

using namespace granmc;

namespace {

/// Cumulative integral of h(w) over w in [0, inf) on the grid s = w / (1 + w), Simpson per cell.
struct TabulatedLaw {
  std::vector<double> w, cdf;
  double total = 0.0, mean = 0.0;

  explicit TabulatedLaw(const std::function<double(double)>& h, int cells = 400000) {
    w.push_back(0.0);
    cdf.push_back(0.0);
    double acc = 0.0, first = 0.0;
    auto g = [&](double s) {  // integrand in s, and w h in s
      if (s >= 1.0) return std::pair{0.0, 0.0};
      const double x = s / (1.0 - s), jac = 1.0 / ((1.0 - s) * (1.0 - s));
      return std::pair{h(x) * jac, x * h(x) * jac};
    };
    for (int k = 0; k < cells; ++k) {
      const double s0 = static_cast<double>(k) / cells, s1 = static_cast<double>(k + 1) / cells;
      const auto [a0, b0] = g(s0);
      const auto [am, bm] = g(0.5 * (s0 + s1));
      const auto [a1, b1] = g(s1);
      acc += (s1 - s0) / 6.0 * (a0 + 4.0 * am + a1);
      first += (s1 - s0) / 6.0 * (b0 + 4.0 * bm + b1);
      w.push_back(s1 >= 1.0 ? INFINITY : s1 / (1.0 - s1));
      cdf.push_back(acc);
    }
    total = acc;
    mean = first / acc;
    for (double& c : cdf) c /= total;
  }
  double at(double x) const {
    const auto it = std::upper_bound(w.begin(), w.end(), x);
    if (it == w.end()) return 1.0;
    const std::size_t k = static_cast<std::size_t>(it - w.begin());
    const double t = (x - w[k - 1]) / (w[k] - w[k - 1]);
    return cdf[k - 1] + t * (cdf[k] - cdf[k - 1]);
  }
};

/// x1 = sqrt(a) v1 from the far left tail (where the flux is 1e-170 of its typical value for the Gaussian)
/// to the far right tail.
template <class Bath>
void check_bath(const Bath& bath, const std::function<double(double)>& f, const char* name, double far_left) {
  const double sa = std::sqrt(bath.a);
  const RandomStream rng(2718, 0);
  for (double x1 : {far_left, -4.0, -1.3, -0.7, -0.1, 0.0, 0.2, 0.9, 2.5, 6.0, 40.0}) {
    const double v1 = x1 / sa;
    const TabulatedLaw law([&](double w) { return w * f(v1 - w); });  // g_+ in w = v1 - v
    // Flux: rho int (v1 - v) f dv.
    const double flux = bath.rho * law.total;
    ASSERT_GT(flux, 0.0) << name << " x1 = " << x1;
    EXPECT_NEAR(bath.flux_right(v1), flux, 1e-7 * flux) << name << " x1 = " << x1;
    // Samples.
    const int n = 100000;
    std::vector<double> w;
    std::uint64_t attempts = 0;
    for (int s = 0; s < n; ++s) {
      double v;
      for (std::uint64_t k = 0;; ++k) {
        ++attempts;
        if (bath.try_sample_right(v1, rng.block(RngPurpose::intruder_event, 0, s, k), v)) break;
      }
      ASSERT_LE(v, v1) << name;
      w.push_back(v1 - v);
    }
    std::sort(w.begin(), w.end());
    double ks = 0.0, sum = 0.0;
    for (int s = 0; s < n; ++s) {
      const double c = law.at(w[s]);
      ks = std::max({ks, std::fabs(c - static_cast<double>(s) / n), std::fabs(c - static_cast<double>(s + 1) / n)});
      sum += w[s];
    }
    const double acceptance = static_cast<double>(n) / static_cast<double>(attempts);
    // Kolmogorov-Smirnov: sup |F_n - F| < 1.95 / sqrt(n) with probability 0.999.
    EXPECT_LT(ks, 1.95 / std::sqrt(n)) << name << " x1 = " << x1;
    EXPECT_GT(acceptance, 0.3) << name << " x1 = " << x1;  // bounded below for every v1: no window, no stall
    if (std::string(name) == "gaussian") {                 // finite variance: the mean within 5 standard errors
      double var = 0.0;
      for (double x : w) var += (x - sum / n) * (x - sum / n);
      EXPECT_NEAR(sum / n, law.mean, 5.0 * std::sqrt(var / n / n)) << name << " x1 = " << x1;
    }
  }
}

}  // namespace

TEST(Bath, GaussianFluxAndExactSampling) {
  const GaussianBath bath{0.7, 1.3};
  check_bath(
      bath, [&](double v) { return std::sqrt(bath.a / std::numbers::pi) * std::exp(-bath.a * v * v); }, "gaussian",
      -19.0);
}

TEST(Bath, PowerLawFluxAndExactSampling) {
  const PowerLawBath bath{1.8, 0.6};
  check_bath(
      bath,
      [&](double v) { return std::sqrt(2.0 * bath.a) / std::numbers::pi / (1.0 + bath.a * bath.a * v * v * v * v); },
      "power-law", -300.0);
}

TEST(Bath, FluxesMatchThePaperClosedFormAndSymmetry) {
  // 002 eq. (19)-(20) as printed, and phi_+ + phi_- = phi.
  const GaussianBath g{2.0, 1.5};
  for (double v1 : {-2.0, -0.3, 0.0, 0.8, 3.0}) {
    const double paper_plus =
        g.rho / 2.0 *
        (v1 + std::exp(-g.a * v1 * v1) / std::sqrt(std::numbers::pi * g.a) + v1 * std::erf(v1 * std::sqrt(g.a)));
    const double paper_total =
        g.rho * (std::exp(-g.a * v1 * v1) / std::sqrt(std::numbers::pi * g.a) + v1 * std::erf(v1 * std::sqrt(g.a)));
    EXPECT_NEAR(g.flux_right(v1), paper_plus, 1e-14);
    EXPECT_NEAR(g.flux_right(v1) + g.flux_right(-v1), paper_total, 1e-14);
  }
  // The power-law series and closed form agree where both apply.
  const PowerLawBath p{1.0, 1.0};
  const double below = p.flux_right(-2.0 - 1e-12), above = p.flux_right(-2.0 + 1e-12);
  EXPECT_NEAR(below, above, 1e-10 * above);
}
