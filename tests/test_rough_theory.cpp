// The theory of rough hard spheres and disks (kernel/theory/rough.hpp) against its exact limits and the table of
// docs/methods/derivations/rough_hcs.py (which checks the rates against the collision rule by Monte Carlo).
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "kernel/theory/rough.hpp"

using namespace granmc::theory;

TEST(RoughTheory, SmoothParticlesCoolAsTheSmoothGasAndDoNotRotate) {
  for (int d : {3, 2}) {
    EXPECT_EQ(rough_hcs_theta(0.8, -1.0, 0.4, d), 0.0);
    EXPECT_DOUBLE_EQ(rough_cooling_rates(0.8, -1.0, 0.4, 1.0, d).translation, (1.0 - 0.64) / d);  // zeta / nu
    EXPECT_EQ(rough_cooling_rates(0.8, -1.0, 0.4, 1.0, d).rotation, 0.0);
  }
  EXPECT_EQ(rough_white_noise_theta(-1.0, 0.4), 0.0);
}

TEST(RoughTheory, PerfectlyRoughElasticParticlesConserveEnergyAndShareItEqually) {
  for (int d : {3, 2}) {
    const double rotations = d * (d - 1) / 2.0;
    for (double kappa : {0.1, 0.4, 2.0 / 3.0, 1.0}) {
      for (double theta : {0.2, 1.0, 3.0}) {  // (d/2) dT + (d_r/2) dT_r = 0 at every theta
        const RoughCoolingRates z = rough_cooling_rates(1.0, 1.0, kappa, theta, d);
        // to the rounding of terms of order 1 (a few 1e-16 each)
        EXPECT_NEAR(d * z.translation + rotations * theta * z.rotation, 0.0, 1e-14) << d << " " << kappa;
      }
      EXPECT_NEAR(rough_hcs_theta(1.0, 1.0, kappa, d), 1.0, 1e-12);  // equipartition
      EXPECT_NEAR(rough_white_noise_theta(1.0, kappa), 1.0, 1e-15);
    }
  }
}

TEST(RoughTheory, CoolingStateHasEqualRatesAndMatchesTheDerivationsTable) {
  // Rows of `docs/methods/derivations/rough_hcs.py` (d, alpha, beta, kappa, theta, zeta / nu).
  struct Row {
    int d;
    double alpha, beta, kappa, theta, zeta;
  };
  for (const Row& r :
       {Row{3, 0.9, -0.5, 0.4, 0.3426268733, 0.1459417198}, Row{3, 0.9, 0.5, 0.4, 0.8670773813, 0.1551072035},
        Row{3, 0.7, 0.0, 0.4, 1.2192059625, 0.2503261250}, Row{2, 0.9, 0.0, 0.5, 0.4695348380, 0.2078036201},
        Row{2, 0.7, 1.0, 0.5, 1.4898852557, 0.1461366098}, Row{2, 0.7, -0.5, 0.5, 4.3226763258, 0.2713517177}}) {
    const double theta = rough_hcs_theta(r.alpha, r.beta, r.kappa, r.d);
    const RoughCoolingRates z = rough_cooling_rates(r.alpha, r.beta, r.kappa, theta, r.d);
    EXPECT_NEAR(theta, r.theta, 1e-9) << r.d << " " << r.alpha << " " << r.beta;
    EXPECT_NEAR(z.translation, r.zeta, 1e-9);
    EXPECT_NEAR(z.rotation, z.translation, 1e-13);  // the cooling state: one rate
  }
  // White noise on translation: theta = b kappa / (kappa - b), b = (1 + beta) kappa / (2 (1 + kappa)).
  EXPECT_NEAR(rough_white_noise_theta(0.0, 0.4), 0.2222222222, 1e-10);
  EXPECT_NEAR(rough_white_noise_theta(0.5, 0.5), 0.5, 1e-15);
}

TEST(RoughTheory, SplitNoiseThetaHasItsLimitsAndTheMaxwellianTable) {
  // epsilon = 0: white noise on translation; epsilon = 1: on rotation only, zeta_tr = 0, which is linear in theta:
  // theta = kappa [(1 - alpha^2) + 2 (d - 1) b (1 - b)] / (2 (d - 1) b^2).
  for (int d : {3, 2}) {
    const double kappa = d == 3 ? 0.4 : 0.5, b = rough_tangential_factor(0.3, kappa), c = 2.0 * (d - 1);
    EXPECT_EQ(rough_split_noise_theta(0.8, 0.3, kappa, 0.0, d), rough_white_noise_theta(0.3, kappa));
    EXPECT_NEAR(rough_split_noise_theta(0.8, 0.3, kappa, 1.0, d),
                kappa * ((1.0 - 0.64) + c * b * (1.0 - b)) / (c * b * b), 1e-12);
  }
  // Disks, kappa = 1/2: the Maxwellian column beside the published DSMC of Megias and Santos (2022) in
  // docs/methods/validation.md (alpha, beta, epsilon, theta), computed independently from the balance of powers.
  struct Row {
    double alpha, beta, share, theta;
  };
  for (const Row& r : {Row{0.9, 0.0, 0.5, 1.0420}, Row{0.7, -0.7, 0.5, 3.2368}, Row{0.9, -0.7, 0.1, 0.2301},
                       Row{0.7, 0.0, 0.8, 3.6700}})
    EXPECT_NEAR(rough_split_noise_theta(r.alpha, r.beta, 0.5, r.share, 2), r.theta, 5e-5) << r.alpha << r.beta;
}

