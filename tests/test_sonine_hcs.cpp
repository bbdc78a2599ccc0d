#include <cmath>

#include <gtest/gtest.h>

#include "kernel/theory/sonine.hpp"
#include "kernel/theory/sonine_hcs.hpp"

// Beyond-linear Sonine theory of the HCS (kernel/theory/sonine_hcs.hpp, docs/derivations/sonine-hcs.md).
// Reference numbers below are from our own exact (rational-arithmetic) derivation,
// docs/derivations/sonine_hcs.py, not transcribed from the literature.

using namespace granmc::theory;

namespace {

// HCS residuals E4 = mu_4 - (4/3) mu_2 <c^4>, E6 = mu_6 - 2 mu_2 <c^6>, units of sqrt(2 pi).
double e4(double alpha, double a2, double a3) {
  const SonineMoments m = hcs_collisional_moments(alpha, a2, a3);
  return m.mu4 - 5.0 * m.mu2 * (1.0 + a2);
}
double e6(double alpha, double a2, double a3) {
  const SonineMoments m = hcs_collisional_moments(alpha, a2, a3);
  return m.mu6 - 26.25 * m.mu2 * (1.0 + 3.0 * a2 - a3);
}

// Value and first derivatives at (0, 0) of a function that is a polynomial of low degree in (a2, a3): the
// central difference is exact for a quadratic and the cubic remainder of E_p is O(h^2).
struct Linear {
  double a, b, c;
};
template <class F>
Linear linearise(F f) {
  const double h = 1e-5;
  return {f(0.0, 0.0), (f(h, 0.0) - f(-h, 0.0)) / (2.0 * h), (f(0.0, h) - f(0.0, -h)) / (2.0 * h)};
}

}  // namespace

TEST(SonineHcs, Mu2IsHaffRateWithFirstSonineCorrection) {
  for (double alpha : {0.1, 0.5, 0.8, 0.95}) {
    const double e = 1.0 - alpha * alpha;
    EXPECT_NEAR(hcs_collisional_moments(alpha, 0.0, 0.0).mu2, e, 1e-15);
    const Linear l = linearise([&](double x, double y) { return hcs_collisional_moments(alpha, x, y).mu2; });
    EXPECT_NEAR(l.b, 3.0 * e / 16.0, 1e-9);
    EXPECT_NEAR(l.c, e / 64.0, 1e-9);
  }
}

TEST(SonineHcs, LinearTruncationReproducesVanNoijeErnst) {
  for (double alpha = 0.0; alpha <= 1.0 + 1e-12; alpha += 0.05) {
    const Linear l = linearise([&](double x, double) { return e4(alpha, x, 0.0); });
    EXPECT_NEAR(-l.a / l.b, hcs_a2(alpha), 1e-9) << "alpha = " << alpha;
  }
}

TEST(SonineHcs, ElasticLimitIsMaxwellian) {
  EXPECT_EQ(hcs_a2_nonlinear(1.0), 0.0);
  EXPECT_NEAR(hcs_second_sonine(1.0).a2, 0.0, 1e-300);
  EXPECT_NEAR(hcs_second_sonine(1.0).a3, 0.0, 1e-300);
  EXPECT_NEAR(hcs_second_sonine_nonlinear(1.0).a2, 0.0, 1e-15);
  EXPECT_NEAR(hcs_second_sonine_nonlinear(1.0).a3, 0.0, 1e-15);
  // A Maxwellian is collisionally invariant for elastic spheres.
  const SonineMoments m = hcs_collisional_moments(1.0, 0.0, 0.0);
  EXPECT_EQ(m.mu2, 0.0);
  EXPECT_EQ(m.mu4, 0.0);
  EXPECT_EQ(m.mu6, 0.0);
  // Quasi-elastic slopes, a_p ~ s_p (1 - alpha): first Sonine s2 = -1/4 (linear and nonlinear agree to
  // O((1 - alpha)^2)); second Sonine s2 = -21/80, s3 = -1/20 -- a3 is of the same order as a2 and shifts
  // a2 already at first order in 1 - alpha.
  const double eps = 1e-6;
  EXPECT_NEAR(hcs_a2(1.0 - eps) / eps, -0.25, 1e-5);
  EXPECT_NEAR(hcs_a2_nonlinear(1.0 - eps) / eps, -0.25, 1e-5);
  EXPECT_NEAR(hcs_second_sonine(1.0 - eps).a2 / eps, -21.0 / 80.0, 1e-5);
  EXPECT_NEAR(hcs_second_sonine(1.0 - eps).a3 / eps, -1.0 / 20.0, 1e-5);
  EXPECT_NEAR(hcs_second_sonine_nonlinear(1.0 - eps).a2 / eps, -21.0 / 80.0, 1e-5);
}

