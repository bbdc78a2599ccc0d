#include <array>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "kernel/collide/enskog_chi.hpp"
#include "kernel/theory/sonine.hpp"
#include "kernel/theory/steady_shear.hpp"
#include "kernel/theory/viscosity.hpp"

// First-Sonine Navier-Stokes shear viscosity (kernel/theory/viscosity.hpp, docs/methods/derivations/viscosity.md).
// The collision integrals behind the formulas are checked exactly, and by independent quadrature, in
// docs/methods/derivations/viscosity.py; here: limits, the papers' closed forms, and the papers' statements.

using namespace granmc::theory;

namespace {

constexpr ViscosityReference kCooling = ViscosityReference::cooling;
constexpr ViscosityReference kThermostat = ViscosityReference::gaussian_thermostat;

double chi_cs(double phi) { return (1.0 - 0.5 * phi) / std::pow(1.0 - phi, 3); }

// 003's c0(alpha), transcribed from the slide.
double c0_003(double alpha) {
  return 32.0 * (1.0 - alpha) * (1.0 - 2.0 * alpha * alpha) /
         (81.0 - 17.0 * alpha + 30.0 * alpha * alpha * (1.0 - alpha));
}

// 003's eta^k and eta, transcribed from the slide (the cooling-state coefficient).
double kinetic_003(double alpha, double phi, double chi) {
  return (1.0 - 0.4 * phi * chi * (1.0 + alpha) * (1.0 - 3.0 * alpha)) /
         (chi * (1.0 + alpha) * (16.0 * (13.0 - alpha) - 3.0 * (4.0 - 3.0 * alpha) * c0_003(alpha)) / 384.0);
}
double total_003(double alpha, double phi, double chi) {
  return kinetic_003(alpha, phi, chi) * (1.0 + 0.8 * phi * chi * (1.0 + alpha)) +
         384.0 / (25.0 * std::numbers::pi) * phi * phi * chi * (1.0 + alpha) * (1.0 - c0_003(alpha) / 32.0);
}

}  // namespace

TEST(ViscosityTheory, ElasticDiluteIsEta0) {
  for (ViscosityReference r : {kCooling, kThermostat}) {
    const ShearViscosity v = shear_viscosity(1.0, 0.0, 1.0, r);
    EXPECT_EQ(v.nu_eta, 1.0);
    EXPECT_EQ(v.zeta, 0.0);
    EXPECT_EQ(v.kinetic, 1.0);
    EXPECT_EQ(v.total, 1.0);
    EXPECT_EQ(shear_viscosity(1.0, 0.0, r).total, 1.0);
  }
}

TEST(ViscosityTheory, Eta0IsTheChapmanCowlingFirstApproximation) {
  // (5/16) sqrt(pi m T) / (pi sigma^2) for rigid spheres (Chapman & Cowling 1970, first approximation).
  for (double m : {0.5, 1.0, 3.0})
    for (double s : {0.7, 1.0, 2.0})
      for (double T : {0.1, 1.0, 4.0})
        EXPECT_NEAR(elastic_dilute_viscosity(m, s, T),
                    5.0 / 16.0 * std::sqrt(std::numbers::pi * m * T) / (std::numbers::pi * s * s), 1e-15);
}

TEST(ViscosityTheory, C0Of003IsTwiceTheVanNoijeErnstA2) {
  for (double alpha = 0.0; alpha <= 1.0 + 1e-12; alpha += 0.05) EXPECT_NEAR(c0_003(alpha), 2.0 * hcs_a2(alpha), 1e-15);
}

TEST(ViscosityTheory, CoolingReferenceIsTheFormulaOf003) {
  for (double alpha = 0.0; alpha <= 1.0 + 1e-12; alpha += 0.1)
    for (double phi : {0.0, 0.05, 0.1, 0.2, 0.3, 0.4, 0.5}) {
      const double chi = chi_cs(phi);
      const ShearViscosity v = shear_viscosity(alpha, phi, kCooling);
      EXPECT_NEAR(v.kinetic, kinetic_003(alpha, phi, chi), 1e-13 * std::abs(v.kinetic)) << alpha << " " << phi;
      EXPECT_NEAR(v.total, total_003(alpha, phi, chi), 1e-13 * v.total) << alpha << " " << phi;
    }
}

