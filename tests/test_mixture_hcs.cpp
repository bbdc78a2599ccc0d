#include <array>
#include <cmath>
#include <initializer_list>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "kernel/theory/mixture_hcs.hpp"
#include "kernel/theory/sonine.hpp"

// HCS of a binary granular mixture (kernel/theory/mixture_hcs.hpp, docs/methods/derivations/mixture-hcs.md).
// Reference numbers are from our own exact derivation, docs/methods/derivations/mixture_hcs.py (which reproduces them
// independently in Python), not transcribed from the literature.

using namespace granmc::theory;

namespace {

const double pi = std::numbers::pi;

double zeta_gap(const MixtureParameters& mp, double gamma, double a0, double a1) {
  const double z0 = partial_cooling_rate(mp, 0, gamma, 1.0, a0, a1);
  const double z1 = partial_cooling_rate(mp, 1, gamma, 1.0, a0, a1);
  return std::abs(z0 - z1) / (std::abs(z0) + std::abs(z1));
}

// Exact (bilinear) cooling rate from the collisional moments: zeta_i = -(m_i / (3 T_i)) sum_j M2_ij.
double zeta_exact(const MixtureParameters& mp, int i, const double T[2], const double a[2]) {
  double s = 0.0;
  for (int j = 0; j < 2; ++j) s += collisional_moment(mp, i, j, 2, T[0], T[1], a[0], a[1]);
  return -mp.mass[i] / (3.0 * T[i]) * s;
}

// HCS fourth-moment residual of species i, no linearisation: sum_j M4_ij + 2 zeta_i <v^4>_i,
// <v^4>_i = 15 theta_i^2 (1 + a_i).
double e4_exact(const MixtureParameters& mp, int i, const double T[2], const double a[2]) {
  double s = 0.0;
  for (int j = 0; j < 2; ++j) s += collisional_moment(mp, i, j, 4, T[0], T[1], a[0], a[1]);
  const double th = T[i] / mp.mass[i];
  return s + 2.0 * zeta_exact(mp, i, T, a) * 15.0 * th * th * (1.0 + a[i]);
}

// Value and gradient at a = 0 of a low-degree polynomial in (a_0, a_1) by central differences.
struct Lin {
  double c, d0, d1;
  [[nodiscard]] double at(double a0, double a1) const { return c + d0 * a0 + d1 * a1; }
};
template <class F>
Lin linear_part(F f) {
  const double h = 1e-4;
  const double z[2] = {0.0, 0.0}, p0[2] = {h, 0.0}, m0[2] = {-h, 0.0}, p1[2] = {0.0, h}, m1[2] = {0.0, -h};
  return {f(z), (f(p0) - f(m0)) / (2.0 * h), (f(p1) - f(m1)) / (2.0 * h)};
}

MixtureParameters identical(double alpha, double delta, double chi = 1.0) {
  MixtureParameters mp = mixture_from_ratios(1.0, 1.0, delta, alpha);
  for (auto& row : mp.chi)
    for (double& c : row) c = chi;
  return mp;
}

}  // namespace

TEST(MixtureHcs, IdenticalSpeciesReduceToOneComponent) {
  for (double alpha : {0.0, 0.3, 0.5, 0.8, 0.95}) {
    for (double delta : {0.1, 1.0, 7.0}) {
      const MixtureParameters mp = identical(alpha, delta, 1.7);
      EXPECT_NEAR(temperature_ratio_maxwell(mp), 1.0, 1e-12) << alpha << " " << delta;
      const MixtureSonine s = mixture_first_sonine(mp);
      EXPECT_NEAR(s.gamma, 1.0, 1e-12) << alpha << " " << delta;
      EXPECT_NEAR(s.a2[0], hcs_a2(alpha), 1e-12) << alpha << " " << delta;
      EXPECT_NEAR(s.a2[1], hcs_a2(alpha), 1e-12) << alpha << " " << delta;
      // The partial cooling rate is the one-component rate with the first-Sonine factor 1 + 3 a2/16.
      const double n = mp.density[0] + mp.density[1];
      const double z = cooling_rate(alpha, n, 1.0, 1.0, 1.3, 1.7, 0.04);
      EXPECT_NEAR(partial_cooling_rate(mp, 0, 1.3, 1.3, 0.04, 0.04), z, 1e-13 * std::abs(z) + 1e-300);
      EXPECT_NEAR(partial_cooling_rate(mp, 1, 1.3, 1.3, 0.04, 0.04), z, 1e-13 * std::abs(z) + 1e-300);
    }
  }
}

