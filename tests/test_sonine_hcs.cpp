#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "kernel/theory/sonine.hpp"
#include "kernel/theory/sonine_hcs.hpp"
#include "kernel/theory/white_noise.hpp"

// Beyond-linear Sonine theory of the HCS (kernel/theory/sonine_hcs.hpp, docs/methods/derivations/sonine-hcs.md).
// Reference numbers below are from our own exact (rational-arithmetic) derivation,
// docs/methods/derivations/sonine_hcs.py, not transcribed from the literature.

using namespace granmc::theory;

namespace {

// HCS residuals E4 = mu_4 - (4/d) mu_2 <c^4>, E6 = mu_6 - (6/d) mu_2 <c^6>, units of sqrt(2 pi), with
// <c^4> = d(d+2)/4 (1 + a2), <c^6> = d(d+2)(d+4)/8 (1 + 3 a2 - a3): 5 and 26.25 for spheres, 4 and 18 for disks.
double e4(double alpha, double a2, double a3, int d = 3) {
  const SonineMoments m = hcs_collisional_moments(alpha, a2, a3, d);
  return m.mu4 - (d == 3 ? 5.0 : 4.0) * m.mu2 * (1.0 + a2);
}
double e6(double alpha, double a2, double a3, int d = 3) {
  const SonineMoments m = hcs_collisional_moments(alpha, a2, a3, d);
  return m.mu6 - (d == 3 ? 26.25 : 18.0) * m.mu2 * (1.0 + 3.0 * a2 - a3);
}

// White-noise residuals: the noise term (xi/2) Lap_c F with xi = mu_2 / d gives mu_p = (p (p + d - 2) / d) mu_2
// <c^(p - 2)>, so E4 = mu_4 - (d + 2) mu_2 and E6 = mu_6 - (3/4)(d + 2)(d + 4) mu_2 (1 + a2).
double wn_e4(double alpha, double a2, double a3, int d) {
  const SonineMoments m = hcs_collisional_moments(alpha, a2, a3, d);
  return m.mu4 - (d + 2.0) * m.mu2;
}
double wn_e6(double alpha, double a2, double a3, int d) {
  const SonineMoments m = hcs_collisional_moments(alpha, a2, a3, d);
  return m.mu6 - 0.75 * (d + 2.0) * (d + 4.0) * m.mu2 * (1.0 + a2);
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
  for (const int d : {3, 2})
    for (double alpha = 0.0; alpha <= 1.0 + 1e-12; alpha += 0.05) {
      const Linear l = linearise([&](double x, double) { return e4(alpha, x, 0.0, d); });
      EXPECT_NEAR(-l.a / l.b, hcs_a2(alpha, d), 1e-9) << "alpha = " << alpha << ", d = " << d;
    }
}

TEST(SonineHcs, ElasticLimitIsMaxwellian) {
  EXPECT_EQ(hcs_a2_nonlinear(1.0), 0.0);
  EXPECT_NEAR(hcs_second_sonine(1.0).a2, 0.0, 1e-300);
  EXPECT_NEAR(hcs_second_sonine(1.0).a3, 0.0, 1e-300);
  EXPECT_NEAR(second_sonine_nonlinear(1.0, SonineState::cooling).a2, 0.0, 1e-15);
  EXPECT_NEAR(second_sonine_nonlinear(1.0, SonineState::cooling).a3, 0.0, 1e-15);
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
  EXPECT_NEAR(second_sonine_nonlinear(1.0 - eps, SonineState::cooling).a2 / eps, -21.0 / 80.0, 1e-5);
}

TEST(SonineHcs, SecondSonineSolvesLinearisedMomentEquations) {
  for (const int d : {3, 2})
    for (double alpha = 0.0; alpha < 1.0; alpha += 0.05) {
      SCOPED_TRACE("alpha = " + std::to_string(alpha) + ", d = " + std::to_string(d));
      const Linear l4 = linearise([&](double x, double y) { return e4(alpha, x, y, d); });
      const Linear l6 = linearise([&](double x, double y) { return e6(alpha, x, y, d); });
      const SecondSonine s = hcs_second_sonine(alpha, d);
      EXPECT_NEAR(l4.a + l4.b * s.a2 + l4.c * s.a3, 0.0, 1e-8);
      EXPECT_NEAR(l6.a + l6.b * s.a2 + l6.c * s.a3, 0.0, 1e-7);
      // Cramer's rule from the moment polynomials agrees with the closed form.
      const double det = l4.b * l6.c - l4.c * l6.b;
      EXPECT_NEAR((-l4.a * l6.c + l4.c * l6.a) / det, s.a2, 1e-8);
      EXPECT_NEAR((-l4.b * l6.a + l4.a * l6.b) / det, s.a3, 1e-8);
    }
}

TEST(SonineHcs, NonlinearSolutionsHaveZeroResidual) {
  for (const int d : {3, 2})
    for (double alpha = 0.0; alpha < 1.0; alpha += 0.05) {
      SCOPED_TRACE("alpha = " + std::to_string(alpha) + ", d = " + std::to_string(d));
      // The physical roots (the others lie beyond -23 and +2): within these distances of the linear values,
      // wider for disks, whose a2 is larger (0.044 at alpha = 0).
      const double first = d == 3 ? 0.02 : 0.05, second = d == 3 ? 0.005 : 0.01;
      const double x = hcs_a2_nonlinear(alpha, d);
      EXPECT_NEAR(e4(alpha, x, 0.0, d), 0.0, 1e-14);
      EXPECT_LT(std::abs(x - hcs_a2(alpha, d)), first);
      const SecondSonine s = second_sonine_nonlinear(alpha, SonineState::cooling, d);
      EXPECT_NEAR(e4(alpha, s.a2, s.a3, d), 0.0, 1e-14);
      EXPECT_NEAR(e6(alpha, s.a2, s.a3, d), 0.0, 1e-13);
      EXPECT_LT(std::abs(s.a2 - hcs_second_sonine(alpha, d).a2), second);
    }
}

TEST(SonineHcs, GeneralLinearSolutionIsTheClosedForm) {
  for (const int d : {3, 2})
    for (double alpha = 0.0; alpha <= 1.0; alpha += 0.05) {
      SCOPED_TRACE("alpha = " + std::to_string(alpha) + ", d = " + std::to_string(d));
      const SecondSonine general = second_sonine_linear(alpha, SonineState::cooling, d);
      const SecondSonine closed = hcs_second_sonine(alpha, d);
      EXPECT_NEAR(general.a2, closed.a2, 1e-14);
      EXPECT_NEAR(general.a3, closed.a3, 1e-14);
    }
}

TEST(WhiteNoiseSonine, LinearTruncationReproducesVanNoijeErnst) {
  // The white-noise condition E4 with a3 = 0, linearised, is van Noije and Ernst's a2 (theory::white_noise_a2,
  // written from their closed form): the conditions of the second Sonine are those of the first, plus E6.
  for (const int d : {3, 2})
    for (double alpha = 0.0; alpha <= 1.0; alpha += 0.05) {
      SCOPED_TRACE("alpha = " + std::to_string(alpha) + ", d = " + std::to_string(d));
      const Linear l4 = linearise([&](double x, double y) { return wn_e4(alpha, x, y, d); });
      EXPECT_NEAR(-l4.a / l4.b, white_noise_a2(alpha, d), 1e-9);  // the differences' rounding: about 1e-10
    }
}

TEST(WhiteNoiseSonine, SecondSonineSolvesTheConditions) {
  for (const int d : {3, 2}) {
    EXPECT_EQ(second_sonine_linear(1.0, SonineState::white_noise, d).a2, 0.0);
    EXPECT_EQ(second_sonine_linear(1.0, SonineState::white_noise, d).a3, 0.0);
    for (double alpha = 0.0; alpha < 1.0; alpha += 0.05) {
      SCOPED_TRACE("alpha = " + std::to_string(alpha) + ", d = " + std::to_string(d));
      const Linear l4 = linearise([&](double x, double y) { return wn_e4(alpha, x, y, d); });
      const Linear l6 = linearise([&](double x, double y) { return wn_e6(alpha, x, y, d); });
      const SecondSonine s = second_sonine_linear(alpha, SonineState::white_noise, d);
      EXPECT_NEAR(l4.a + l4.b * s.a2 + l4.c * s.a3, 0.0, 1e-8);
      EXPECT_NEAR(l6.a + l6.b * s.a2 + l6.c * s.a3, 0.0, 1e-7);
      const SecondSonine n = second_sonine_nonlinear(alpha, SonineState::white_noise, d);
      EXPECT_NEAR(wn_e4(alpha, n.a2, n.a3, d), 0.0, 1e-14);
      EXPECT_NEAR(wn_e6(alpha, n.a2, n.a3, d), 0.0, 1e-13);
      // White noise keeps F closer to the Maxwellian than cooling does: a2 within 0.005 of the linear one
      EXPECT_LT(std::abs(n.a2 - s.a2), 0.005);
      EXPECT_NEAR(white_noise_a2_model_error(alpha, d), std::abs(s.a2 - white_noise_a2(alpha, d)), 1e-15);
    }
  }
  for (const int d : {3, 2})
    for (const double alpha : {0.1, 0.5, 0.8, 0.9}) {
      const SecondSonine s = second_sonine_linear(alpha, SonineState::white_noise, d);
      const SecondSonine n = second_sonine_nonlinear(alpha, SonineState::white_noise, d);
      std::printf(
          "[ values ] d = %d, alpha = %.1f: first Sonine a2 %.5f; second Sonine a2 %.5f, a3 %.5f; "
          "nonlinear a2 %.5f, a3 %.5f\n",
          d, alpha, white_noise_a2(alpha, d), s.a2, s.a3, n.a2, n.a3);
    }
}

TEST(IsotropicWhiteNoiseA2, HasTheExactLimitsAndTheDerivationsValues) {
  // docs/methods/derivations/vhs_white_noise_a2.py: lambda = 0 is the exact Maxwell a2, lambda = 1 with d = 3 van Noije
  // and Ernst's hard spheres (whose e is uniform); in between the script's exact rationals.
  for (const int d : {3, 2})
    for (double alpha = 0.0; alpha <= 1.0; alpha += 0.05) {
      SCOPED_TRACE("alpha = " + std::to_string(alpha) + ", d = " + std::to_string(d));
      EXPECT_NEAR(isotropic_white_noise_a2(alpha, 0.0, d), maxwell_white_noise_a2(alpha, d), 1e-15);
      if (d == 3) {
        EXPECT_NEAR(isotropic_white_noise_a2(alpha, 1.0, d), white_noise_a2(alpha, d), 1e-15);
      }
    }
  EXPECT_EQ(isotropic_white_noise_a2(1.0, 0.5, 2), 0.0);
  EXPECT_NEAR(isotropic_white_noise_a2(0.5, 0.5, 2), 448.0 / 7365.0, 1e-15);
  EXPECT_NEAR(isotropic_white_noise_a2(0.5, 0.5, 3), 64.0 / 1235.0, 1e-15);
  EXPECT_NEAR(isotropic_white_noise_a2(0.1, 0.25, 3), 1366272.0 / 11292239.0, 1e-15);
  EXPECT_NEAR(isotropic_white_noise_a2(0.9, 0.25, 2), 43264.0 / 23782143.0, 1e-15);
}

TEST(IsotropicWhiteNoiseSecondSonine, HasTheExactLimitsAndTheDerivationsValues) {
  // docs/methods/derivations/vhs_white_noise_a2.py, "Second Sonine": lambda = 1 with d = 3 is the hard spheres' linear
  // second Sonine (their e is uniform); lambda = 0 keeps the exact Maxwell a2; at lambda = 1/2 the script's exact
  // rationals.
  for (double alpha = 0.05; alpha < 1.0; alpha += 0.05) {
    SCOPED_TRACE("alpha = " + std::to_string(alpha));
    const SecondSonine hard = second_sonine_linear(alpha, SonineState::white_noise, 3);
    const SecondSonine isotropic = isotropic_white_noise_second_sonine(alpha, 1.0, 3);
    EXPECT_NEAR(isotropic.a2, hard.a2, 1e-14);
    EXPECT_NEAR(isotropic.a3, hard.a3, 1e-14);
    for (const int d : {3, 2})
      EXPECT_NEAR(isotropic_white_noise_second_sonine(alpha, 0.0, d).a2, maxwell_white_noise_a2(alpha, d), 1e-14);
  }
  const SecondSonine disks = isotropic_white_noise_second_sonine(0.5, 0.5, 2);
  EXPECT_NEAR(disks.a2, 1832651328.0 / 30764861953.0, 1e-15);
  EXPECT_NEAR(disks.a3, -266617856.0 / 21974901395.0, 1e-15);
  const SecondSonine spheres = isotropic_white_noise_second_sonine(0.5, 0.5, 3);
  EXPECT_NEAR(spheres.a2, 61435712.0 / 1209815701.0, 1e-15);
  EXPECT_NEAR(spheres.a3, -60017664.0 / 6049078505.0, 1e-15);
}

/// Hard disks: the table of docs/methods/derivations/sonine-hcs.md ("Hard disks"), printed to 8 decimals by
/// `docs/methods/derivations/sonine_hcs.py --dimension 2`: linear and nonlinear first Sonine, linear and nonlinear
/// second Sonine (a2, a3).
TEST(SonineHcs, DisksAgreeWithTheDerivationsTable) {
  struct Row {
    double alpha, vne, nl1, a2_2s, a3_2s, a2_2s_nl, a3_2s_nl;
  };
  const Row rows[] = {
      {0.1, 0.25765930, 0.29059686, 0.13038575, -0.20564267, 0.12492829, -0.22253686},
      {0.3, 0.17871181, 0.19021656, 0.11301607, -0.11937078, 0.11077182, -0.12974396},
      {0.5, 0.08290155, 0.08458670, 0.06545421, -0.03710564, 0.06531892, -0.03942245},
      {0.7, 0.00218629, 0.00218699, -0.00140185, -0.00927205, -0.00140094, -0.00927007},
      {0.8, -0.02193928, -0.02189282, -0.02550735, -0.01035679, -0.02548223, -0.01046648},
      {0.9, -0.02686163, -0.02683265, -0.02967104, -0.00936598, -0.02967858, -0.00950248},
  };
  for (const Row& r : rows) {
    SCOPED_TRACE("alpha = " + std::to_string(r.alpha));
    EXPECT_NEAR(hcs_a2(r.alpha, 2), r.vne, 5e-9);
    EXPECT_NEAR(hcs_a2_nonlinear(r.alpha, 2), r.nl1, 5e-9);
    EXPECT_NEAR(hcs_second_sonine(r.alpha, 2).a2, r.a2_2s, 5e-9);
    EXPECT_NEAR(hcs_second_sonine(r.alpha, 2).a3, r.a3_2s, 5e-9);
    EXPECT_NEAR(second_sonine_nonlinear(r.alpha, SonineState::cooling, 2).a2, r.a2_2s_nl, 5e-9);
    EXPECT_NEAR(second_sonine_nonlinear(r.alpha, SonineState::cooling, 2).a3, r.a3_2s_nl, 5e-9);
  }
  // mu_2 of disks is half that of spheres at every (a2, a3) (docs/methods/derivations/sonine-hcs.md).
  EXPECT_EQ(hcs_collisional_moments(0.6, 0.05, -0.02, 2).mu2, 0.5 * hcs_collisional_moments(0.6, 0.05, -0.02).mu2);
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
  EXPECT_NEAR(second_sonine_nonlinear(0.5, SonineState::cooling).a2, 0.044982735426126897, 1e-14);
  EXPECT_NEAR(second_sonine_nonlinear(0.5, SonineState::cooling).a3, -0.018549219057136016, 1e-14);
  EXPECT_NEAR(second_sonine_nonlinear(0.8, SonineState::cooling).a2, -0.014082511968051245, 1e-14);
  EXPECT_NEAR(second_sonine_nonlinear(0.8, SonineState::cooling).a3, -0.0047670808508758306, 1e-14);
  EXPECT_NEAR(second_sonine_nonlinear(0.9, SonineState::cooling).a2, -0.015670213193269382, 1e-14);
  EXPECT_NEAR(second_sonine_nonlinear(0.9, SonineState::cooling).a3, -0.0039145621948056657, 1e-14);
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

TEST(WhiteNoiseTemperature, IsThe001EnergyBalanceForHardSpheresAndBalancesTheHeating) {
  // 000's hard spheres with n sigma^2 = 4 rate are 001's kernel form with lambda = 1 (collide/pair_coefficients.cpp):
  // the two energy balances give the same steady temperature, with or without the first-Sonine factor.
  for (double alpha : {0.3, 0.7, 0.95})
    for (double a2 : {0.0, 0.05}) {
      const double rate = 0.7, beta = 1.3;
      const double t = granmc::theory::white_noise_temperature(alpha, 4.0 * rate, 1.0, 1.0, 1.0, beta, a2, 3);
      EXPECT_NEAR(t, granmc::theory::white_noise_steady_temperature(1.0, rate, alpha, beta, a2), 1e-12 * t) << alpha;
    }
  // Hard disks with n sigma = pi rate are 001's kernel form in the plane (collide/pair_coefficients.cpp), whose
  // energy balance carries <1 - mu> = 4/3 of the hard-disk law (tests/test_collision_rule.cpp, HardDiskScattering).
  for (double alpha : {0.3, 0.7, 0.95})
    for (double a2 : {0.0, 0.05}) {
      const double rate = 0.7, beta = 1.3;
      const double t =
          granmc::theory::white_noise_temperature(alpha, std::numbers::pi * rate, 1.0, 1.0, 1.0, beta, a2, 2);
      EXPECT_NEAR(t, granmc::theory::white_noise_steady_temperature(1.0, rate, alpha, beta, a2, 2), 1e-12 * t) << alpha;
    }
  // Disks, mass 2, chi 1.4: at the steady temperature the cooling zeta T takes the heating 2 beta m.
  const double t = granmc::theory::white_noise_temperature(0.6, 0.8, 1.2, 2.0, 1.4, 0.9, 0.03, 2);
  EXPECT_NEAR(granmc::theory::cooling_rate(0.6, 0.8, 1.2, 2.0, t, 1.4, 0.03, 2) * t, 2.0 * 0.9 * 2.0, 1e-12);
}