namespace {

/// Two species of rough particles: masses m, diameters sigma, densities n, one alpha for every pair.
RoughMixture rough_mixture(int d, const double (&m)[2], const double (&sigma)[2], const double (&n)[2], double alpha,
                           double beta, double kappa) {
  RoughMixture r;
  r.gas.dimension = d;
  r.beta = beta;
  r.kappa = kappa;
  for (int i = 0; i < 2; ++i) {
    r.gas.mass[i] = m[i];
    r.gas.diameter[i] = sigma[i];
    r.gas.density[i] = n[i];
    for (int j = 0; j < 2; ++j) r.gas.alpha[i][j] = alpha, r.gas.chi[i][j] = 1.0;
  }
  return r;
}

}  // namespace

TEST(RoughTheory, TwoSpeciesAlikeAreTheMonodisperseGas) {
  // Species that differ only in their label: the rates per particle, theta and the ratio 1 of the one-species gas,
  // for the cooling state and white noise (on translation, and split).
  for (int d : {3, 2}) {
    const double kappa = d == 3 ? 0.4 : 0.5;
    for (const double beta : {-0.5, 0.0, 0.7}) {
      const RoughMixture m = rough_mixture(d, {1.0, 1.0}, {1.0, 1.0}, {0.3, 0.7}, 0.8, beta, kappa);
      const RoughMixtureState hcs = rough_mixture_hcs(m);
      const double theta = rough_hcs_theta(0.8, beta, kappa, d);
      EXPECT_NEAR(hcs.temperature_ratio, 1.0, 1e-12);
      for (double x : hcs.theta) EXPECT_NEAR(x, theta, 1e-12 * theta) << d << " " << beta;
      // The rates at that state over nu = 4 sqrt(pi) n sigma^2 sqrt(T/m) (spheres), 2 sqrt(pi) n sigma sqrt(T/m):
      const RoughTemperatures rates = rough_mixture_collision_rates(m, {{1.0, 1.0}, {theta, theta}});
      const double nu = (d == 3 ? 4.0 : 2.0) * std::sqrt(std::numbers::pi);
      const RoughCoolingRates z = rough_cooling_rates(0.8, beta, kappa, theta, d);
      for (int i = 0; i < 2; ++i) {
        EXPECT_NEAR(-rates.translation[i] / nu, z.translation, 1e-14);
        EXPECT_NEAR(-rates.rotation[i] / (nu * theta), z.rotation, 1e-13);
      }
      for (const double share : {0.0, 0.5}) {
        const RoughMixtureState noise = rough_mixture_white_noise(m, share);
        const double expected = rough_split_noise_theta(0.8, beta, kappa, share, d);
        EXPECT_NEAR(noise.temperature_ratio, 1.0, 1e-12);
        for (double x : noise.theta) EXPECT_NEAR(x, expected, 1e-12 * expected) << d << " " << beta << " " << share;
      }
    }
  }
}

TEST(RoughTheory, MixturesHaveTheirLimits) {
  for (int d : {3, 2}) {
    const double kappa = d == 3 ? 0.4 : 0.5;
    // alpha = beta = 1: equipartition of all four temperatures, whatever masses and sizes.
    const RoughMixtureState elastic =
        rough_mixture_hcs(rough_mixture(d, {1.0, 4.0}, {1.0, 2.0}, {1.0, 0.2}, 1.0, 1.0, kappa));
    EXPECT_NEAR(elastic.temperature_ratio, 1.0, 1e-12);
    for (double x : elastic.theta) EXPECT_NEAR(x, 1.0, 1e-12);
    // beta = -1: smooth particles, the smooth mixture's ratio. The limit beta -> -1 is singular (theta grows as
    // 1 / b^2, so b^2 theta, the rotation's feedback on the translation, stays finite): no continuity is claimed.
    const RoughMixture unequal = rough_mixture(d, {1.0, 4.0}, {1.0, 2.0}, {1.0, 0.2}, 0.8, -1.0, kappa);
    EXPECT_EQ(rough_mixture_hcs(unequal).temperature_ratio, temperature_ratio_maxwell(unequal.gas));
    // A genuine mixture (alpha = 0.8): the four temperatures cool at one rate, also near the smooth limit, where
    // theta_2 reaches 10^5 (beta = -0.99).
    for (const double beta : {0.0, 0.9, -0.9, -0.99}) {
      RoughMixture rough = unequal;
      rough.beta = beta;
      const RoughMixtureState s = rough_mixture_hcs(rough);
      const RoughTemperatures t{{s.temperature_ratio, 1.0}, {s.temperature_ratio * s.theta[0], s.theta[1]}};
      const RoughTemperatures r = rough_mixture_collision_rates(rough, t);
      const double zeta = r.translation[1];  // T_2 = 1
      EXPECT_NEAR(r.translation[0] / t.translation[0], zeta, 1e-12 * std::fabs(zeta)) << beta;
      EXPECT_NEAR(r.rotation[0] / t.rotation[0], zeta, 1e-12 * std::fabs(zeta)) << beta;
      EXPECT_NEAR(r.rotation[1] / t.rotation[1], zeta, 1e-12 * std::fabs(zeta)) << beta;
    }
  }
}