TEST(MixtureHcs, ElasticLimitIsEquipartitionWithMaxwellians) {
  for (double mu : {1e-3, 0.1, 2.0, 10.0, 1e3}) {
    for (double omega : {0.5, 1.0, 3.0}) {
      for (double delta : {0.25, 1.0, 4.0}) {
        const MixtureParameters mp = mixture_from_ratios(mu, omega, delta, 1.0, 0.2);
        EXPECT_NEAR(temperature_ratio_maxwell(mp), 1.0, 1e-12);
        const MixtureSonine s = mixture_first_sonine(mp);
        EXPECT_NEAR(s.gamma, 1.0, 1e-12) << mu << " " << omega << " " << delta;
        EXPECT_NEAR(s.a2[0], 0.0, 1e-12);
        EXPECT_NEAR(s.a2[1], 0.0, 1e-12);
        // Maxwellians at a common temperature are collisional invariants for elastic spheres.
        for (int i = 0; i < 2; ++i)
          for (int j = 0; j < 2; ++j)
            for (int p : {2, 4}) EXPECT_NEAR(collisional_moment(mp, i, j, p, 0.7, 0.7, 0.0, 0.0), 0.0, 1e-14);
      }
    }
  }
}

TEST(MixtureHcs, MaxwellCoolingRateIsTheClosedForm) {
  // zeta_i = (8 sqrt(2 pi)/3) sum_j n_j sigma_ij^2 chi_ij m_ij (1 + alpha_ij) s_ij^3 / T_i
  //          [(T_i - T_j)/(M_ij s_ij^2) + mu_ji (1 - alpha_ij)/2]
  MixtureParameters mp = mixture_from_ratios(3.0, 0.6, 0.4, 0.7, 0.25);
  mp.alpha[0][0] = 0.5, mp.alpha[1][1] = 0.9, mp.alpha[0][1] = mp.alpha[1][0] = 0.65;
  const double T[2] = {2.3, 0.8};
  for (int i = 0; i < 2; ++i) {
    double z = 0.0;
    for (int j = 0; j < 2; ++j) {
      const double M = mp.mass[i] + mp.mass[j], mij = mp.mass[i] * mp.mass[j] / M, mu_ji = mp.mass[j] / M;
      const double s2 = T[i] / mp.mass[i] + T[j] / mp.mass[j], al = mp.alpha[i][j];
      const double sij = 0.5 * (mp.diameter[i] + mp.diameter[j]);
      z += 8.0 * std::sqrt(2.0 * pi) / 3.0 * mp.density[j] * sij * sij * mp.chi[i][j] * mij * (1.0 + al) *
           std::pow(s2, 1.5) / T[i] * ((T[i] - T[j]) / (M * s2) + mu_ji * (1.0 - al) / 2.0);
    }
    EXPECT_NEAR(partial_cooling_rate(mp, i, T[0], T[1], 0.0, 0.0), z, 1e-13 * std::abs(z));
  }
}

TEST(MixtureHcs, PartialCoolingRateIsFirstOrderPartOfCollisionalMoment) {
  // zeta_i from partial_cooling_rate = value + gradient at a2 = 0 of the exact (bilinear; a2_i^2 from the
  // like-species pair) rate -(m_i / (3 T_i)) sum_j M2_ij built from collisional_moment.
  MixtureParameters mp = mixture_from_ratios(0.3, 1.5, 2.0, 0.6, 0.1);
  const double T[2] = {0.4, 1.1};
  for (int i = 0; i < 2; ++i) {
    const Lin z = linear_part([&](const double* a) { return zeta_exact(mp, i, T, a); });
    for (const auto& a : {std::array<double, 2>{0.0, 0.0}, std::array<double, 2>{0.12, 0.0},
                          std::array<double, 2>{0.0, -0.2}, std::array<double, 2>{0.1, 0.3}}) {
      const double lin = z.at(a[0], a[1]);
      EXPECT_NEAR(partial_cooling_rate(mp, i, T[0], T[1], a[0], a[1]), lin, 1e-10 * std::abs(lin));
    }
  }
}