TEST(ViscosityTheory, CarnahanStarlingOverloadUsesEnskogChi) {
  for (double phi : {0.0, 0.1, 0.3, 0.5}) {
    EXPECT_NEAR(granmc::enskog_chi(phi, {1.0}, {1.0}, 0, 0), chi_cs(phi), 1e-14 * chi_cs(phi));
    for (ViscosityReference r : {kCooling, kThermostat})
      EXPECT_EQ(shear_viscosity(0.7, phi, r).total,
                shear_viscosity(0.7, phi, granmc::enskog_chi(phi, {1.0}, {1.0}, 0, 0), r).total);
  }
}

TEST(ViscosityTheory, DenominatorsAreNuEtaMinusZetaOverTwoOrZeta) {
  // nu_eta - zeta/2 is 003's (1/384) chi (1+alpha)[16(13 - alpha) - 3(4 - 3 alpha) c0]; nu_eta - zeta is
  // (1/384) chi (1+alpha)[64(2 + alpha) - (3/2)(13 - 11 alpha) c0] (viscosity.py, exact).
  for (double alpha = 0.0; alpha <= 1.0 + 1e-12; alpha += 0.05)
    for (double chi : {1.0, 1.7, 4.2}) {
      const double c0 = 2.0 * hcs_a2(alpha);
      const ShearViscosity v = shear_viscosity(alpha, 0.0, chi, kCooling);
      EXPECT_NEAR(v.nu_eta - 0.5 * v.zeta,
                  chi * (1.0 + alpha) * (16.0 * (13.0 - alpha) - 3.0 * (4.0 - 3.0 * alpha) * c0) / 384.0, 1e-14);
      EXPECT_NEAR(v.nu_eta - v.zeta,
                  chi * (1.0 + alpha) * (64.0 * (2.0 + alpha) - 1.5 * (13.0 - 11.0 * alpha) * c0) / 384.0, 1e-14);
      EXPECT_NEAR(1.0 / shear_viscosity(alpha, 0.0, chi, kThermostat).kinetic, v.nu_eta - v.zeta, 1e-14);
    }
}

TEST(ViscosityTheory, ReferencesCoincideWhenElastic) {
  for (double phi : {0.0, 0.1, 0.25, 0.4, 0.5}) {
    const ShearViscosity a = shear_viscosity(1.0, phi, kCooling), b = shear_viscosity(1.0, phi, kThermostat);
    EXPECT_EQ(a.kinetic, b.kinetic);
    EXPECT_EQ(a.total, b.total);
  }
}

TEST(ViscosityTheory, ElasticLimitIsEnskogTheory) {
  // Enskog's dense hard-sphere gas, first approximation (Chapman & Cowling 1970, ch. 16; 000 ref. [9]):
  //   eta / eta0 = (1/chi) [ (1 + (2/5) y)^2 + (48 / (25 pi)) y^2 ],   eta^k / eta0 = (1/chi)(1 + (2/5) y),
  // with y = b n chi = 4 phi chi (b = 2 pi sigma^3 / 3), for any chi(phi).
  for (double phi : {0.0, 0.01, 0.1, 0.2, 0.3, 0.4, 0.5})
    for (double chi : {1.0, 1.5, chi_cs(phi)}) {
      const double y = 4.0 * phi * chi;
      const ShearViscosity v = shear_viscosity(1.0, phi, chi, kCooling);
      EXPECT_NEAR(v.kinetic, (1.0 + 0.4 * y) / chi, 1e-14 * v.kinetic);
      EXPECT_NEAR(v.total, ((1.0 + 0.4 * y) * (1.0 + 0.4 * y) + 48.0 / (25.0 * std::numbers::pi) * y * y) / chi,
                  1e-14 * v.total);
    }
}