TEST(SonineHcs, SecondSonineSolvesLinearisedMomentEquations) {
  for (double alpha = 0.0; alpha < 1.0; alpha += 0.05) {
    const Linear l4 = linearise([&](double x, double y) { return e4(alpha, x, y); });
    const Linear l6 = linearise([&](double x, double y) { return e6(alpha, x, y); });
    const SecondSonine s = hcs_second_sonine(alpha);
    EXPECT_NEAR(l4.a + l4.b * s.a2 + l4.c * s.a3, 0.0, 1e-8) << "alpha = " << alpha;
    EXPECT_NEAR(l6.a + l6.b * s.a2 + l6.c * s.a3, 0.0, 1e-7) << "alpha = " << alpha;
    // Cramer's rule from the moment polynomials agrees with the closed form.
    const double det = l4.b * l6.c - l4.c * l6.b;
    EXPECT_NEAR((-l4.a * l6.c + l4.c * l6.a) / det, s.a2, 1e-8) << "alpha = " << alpha;
    EXPECT_NEAR((-l4.b * l6.a + l4.a * l6.b) / det, s.a3, 1e-8) << "alpha = " << alpha;
  }
}

TEST(SonineHcs, NonlinearSolutionsHaveZeroResidual) {
  for (double alpha = 0.0; alpha < 1.0; alpha += 0.05) {
    const double x = hcs_a2_nonlinear(alpha);
    EXPECT_NEAR(e4(alpha, x, 0.0), 0.0, 1e-14) << "alpha = " << alpha;
    EXPECT_LT(std::abs(x - hcs_a2(alpha)), 0.02) << "alpha = " << alpha;  // the physical root
    const SecondSonine s = hcs_second_sonine_nonlinear(alpha);
    EXPECT_NEAR(e4(alpha, s.a2, s.a3), 0.0, 1e-14) << "alpha = " << alpha;
    EXPECT_NEAR(e6(alpha, s.a2, s.a3), 0.0, 1e-13) << "alpha = " << alpha;
    EXPECT_LT(std::abs(s.a2 - hcs_second_sonine(alpha).a2), 0.005) << "alpha = " << alpha;
  }
}

TEST(SonineHcs, ValuesFromExactDerivation) {
  // alpha = 1/2: linear second Sonine a2 = 113008/2511625, a3 = -44416/2511625 (exact rationals).
  EXPECT_NEAR(hcs_second_sonine(0.5).a2, 113008.0 / 2511625.0, 1e-15);
  EXPECT_NEAR(hcs_second_sonine(0.5).a3, -44416.0 / 2511625.0, 1e-15);
  EXPECT_NEAR(hcs_second_sonine(0.8).a2, -154318288.0 / 10958251385.0, 1e-15);
  EXPECT_NEAR(hcs_second_sonine(0.8).a3, -51832448.0 / 10958251385.0, 1e-15);
  EXPECT_NEAR(hcs_second_sonine(0.9).a2, -2603389008.0 / 166225387685.0, 1e-15);
  EXPECT_NEAR(hcs_second_sonine(0.9).a3, -643700608.0 / 166225387685.0, 1e-15);
  // Roots of the exact equations (40-digit sympy nsolve).
  EXPECT_NEAR(hcs_a2_nonlinear(0.5), 0.052964085534803122, 1e-14);
  EXPECT_NEAR(hcs_a2_nonlinear(0.8), -0.012567649049597848, 1e-14);
  EXPECT_NEAR(hcs_a2_nonlinear(0.9), -0.014556783643851375, 1e-14);
  EXPECT_NEAR(hcs_second_sonine_nonlinear(0.5).a2, 0.044982735426126897, 1e-14);
  EXPECT_NEAR(hcs_second_sonine_nonlinear(0.5).a3, -0.018549219057136016, 1e-14);
  EXPECT_NEAR(hcs_second_sonine_nonlinear(0.8).a2, -0.014082511968051245, 1e-14);
  EXPECT_NEAR(hcs_second_sonine_nonlinear(0.8).a3, -0.0047670808508758306, 1e-14);
  EXPECT_NEAR(hcs_second_sonine_nonlinear(0.9).a2, -0.015670213193269382, 1e-14);
  EXPECT_NEAR(hcs_second_sonine_nonlinear(0.9).a3, -0.0039145621948056657, 1e-14);
}

TEST(SonineHcs, CoolingRateFactorIsMu2Ratio) {
  for (double alpha : {0.2, 0.8})
    for (double a2 : {-0.1, 0.0, 0.3})
      for (double a3 : {-0.2, 0.05}) {
        const double ratio = hcs_collisional_moments(alpha, a2, a3).mu2 / hcs_collisional_moments(alpha, 0.0, 0.0).mu2;
        EXPECT_NEAR(hcs_cooling_rate_factor(a2, a3), ratio, 1e-15);
      }
  EXPECT_EQ(hcs_cooling_rate_factor(0.0, 0.0), 1.0);
}