TEST(MixtureHcs, PairEnergyBalance) {
  // n_i m_i M2_ij + n_j m_j M2_ji = -(1 - alpha^2) m_ij n_i n_j sigma_ij^2 chi_ij int Theta (sig.g)^3 f_i f_j,
  // int Theta (sig.g)^3 f_i f_j / (n_i n_j) = 2 sqrt(2 pi) s^3 [2 + 3 (u^2 a_i + v^2 a_j)/4 + 9 u^2 v^2 a_i a_j/32]
  // (mixture_hcs.py, "Q"), exact in a_i, a_j.  Tests the consistency of the (1,0), (0,1), (1,1) coefficients.
  for (double al : {1.0, 0.7, 0.0}) {
    const MixtureParameters mp = mixture_from_ratios(4.0, 2.0, 0.5, al, 0.3);
    const double T[2] = {1.9, 0.6}, a[2] = {0.3, -0.25};
    const int i = 0, j = 1;
    const double lhs = mp.density[i] * mp.mass[i] * collisional_moment(mp, i, j, 2, T[0], T[1], a[0], a[1]) +
                       mp.density[j] * mp.mass[j] * collisional_moment(mp, j, i, 2, T[0], T[1], a[0], a[1]);
    const double thi = T[i] / mp.mass[i], thj = T[j] / mp.mass[j], s2 = thi + thj, u = thi / s2, v = thj / s2;
    const double q = 2.0 * std::sqrt(2.0 * pi) * std::pow(s2, 1.5) *
                     (2.0 + 0.75 * (u * u * a[i] + v * v * a[j]) + 9.0 / 32.0 * u * u * v * v * a[i] * a[j]);
    const double mij = mp.mass[i] * mp.mass[j] / (mp.mass[i] + mp.mass[j]);
    const double sij = 0.5 * (mp.diameter[i] + mp.diameter[j]);
    const double rhs = -(1.0 - al * al) * mij * mp.density[i] * mp.density[j] * sij * sij * mp.chi[i][j] * q;
    EXPECT_NEAR(lhs, rhs, 1e-13 * (std::abs(rhs) + std::abs(lhs) + 1.0)) << "alpha = " << al;
  }
}

TEST(MixtureHcs, MaxwellRootEqualisesCoolingRates) {
  for (double mu : {1e-3, 0.1, 0.5, 2.0, 10.0, 1e3}) {
    for (double delta : {0.25, 1.0, 4.0}) {
      for (double alpha : {0.0, 0.5, 0.9}) {
        const MixtureParameters mp = mixture_from_ratios(mu, 2.0, delta, alpha, 0.1);
        const double g = temperature_ratio_maxwell(mp);
        ASSERT_TRUE(std::isfinite(g) && g > 0.0);
        EXPECT_LT(zeta_gap(mp, g, 0.0, 0.0), 1e-12) << mu << " " << delta << " " << alpha;
      }
    }
  }
}

TEST(MixtureHcs, MaxwellRatioIsMassRatioForCompletelyInelasticEqualSpheres) {
  // alpha = 0, sigma_1 = sigma_2, n_1 = n_2: at T_1/m_1 = T_2/m_2 every pair has u = 1/2 and b = mu_ji, so
  // b (2u - b)/u = 2 mu_ij mu_ji for both species and zeta_1 = zeta_2 exactly: gamma = m_1/m_2.
  for (double mu : {1e-3, 0.2, 3.0, 1e3}) {
    EXPECT_NEAR(temperature_ratio_maxwell(mixture_from_ratios(mu, 1.0, 1.0, 0.0)), mu, 1e-12 * mu);
  }
}