TEST(ViscosityTheory, Figure6HssAboveHcsBothRisingWithDissipation) {
  // 000 sec. 4 on Fig. 6: "In both cases the viscosity increases with the dissipation. However, ... the
  // influence of dissipation on the viscosity in the HCS case is smaller than in the HSS."
  double hcs_prev = 1.0, hss_prev = 1.0;
  for (double alpha = 0.95; alpha >= -1e-12; alpha -= 0.05) {
    const double hcs = shear_viscosity(alpha, 0.0, kCooling).total,
                 hss = shear_viscosity(alpha, 0.0, kThermostat).total;
    EXPECT_GT(hcs, hcs_prev) << alpha;
    EXPECT_GT(hss, hss_prev) << alpha;
    EXPECT_GT(hss, hcs) << alpha;
    hcs_prev = hcs;
    hss_prev = hss;
  }
}

TEST(ViscosityTheory, CrossoverNearPhiOneTenthAs003States) {
  // 003, results: eta(alpha, phi) > eta(1, phi) if phi <~ 0.1, eta(alpha, phi) < eta(1, phi) if phi >~ 0.1
  // (the crossover of the formula is 0.088 to 0.110 for alpha = 0.5 to 0.95).
  for (double alpha : {0.5, 0.6, 0.7, 0.8, 0.9, 0.95}) {
    EXPECT_GT(shear_viscosity(alpha, 0.05, kCooling).total, shear_viscosity(1.0, 0.05, kCooling).total) << alpha;
    EXPECT_LT(shear_viscosity(alpha, 0.15, kCooling).total, shear_viscosity(1.0, 0.15, kCooling).total) << alpha;
  }
}

TEST(ViscosityTheory, RegressionValuesFromExactArithmetic) {
  // viscosity.py closed forms in exact arithmetic (not literature values): at phi = 0 and alpha = 1/2,
  // eta/eta0 = 1952/1519 (cooling) and 1952/1211 (Gaussian thermostat).
  EXPECT_NEAR(shear_viscosity(0.5, 0.0, kCooling).total, 1952.0 / 1519.0, 1e-14);
  EXPECT_NEAR(shear_viscosity(0.5, 0.0, kThermostat).total, 1952.0 / 1211.0, 1e-14);
  EXPECT_NEAR(shear_viscosity(0.8, 0.0, kCooling).total, 1781000.0 / 1630623.0, 1e-14);
  EXPECT_NEAR(shear_viscosity(0.8, 0.0, kThermostat).total, 1781000.0 / 1497363.0, 1e-14);
  const ShearViscosity c = shear_viscosity(0.8, 0.2, kCooling), h = shear_viscosity(0.8, 0.2, kThermostat);
  EXPECT_NEAR(c.kinetic, 0.8415438216627087, 1e-14);
  EXPECT_NEAR(c.total, 1.886856219091119, 1e-14);
  EXPECT_NEAR(h.kinetic, 0.9164382391651932, 1e-14);
  EXPECT_NEAR(h.total, 1.999665935454236, 1e-14);
}

TEST(ViscosityTheory, ReducedViscosityOfFigures10To12) {
  EXPECT_NEAR(reduced_viscosity_one_species(1.0), 5.0 * std::sqrt(2.0) / 16.0, 1e-16);
  for (double m : {0.5, 2.0})
    for (double s : {1.0, 1.3})
      for (double T : {0.2, 3.0}) {
        const double eta = 1.37 * elastic_dilute_viscosity(m, s, T);
        EXPECT_NEAR(reduced_viscosity(eta, T, s, std::sqrt(2.0 * T / m)), reduced_viscosity_one_species(1.37), 1e-14);
        // 000 eq. (7) for identical species: v0 = sqrt(4 T / m).
        EXPECT_NEAR(mixture_thermal_speed(T, m, m), std::sqrt(4.0 * T / m), 1e-14 * std::sqrt(T / m));
      }
  EXPECT_NEAR(mixture_thermal_speed(1.0, 4.0, 1.0), std::sqrt(2.5), 1e-15);
}

