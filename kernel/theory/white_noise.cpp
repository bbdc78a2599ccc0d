#include "kernel/theory/white_noise.hpp"

#include <array>
#include <cmath>
#include <map>
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

namespace {

/// A polynomial in X = |G|^2, Y = |u|^2 and C = cos^2(G, u) of a colliding pair c1 = G + u/2, c2 = G - u/2
/// (docs/methods/derivations/vhs-white-noise-a2.md): the exponents (i, j, k) of X^i Y^j C^k and their coefficients.
class PairPolynomial {
 public:
  PairPolynomial(double constant = 0.0) {  // NOLINT(google-explicit-constructor): a number is a polynomial
    if (constant != 0.0) terms_[{0, 0, 0}] = constant;
  }
  static PairPolynomial monomial(int i, int j, int k, double coefficient = 1.0) {
    PairPolynomial p;
    p.terms_[{i, j, k}] = coefficient;
    return p;
  }
  friend PairPolynomial operator+(PairPolynomial a, const PairPolynomial& b) {
    for (const auto& [e, c] : b.terms_) a.terms_[e] += c;
    return a;
  }
  friend PairPolynomial operator-(const PairPolynomial& a, const PairPolynomial& b) { return a + (-1.0) * b; }
  friend PairPolynomial operator*(const PairPolynomial& a, const PairPolynomial& b) {
    PairPolynomial p;
    for (const auto& [ea, ca] : a.terms_)
      for (const auto& [eb, cb] : b.terms_) p.terms_[{ea[0] + eb[0], ea[1] + eb[1], ea[2] + eb[2]}] += ca * cb;
    return p;
  }
  friend PairPolynomial operator*(double x, PairPolynomial a) {
    for (auto& term : a.terms_) term.second *= x;
    return a;
  }
  /// The pair average weighted by |u|^lambda over its Maxwellian value: X^i Y^j C^k -> 2^-i (d/2)_i x
  /// 2^j ((d + lambda)/2)_j x (1/2)_k / (d/2)_k, (x)_n the rising factorial.
  [[nodiscard]] double average(double lambda, double d) const {
    const auto rising = [](double x, int n) {
      double r = 1.0;
      for (int m = 0; m < n; ++m) r *= x + m;
      return r;
    };
    double total = 0.0;
    for (const auto& [e, c] : terms_)
      total += c * std::pow(0.5, e[0]) * rising(0.5 * d, e[0]) * std::pow(2.0, e[1]) *
               rising(0.5 * (d + lambda), e[1]) * rising(0.5, e[2]) / rising(0.5 * d, e[2]);
    return total;
  }

 private:
  std::map<std::array<int, 3>, double> terms_;
};

}  // namespace

SecondSonine isotropic_white_noise_second_sonine(double alpha, double lambda, int dimension) {
  // docs/methods/derivations/vhs-white-noise-a2.md, "Second Sonine"; docs/methods/derivations/vhs_white_noise_a2.py
  // does the same symbolically.
  const double d = dimension, a = 0.5 * (1.0 - alpha), b = 0.5 * (1.0 + alpha), s = a * a + b * b;
  const PairPolynomial x = PairPolynomial::monomial(1, 0, 0), y = PairPolynomial::monomial(0, 1, 0);
  const PairPolynomial z = PairPolynomial::monomial(1, 1, 1);  // (G.u)^2
  const PairPolynomial q = x + 0.25 * y;                       // c1^2 = Q + G.u, c2^2 = Q - G.u
  const PairPolynomial sum2 = 2.0 * q, sum4 = 2.0 * q * q + 2.0 * z, sum6 = 2.0 * q * q * q + 6.0 * q * z;
  // S2(c1^2) + S2(c2^2) and S3(c1^2) + S3(c2^2) from the sums of c^2, c^4, c^6
  const PairPolynomial s2 = 0.5 * sum4 - 0.5 * (d + 2.0) * sum2 + PairPolynomial(d * (d + 2.0) / 4.0);
  const PairPolynomial s3 = (-1.0 / 6.0) * sum6 + 0.25 * (d + 4.0) * sum4 - (d + 2.0) * (d + 4.0) / 8.0 * sum2 +
                            PairPolynomial(d * (d + 2.0) * (d + 4.0) / 24.0);
  // 001 eq. (4), u' = a u + b |u| e, averaged over e uniform on S^(d-1)
  const PairPolynomial u2 = s * y, u4 = (s * s + 4.0 * a * a * b * b / d) * (y * y);
  const PairPolynomial u6 = (s * s * s + 12.0 * s * a * a * b * b / d) * (y * y * y);
  const PairPolynomial gu2 = a * a * z + (b * b / d) * (x * y);  // (G.u')^2
  const PairPolynomial u2gu2 = y * (s * a * a * z + (s * b * b / d) * (x * y) + (4.0 * a * a * b * b / d) * z);
  const PairPolynomial delta2 = 0.5 * (u2 - y);
  const PairPolynomial delta4 = 2.0 * (x * x + 0.5 * (x * u2) + u4 * (1.0 / 16.0)) + 2.0 * gu2 - sum4;
  const PairPolynomial delta6 = 2.0 * (x * x * x + 0.75 * (x * x * u2) + (3.0 / 16.0) * (x * u4) + u6 * (1.0 / 64.0)) +
                                6.0 * (x * gu2 + 0.25 * u2gu2) - sum6;
  // A_p = A_p0 + a2 A_p2 + a3 A_p3, A_pq = -(1/2) E[|u|^lambda Delta_p S_q]; E4 = A_4 - (d + 2) A_2,
  // E6 = A_6 - (3/4)(d + 2)(d + 4) A_2 (1 + a2), linear in (a2, a3) (docs/methods/derivations/sonine-hcs.md, "White
  // noise")
  const auto moments = [&](const PairPolynomial& delta) {
    return std::array<double, 3>{(-0.5 * delta).average(lambda, d), (-0.5 * (delta * s2)).average(lambda, d),
                                 (-0.5 * (delta * s3)).average(lambda, d)};
  };
  const std::array<double, 3> m2 = moments(delta2), m4 = moments(delta4), m6 = moments(delta6);
  const double k6 = 0.75 * (d + 2.0) * (d + 4.0);
  const double e4[3] = {m4[0] - (d + 2.0) * m2[0], m4[1] - (d + 2.0) * m2[1], m4[2] - (d + 2.0) * m2[2]};
  const double e6[3] = {m6[0] - k6 * m2[0], m6[1] - k6 * (m2[1] + m2[0]), m6[2] - k6 * m2[2]};
  const double det = e4[1] * e6[2] - e4[2] * e6[1];
  return {(e4[2] * e6[0] - e4[0] * e6[2]) / det, (e4[0] * e6[1] - e4[1] * e6[0]) / det};
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
  // docs/methods/derivations/vhs_white_noise_a2.py: a2 = 16 (1 - alpha) N / D with
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