TEST(MixtureHcs, SonineSolvesLinearisedMomentEquations) {
  // Rebuild the HCS equations from collisional_moment (exact, bilinear) and linearise numerically.
  for (const auto& r : {std::array<double, 5>{2.0, 1.0, 1.0, 0.5, 0.0}, std::array<double, 5>{10.0, 1.0, 2.0, 0.7, 0.0},
                        std::array<double, 5>{0.1, 1.0, 2.0, 0.6, 0.0}, std::array<double, 5>{2.0, 2.0, 0.5, 0.6, 0.4},
                        std::array<double, 5>{1e3, 1.0, 1.0, 0.0, 0.0}}) {
    const MixtureParameters mp = mixture_from_ratios(r[0], r[1], r[2], r[3], r[4]);
    const MixtureSonine s = mixture_first_sonine(mp);
    const double T[2] = {s.gamma, 1.0};
    for (int i = 0; i < 2; ++i) {
      const Lin e = linear_part([&](const double* a) { return e4_exact(mp, i, T, a); });
      // scale: the a-independent part of the like-species moment
      const double scale = std::abs(collisional_moment(mp, i, i, 4, T[0], T[1], 0.0, 0.0)) +
                           std::abs(collisional_moment(mp, i, 1 - i, 4, T[0], T[1], 0.0, 0.0));
      EXPECT_LT(std::abs(e.at(s.a2[0], s.a2[1])), 1e-7 * scale) << "mu = " << r[0] << ", species " << i;
    }
    const Lin z0 = linear_part([&](const double* a) { return zeta_exact(mp, 0, T, a); });
    const Lin z1 = linear_part([&](const double* a) { return zeta_exact(mp, 1, T, a); });
    const double za = z0.at(s.a2[0], s.a2[1]), zb = z1.at(s.a2[0], s.a2[1]);
    EXPECT_LT(std::abs(za - zb), 1e-7 * (std::abs(za) + std::abs(zb))) << "mu = " << r[0];
    EXPECT_LT(zeta_gap(mp, s.gamma, s.a2[0], s.a2[1]), 1e-12) << "mu = " << r[0];
  }
}

TEST(MixtureHcs, UniformChiScalingLeavesStateUnchanged) {
  const MixtureParameters base = mixture_from_ratios(4.0, 1.5, 0.5, 0.7);
  MixtureParameters scaled = base;
  for (auto& row : scaled.chi)
    for (double& c : row) c *= 2.7;
  EXPECT_NEAR(temperature_ratio_maxwell(scaled), temperature_ratio_maxwell(base), 1e-13);
  const MixtureSonine a = mixture_first_sonine(base), b = mixture_first_sonine(scaled);
  EXPECT_NEAR(a.gamma, b.gamma, 1e-13);
  EXPECT_NEAR(a.a2[0], b.a2[0], 1e-13);
  EXPECT_NEAR(a.a2[1], b.a2[1], 1e-13);
  // chi only multiplies the rates: zeta_i is linear in the chi_ij.
  for (int i = 0; i < 2; ++i) {
    const double z = partial_cooling_rate(base, i, 1.4, 0.9, 0.05, -0.02);
    EXPECT_NEAR(partial_cooling_rate(scaled, i, 1.4, 0.9, 0.05, -0.02), 2.7 * z, 1e-13 * std::abs(z));
  }
}

TEST(MixtureHcs, CarnahanStarlingChiLowersTheTemperatureRatio) {
  // 000 Fig. 5 (mu = omega = 2, delta = 1/2): gamma(alpha, phi)/gamma(alpha, 0) < 1, decreasing with phi, and
  // lower at alpha = 0.6 than at alpha = 0.8 (000 sec. 4). Values at phi = 0.5 from mixture_hcs.py.
  double prev[2] = {1.0, 1.0};
  const double g0[2] = {mixture_first_sonine(mixture_from_ratios(2.0, 2.0, 0.5, 0.6)).gamma,
                        mixture_first_sonine(mixture_from_ratios(2.0, 2.0, 0.5, 0.8)).gamma};
  for (double phi : {0.1, 0.2, 0.3, 0.4, 0.5}) {
    double ratio[2];
    for (int k = 0; k < 2; ++k) {
      ratio[k] = mixture_first_sonine(mixture_from_ratios(2.0, 2.0, 0.5, k == 0 ? 0.6 : 0.8, phi)).gamma / g0[k];
      EXPECT_LT(ratio[k], prev[k]) << "phi = " << phi;
      prev[k] = ratio[k];
    }
    EXPECT_LT(ratio[0], ratio[1]) << "phi = " << phi;
  }
  EXPECT_NEAR(prev[0], 0.89740, 5e-6);
  EXPECT_NEAR(prev[1], 0.94512, 5e-6);
}