// Steady uniform shear flow without a thermostat, Grad's solution (kernel/theory/steady_shear.hpp).

TEST(SteadyShearTheory, ElasticLimitIsEquilibrium) {
  for (int d : {3, 2}) {
    const SteadyShearFlow s = steady_shear_grad(1.0, d);
    EXPECT_EQ(s.shear_rate_nu0, 0.0);
    EXPECT_EQ(s.eta_over_eta0, 1.0);
    EXPECT_EQ(s.pressure_xx, 1.0);
    EXPECT_EQ(s.pressure_yy, 1.0);
  }
}

TEST(SteadyShearTheory, IsTheEndOfTheGradMomentEquations) {
  // The moment equations the closed form solves, integrated in time from equilibrium (RK4) at a fixed shear
  // rate a, in d = 3 and d = 2, with nu0 = n T / eta0 following T = tr P / d (n = sigma = m = 1;
  // eta0 = ((d + 2) / 8) Gamma(d / 2) pi^(-(d - 1) / 2) sqrt(T), theory/viscosity.hpp):
  //   dP_xx/dt = -2 a P_xy - nu0 [beta (P_xx - p) + zeta p],  dP_yy/dt = -nu0 [beta (P_yy - p) + zeta p],
  //   dP_xy/dt = -a P_yy - nu0 beta P_xy,  P_zz = P_yy (spheres),
  // beta = (3 / (4 d)) (1 - alpha + 2 d / 3)(1 + alpha), zeta = ((d + 2) / (4 d)) (1 - alpha^2).
  for (int d : {3, 2})
    for (double alpha : {0.5, 0.7, 0.9}) {
      const double beta = 3.0 / (4.0 * d) * (1.0 - alpha + 2.0 * d / 3.0) * (1.0 + alpha);
      const double zeta = (d + 2.0) / (4.0 * d) * (1.0 - alpha * alpha);
      const double nu0_root_t = 8.0 * std::pow(std::numbers::pi, 0.5 * (d - 1)) / ((d + 2.0) * std::tgamma(0.5 * d));
      const double a = 2.0;
      auto pressure = [&](const std::array<double, 3>& P) { return (P[0] + (d - 1.0) * P[1]) / d; };
      auto rate = [&](const std::array<double, 3>& P) {
        const double p = pressure(P), nu0 = nu0_root_t * std::sqrt(p);
        return std::array<double, 3>{-2.0 * a * P[2] - nu0 * (beta * (P[0] - p) + zeta * p),
                                     -nu0 * (beta * (P[1] - p) + zeta * p), -a * P[1] - nu0 * beta * P[2]};
      };
      std::array<double, 3> P{1.0, 1.0, 0.0};
      const double dt = 1e-3;
      for (int step = 0; step < 200000; ++step) {
        auto add = [&](const std::array<double, 3>& k, double f) {
          return std::array<double, 3>{P[0] + f * k[0], P[1] + f * k[1], P[2] + f * k[2]};
        };
        const auto k1 = rate(P), k2 = rate(add(k1, dt / 2)), k3 = rate(add(k2, dt / 2)), k4 = rate(add(k3, dt));
        for (int i = 0; i < 3; ++i) P[i] += dt / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
      }
      const double p = pressure(P), nu0 = nu0_root_t * std::sqrt(p);
      const SteadyShearFlow s = steady_shear_grad(alpha, d);
      EXPECT_NEAR(a / nu0, s.shear_rate_nu0, 1e-9) << d << " " << alpha;
      EXPECT_NEAR(P[0] / p, s.pressure_xx, 1e-9) << d << " " << alpha;
      EXPECT_NEAR(P[1] / p, s.pressure_yy, 1e-9) << d << " " << alpha;
      EXPECT_NEAR(P[2] / p, s.pressure_xy, 1e-9) << d << " " << alpha;
      EXPECT_NEAR(-P[2] / a * nu0 / p, s.eta_over_eta0, 1e-9) << d << " " << alpha;
      EXPECT_NEAR(p, steady_shear_temperature(s, a, 1.0, 1.0, 1.0), 1e-9) << d << " " << alpha;
      // granmc's a* and eta* (000's nu = sqrt(pi) n sigma^2 sqrt(2 T / m); disks (sqrt(pi) / 2) n sigma
      // sqrt(2 T / m), observe/pressure_tensor.hpp).
      const double nu = std::pow(std::numbers::pi, 0.5 * (d - 1)) / (2.0 * std::tgamma(0.5 * d)) * std::sqrt(2.0 * p);
      EXPECT_NEAR(a / nu, s.shear_rate_star, 1e-9) << d << " " << alpha;
      EXPECT_NEAR(-P[2] / a * nu / p, s.eta_star, 1e-9) << d << " " << alpha;
    }
}