TEST(MixtureHcs, SpeciesRelabellingSymmetry) {
  for (double alpha : {0.3, 0.8}) {
    const MixtureParameters a = mixture_from_ratios(5.0, 0.7, 3.0, alpha, 0.2);
    MixtureParameters b = a;
    for (int i = 0; i < 2; ++i) {
      b.mass[i] = a.mass[1 - i], b.diameter[i] = a.diameter[1 - i], b.density[i] = a.density[1 - i];
      for (int j = 0; j < 2; ++j) b.alpha[i][j] = a.alpha[1 - i][1 - j], b.chi[i][j] = a.chi[1 - i][1 - j];
    }
    EXPECT_NEAR(temperature_ratio_maxwell(a) * temperature_ratio_maxwell(b), 1.0, 1e-13);
    const MixtureSonine sa = mixture_first_sonine(a), sb = mixture_first_sonine(b);
    EXPECT_NEAR(sa.gamma * sb.gamma, 1.0, 1e-13);
    EXPECT_NEAR(sa.a2[0], sb.a2[1], 1e-13);
    EXPECT_NEAR(sa.a2[1], sb.a2[0], 1e-13);
  }
}

TEST(MixtureHcs, ExtremeMassRatiosStaySane) {
  // delta = omega = 1, mass ratios 1e-3 .. 1e3, alpha down to 0: finite, positive, a2 small and the Sonine
  // gamma within a few per cent of the Maxwellian one. (The linear Sonine theory does break down when the heavy
  // species is also very dilute, e.g. mu = 1e3, delta = 1e-3: see docs/methods/derivations/mixture-hcs.md.)
  for (double mu : {1e-3, 1e-2, 0.1, 10.0, 100.0, 1e3}) {
    for (double alpha : {0.0, 0.3, 0.6, 0.9}) {
      const MixtureParameters mp = mixture_from_ratios(mu, 1.0, 1.0, alpha);
      const double gm = temperature_ratio_maxwell(mp);
      const MixtureSonine s = mixture_first_sonine(mp);
      ASSERT_TRUE(std::isfinite(gm) && std::isfinite(s.gamma) && gm > 0.0 && s.gamma > 0.0);
      EXPECT_NEAR(s.gamma / gm, 1.0, 0.05) << mu << " " << alpha;
      EXPECT_LT(std::abs(s.a2[0]), 0.25) << mu << " " << alpha;
      EXPECT_LT(std::abs(s.a2[1]), 0.25) << mu << " " << alpha;
      EXPECT_LT(zeta_gap(mp, s.gamma, s.a2[0], s.a2[1]), 1e-12) << mu << " " << alpha;
    }
  }
}

namespace {

/// A line of mixture_hcs.py's "reference values": the mixture and its Maxwellian and first-Sonine state.
struct ReferenceState {
  double mu, omega, delta, alpha, gm, gs, a0, a1;
};

void expect_reference_states(std::initializer_list<ReferenceState> states, int dimension) {
  for (const ReferenceState& c : states) {
    MixtureParameters mp = mixture_from_ratios(c.mu, c.omega, c.delta, c.alpha);
    mp.dimension = dimension;
    EXPECT_NEAR(temperature_ratio_maxwell(mp), c.gm, 1e-12 * c.gm);
    const MixtureSonine s = mixture_first_sonine(mp);
    EXPECT_NEAR(s.gamma, c.gs, 1e-12 * c.gs);
    EXPECT_NEAR(s.a2[0], c.a0, 1e-12);
    EXPECT_NEAR(s.a2[1], c.a1, 1e-12);
  }
}

}  // namespace

TEST(MixtureHcs, ValuesFromExactDerivation) {
  // mixture_hcs.py "reference values" (independent Python implementation of the same closed forms).
  expect_reference_states(
      {{2, 1, 1, 0.5, 1.37042036301277, 1.36176350417998, 0.0713790013630778, 0.0355835809202199},
       {2, 1, 1, 0.8, 1.12566811848768, 1.12076338803179, -0.00554339143179936, -0.0153400740499466},
       {10, 1, 2, 0.5, 3.82639631508244, 3.80051147119688, 0.0545383083278067, 0.00901922556185767},
       {0.1, 1, 2, 0.7, 0.322432911895166, 0.323050042265275, 0.00853174268111041, 0.0328512124448888},
       {4, 1, 0.25, 0.6, 1.98780053596349, 1.9641354564311, 0.082611972775386, 0.0206348326256949},
       {1000, 1, 1, 0.0, 1000.0, 979.454395844151, 0.195999272095863, 0.116139984712178}},
      3);
}

TEST(MixtureHcs, CollisionalMomentsFromExactDerivation) {
  // Psi_p^ij of mixture_hcs.py evaluated in exact arithmetic (sympy, 17 digits) at m = {2, 1}, T = {1.3, 1},
  // alpha = 0.7, a2 = {0.3, -0.2}; unit n_j sigma_ij^2 chi_ij, so collisional_moment = Psi_p^ij. Covers every
  // coefficient including the bilinear a2_i a2_j ones.
  MixtureParameters mp = mixture_from_ratios(2.0, 1.0, 1.0, 0.7);
  struct Case {
    int i, j, p;
    double value;
  };
  for (const Case& c :
       {Case{0, 1, 2, -3.3207070476512073}, Case{0, 1, 4, -32.677633733523829}, Case{1, 0, 2, -0.50749244360178313},
        Case{1, 0, 4, 24.136563972276534}, Case{0, 0, 2, -2.0029355643294852}, Case{0, 0, 4, -22.383912975298738}}) {
    EXPECT_NEAR(collisional_moment(mp, c.i, c.j, c.p, 1.3, 1.0, 0.3, -0.2), c.value, 1e-13 * std::abs(c.value))
        << c.i << c.j << " p = " << c.p;
  }
}

TEST(MixtureHcs, DisksFromExactDerivation) {
  // `mixture_hcs.py --dimension 2` "reference values" and Psi_p^ij (unit n_j sigma_ij chi_ij); its moments agree
  // with the one-component ones of sonine_hcs.py --dimension 2 and, in --mc, with Monte Carlo on the circle
  // (docs/methods/derivations/mixture-hcs.md, "Disks").
  expect_reference_states(
      {{2, 1, 1, 0.5, 1.37042036301277, 1.36128966272593, 0.106917410401724, 0.0603818920589719},
       {2, 1, 1, 0.8, 1.12566811848768, 1.11830243835068, -0.0104226821409081, -0.0242357357340153},
       {10, 1, 2, 0.5, 3.82639631508244, 3.79735123081881, 0.0829930539866959, 0.0201745707170987},
       {0.1, 1, 2, 0.7, 0.322432911895166, 0.322909251347765, 0.0153824385941323, 0.0481380369078656},
       {4, 1, 0.25, 0.6, 1.98780053596349, 1.96165194985678, 0.115385846823711, 0.036085082917013},
       {1000, 1, 1, 0.0, 1000.0, 980.048252543065, 0.278227556848131, 0.19836878403519}},
      2);
  MixtureParameters mp = mixture_from_ratios(2.0, 1.0, 1.0, 0.7);
  mp.dimension = 2;
  struct Moment {
    int i, j, p;
    double value;
  };
  for (const Moment& c : {Moment{0, 1, 2, -1.6603535238256037}, Moment{0, 1, 4, -12.752398784764361},
                          Moment{1, 0, 2, -0.25374622180089157}, Moment{1, 0, 4, 9.9049141578685085},
                          Moment{0, 0, 2, -1.0014677821647426}, Moment{0, 0, 4, -8.3723242754177683}}) {
    EXPECT_NEAR(collisional_moment(mp, c.i, c.j, c.p, 1.3, 1.0, 0.3, -0.2), c.value, 1e-13 * std::abs(c.value))
        << c.i << c.j << " p = " << c.p;
  }
  // Identical disks: the one-component cooling state of disks (van Noije and Ernst, d = 2).
  for (const double alpha : {0.3, 0.6, 0.9}) {
    MixtureParameters same = mixture_from_ratios(1.0, 1.0, 0.5, alpha);
    same.dimension = 2;
    const MixtureSonine t = mixture_first_sonine(same);
    EXPECT_NEAR(t.gamma, 1.0, 1e-12);
    EXPECT_NEAR(t.a2[0], hcs_a2(alpha, 2), 1e-12);
    EXPECT_NEAR(t.a2[1], hcs_a2(alpha, 2), 1e-12);
  }
}