TEST(ViscosityTheory, DisksHaveTheFirstSonineCoefficientsOfDimensionTwo) {
  // shear_viscosity in d = 2 against the d-general forms (theory/viscosity.hpp) written here with d explicit,
  // dilute and dense. The d-general dilute collision integrals are checked by Monte Carlo in
  // docs/methods/derivations/viscosity.md, "Disks".
  const double d = 2.0;
  for (double alpha : {0.3, 0.6, 0.9, 1.0})
    for (ViscosityReference r : {kCooling, kThermostat})
      for (double phi : {0.0, 0.2}) {
        const double chi = phi > 0.0 ? granmc::enskog_chi_disks(phi) : 1.0, c0 = 2.0 * hcs_a2(alpha, 2);
        const double nu_eta = 3.0 / (4.0 * d) * chi * (1.0 - alpha + 2.0 * d / 3.0) * (1.0 + alpha) * (1.0 - c0 / 64.0);
        const double zeta = (d + 2.0) / (4.0 * d) * chi * (1.0 - alpha * alpha) * (1.0 + 3.0 * c0 / 32.0);
        const double kinetic =
            (1.0 - std::pow(2.0, d - 2.0) / (d + 2.0) * phi * chi * (1.0 + alpha) * (1.0 - 3.0 * alpha)) /
            (nu_eta - (r == kCooling ? 0.5 : 1.0) * zeta);
        const double total = kinetic * (1.0 + std::pow(2.0, d - 1.0) / (d + 2.0) * phi * chi * (1.0 + alpha)) +
                             d / (d + 2.0) * std::pow(2.0, 2.0 * d + 1.0) / (std::numbers::pi * (d + 2.0)) * phi * phi *
                                 chi * (1.0 + alpha) * (1.0 - c0 / 32.0);
        const ShearViscosity v = shear_viscosity(alpha, phi, r, 2);
        EXPECT_NEAR(v.nu_eta, nu_eta, 1e-15) << alpha;
        EXPECT_NEAR(v.zeta, zeta, 1e-15) << alpha;
        EXPECT_NEAR(v.kinetic, kinetic, 1e-14) << alpha;
        EXPECT_NEAR(v.total, total, 1e-14) << alpha;
      }
  EXPECT_EQ(shear_viscosity(1.0, 0.0, kCooling, 2).total, 1.0);
  EXPECT_NEAR(reduced_viscosity_one_species(1.0, 2), std::sqrt(2.0) / 4.0, 1e-16);
  // Elastic disks: Gass's Enskog viscosity, eta / eta0 = 1/chi + 2 phi + (1 + 8/pi) phi^2 chi (J. Chem. Phys.
  // 54, 1898 (1971)).
  for (double phi : {0.1, 0.25, 0.4}) {
    const double chi = granmc::enskog_chi_disks(phi);
    EXPECT_NEAR(shear_viscosity(1.0, phi, kThermostat, 2).total,
                1.0 / chi + 2.0 * phi + (1.0 + 8.0 / std::numbers::pi) * phi * phi * chi, 1e-14)
        << phi;
  }
}