TEST(MixtureHcs, CollisionalMomentsAgreeWithMonteCarlo) {
  // Plain Monte Carlo of (1/n_i) int v^p J_ij in the original velocities (no pair decomposition): v1 ~
  // N(0, T_i/m_i), v2 ~ N(0, T_j/m_j), sig uniform on the sphere, weights [1 + a_i S2(x1)][1 + a_j S2(x2)].
  // Fixed seed; 2e6 samples; |z| < 4.
  struct Point {
    double mu, omega, delta, alpha, T1, T2, a1, a2;
    int i, j;
  };
  std::mt19937_64 rng(20240611);
  std::normal_distribution<double> N01;
  const auto S2 = [](double x) { return 0.5 * x * x - 2.5 * x + 15.0 / 8.0; };
  for (const Point& pt :
       {Point{2.0, 1.0, 1.0, 0.7, 1.3, 1.0, 0.3, -0.2, 0, 1}, Point{0.1, 2.0, 0.5, 0.5, 0.2, 1.0, -0.15, 0.25, 1, 0},
        Point{5.0, 0.5, 2.0, 0.0, 3.0, 0.4, 0.2, 0.2, 0, 0}}) {
    MixtureParameters mp = mixture_from_ratios(pt.mu, pt.omega, pt.delta, pt.alpha);
    mp.chi[pt.i][pt.j] = mp.chi[pt.j][pt.i] = 1.3;
    const double T[2] = {pt.T1, pt.T2}, a[2] = {pt.a1, pt.a2};
    const int i = pt.i, j = pt.j;
    const double thi = T[i] / mp.mass[i], thj = T[j] / mp.mass[j];
    const double b = mp.mass[j] / (mp.mass[i] + mp.mass[j]) * (1.0 + mp.alpha[i][j]);
    const double sij = 0.5 * (mp.diameter[i] + mp.diameter[j]);
    const double w = mp.density[j] * sij * sij * mp.chi[i][j];
    const int n = 2'000'000;
    double sum[2] = {0, 0}, sum2[2] = {0, 0};
    for (int k = 0; k < n; ++k) {
      double v1[3], v2[3], s[3], norm = 0.0;
      for (int c = 0; c < 3; ++c) {
        v1[c] = std::sqrt(thi) * N01(rng), v2[c] = std::sqrt(thj) * N01(rng), s[c] = N01(rng);
        norm += s[c] * s[c];
      }
      norm = std::sqrt(norm);
      double sg = 0.0, x1 = 0.0, x2 = 0.0;
      for (int c = 0; c < 3; ++c) {
        s[c] /= norm;
        sg += s[c] * (v1[c] - v2[c]);
        x1 += v1[c] * v1[c], x2 += v2[c] * v2[c];
      }
      double y1 = 0.0;
      for (int c = 0; c < 3; ++c) {
        const double vp = v1[c] - b * sg * s[c];
        y1 += vp * vp;
      }
      const double weight =
          sg > 0.0 ? 4.0 * pi * sg * (1.0 + a[i] * S2(x1 / (2.0 * thi))) * (1.0 + a[j] * S2(x2 / (2.0 * thj))) : 0.0;
      const double d2 = weight * (y1 - x1), d4 = weight * (y1 * y1 - x1 * x1);
      sum[0] += d2, sum2[0] += d2 * d2, sum[1] += d4, sum2[1] += d4 * d4;
    }
    for (int q = 0; q < 2; ++q) {
      const double mean = sum[q] / n, se = std::sqrt((sum2[q] / n - mean * mean) / n);
      const double exact = collisional_moment(mp, i, j, q == 0 ? 2 : 4, T[0], T[1], a[0], a[1]);
      EXPECT_LT(std::abs(w * mean - exact), 4.0 * w * se)
          << "p = " << (q == 0 ? 2 : 4) << ", i = " << i << ", j = " << j << ": exact " << exact << ", MC " << w * mean
          << " +- " << w * se;
    }
  }
}
