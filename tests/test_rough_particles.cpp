// Rough particles in the time-stepped scheme (collide/rough_rule.hpp) against what is exact and what is
// published:
//  - perfectly rough elastic particles (alpha = beta = 1), one species or a mixture, conserve translational plus
//    rotational energy over a run, and the translational bookkeeping closes (energy_residual);
//  - the Gaussian thermostat holds T and gives the cooling state's theta, also in each of two species of the same
//    particles;
//  - rough hard disks (kappa = 1/2) under white noise on translation, and with half its power on the spins (the
//    splitting thermostat, effects/white_noise.hpp): theta = T_rot / T_tr against the DSMC of Megias and Santos,
//    Front. Phys. 10 (2022) 971671, data files `Steady states/theta_st_DSMC_{alpha}_{beta}.txt` of
//    github.com/amegiasf/MpembaSplitting, rows epsilon = 0 and 0.5. The splitting of the white
//    noise from the collisions makes theta move linearly with dt (docs/methods/validation/disks-and-rough.md, "Rough
//    particles"), so the comparison is at dt -> 0 by Richardson extrapolation, per replica, from runs at dt and dt / 2.
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "kernel/analysis/replica_statistics.hpp"
#include "kernel/observe/gas_series.hpp"
#include "kernel/setup/run_plan.hpp"
#include "kernel/setup/run_scene.hpp"
#include "tests/statistical_check.hpp"
#include "tests/test_scenes.hpp"

using namespace granmc;
using granmc::testing::scene_from_toml;
using granmc::testing::within_ci;

namespace {

/// The scene with its one species split into two of the same particles, each with half the particles and half
/// the density (and, if given, the second one's mass and diameter changed).
Scene split_into_two_species(Scene s, double mass = 1.0, double diameter = 1.0) {
  SpeciesConfig half = s.species[0];
  half.particles /= 2;
  half.density /= 2.0;
  s.species = {half, half};
  s.species[1].name = "second";
  s.species[1].mass = mass;
  s.species[1].diameter = diameter;
  return s;
}

/// `heated`: white noise (beta = 1) with a share `rotational_share` of its power on the spins, else no thermostat.
Scene rough_disks(double alpha, double beta, double dt, bool heated, int particles, int replicas, double t_end,
                  double rotational_share = 0.0) {
  constexpr std::string_view text = R"(
    [run]
    seed = 12
    replicas = ${replicas}
    t_end = ${t_end}
    dt = ${dt}
    samples = 80
    dimension = 2

    [[species]]
    name = "disks"
    particles = ${particles}

    [collision]
    restitution = ${alpha}
    tangential_restitution = ${beta}
  )";
  constexpr std::string_view white_noise = R"(
    [thermostat]
    kind = "white-noise"
    beta = 1.0
  )";
  const std::string thermostat =
      heated ? std::string(white_noise) + "rotational_share = " + std::to_string(rotational_share) + "\n" : "";
  return scene_from_toml(std::string(text) + thermostat, {{"replicas", replicas},
                                                          {"t_end", t_end},
                                                          {"dt", dt},
                                                          {"particles", particles},
                                                          {"alpha", alpha},
                                                          {"beta", beta}});
}

/// Per replica, the time average of T_rot / T of species i over the stationary samples.
std::vector<double> stationary_theta(const RunResult& r, std::size_t i = 0) {
  std::vector<double> theta;
  const std::size_t first = first_stationary_sample(r.times.size());
  for (const ReplicaSeries& s : r.replicas) {
    double sum = 0.0;
    for (std::size_t k = first; k < r.times.size(); ++k)
      sum += s.species[i].rotational_temperature[k] / s.species[i].temperature[k];
    theta.push_back(sum / static_cast<double>(r.times.size() - first));
  }
  return theta;
}

}  // namespace

TEST(RoughParticles, PerfectlyRoughElasticParticlesConserveTheirEnergy) {
  // No thermostat, alpha = beta = 1: sum_i N_i [(d/2) T_i + (d_r/2) T_rot,i] keeps its value at t = 0 to rounding
  // (the translational energy moves to rotation and back, and between the species); spheres and disks, one
  // species and a mixture of unequal masses and diameters.
  for (int d : {3, 2})
    for (const bool mixture : {false, true}) {
      Scene s = rough_disks(1.0, 1.0, 0.01, false, 2000, 2, 5.0);
      s.run.dimension = d;
      s.collision.reduced_inertia = d == 3 ? 0.4 : 0.5;
      if (mixture) s = split_into_two_species(s, 3.0, 1.4);
      const RunResult r = run_scene(s, {});
      const double d_r = d == 3 ? 3.0 : 1.0;
      SCOPED_TRACE("d = " + std::to_string(d) + (mixture ? ", mixture" : ""));
      for (const ReplicaSeries& rep : r.replicas) {
        ASSERT_GT(rep.collisions.back(), 10000.0);  // several collisions per particle
        const auto energy = [&](std::size_t k) {
          double e = 0.0;
          for (std::size_t i = 0; i < s.species.size(); ++i)
            e += static_cast<double>(s.species[i].particles) *
                 (d * rep.species[i].temperature[k] + d_r * rep.species[i].rotational_temperature[k]);
          return e;
        };
        for (std::size_t k = 1; k < r.times.size(); ++k)
          EXPECT_NEAR(energy(k) / energy(0), 1.0, 1e-12) << "t = " << r.times[k];
        EXPECT_LT(*rep.energy_residual, energy_balance_tolerance);
      }
    }
}

TEST(RoughParticles, ShearedRoughParticlesKeepMomentumAndTheirBookkeeping) {
  // A dilute uniform shear flow (Lagrangian frame, effects/lagrangian_shear.hpp) of rough spheres and disks:
  // momentum stays zero and the translational bookkeeping closes to rounding (the shear's heating, the
  // collisions' exact translational loss, the thermostat's work), with and without the Gaussian thermostat, for
  // perfectly rough elastic particles (alpha = beta = 1) and inelastic ones.
  for (int d : {3, 2})
    for (const bool thermostat : {false, true})
      for (const double restitution : {1.0, 0.8}) {
        Scene s = rough_disks(restitution, restitution == 1.0 ? 1.0 : 0.3, 0.01, false, 2000, 2, 4.0);
        s.run.dimension = d;
        s.collision.reduced_inertia = d == 3 ? 0.4 : 0.5;
        s.shear_rate = 0.5;
        if (thermostat) {
          s.thermostat.kind = ThermostatKind::gaussian;
          s.thermostat.zeta_is_cooling_rate = true;
        }
        SCOPED_TRACE("d = " + std::to_string(d) + (thermostat ? ", Gaussian thermostat" : "") +
                     ", alpha = " + std::to_string(restitution));
        const RunResult r = run_scene(s, {});
        for (const ReplicaSeries& rep : r.replicas) {
          ASSERT_GT(rep.collisions.back(), 4000.0);
          for (double p : rep.momentum_relative) EXPECT_LT(p, 1e-13);
          EXPECT_LT(*rep.energy_residual, energy_balance_tolerance);
        }
      }
  // The dense gas's Enskog shift would also move the tangential contact velocity: refused, naming the key.
  Scene dense = rough_disks(0.8, 0.3, 0.01, false, 2000, 2, 4.0);
  dense.shear_rate = 0.5;
  dense.collision.packing_fraction = 0.1;
  dense.species[0].density = 4.0 * 0.1 / std::numbers::pi;
  EXPECT_NE(plan_refusal(dense).find("packing_fraction"), std::string::npos) << plan_refusal(dense);
}

TEST(RoughParticles, GaussianThermostatHoldsTheCoolingStatesTheta) {
  // The Gaussian thermostat scales velocities and spins alike (the velocity scale), so its steady state is the
  // cooling state in scaled variables: the same theta = T_rot / T. Rough disks, alpha = 0.9, beta = 0; with zeta =
  // "cooling-rate" T stays at its value at t = 0 to rounding. theta of the two runs over their last halves; the
  // cooling run is four times longer, as its collisions slow down with T (about 16 per particle by t = 64, where
  // its theta has settled; the heated run's settles within t = 6).
  const Scene cooling = rough_disks(0.9, 0.0, 0.01, false, 10000, 16, 64.0);
  Scene heated = rough_disks(0.9, 0.0, 0.01, false, 10000, 16, 16.0);
  heated.thermostat.kind = ThermostatKind::gaussian;
  heated.thermostat.zeta_is_cooling_rate = true;
  const RunResult a = run_scene(cooling, {}), b = run_scene(heated, {});
  for (const ReplicaSeries& rep : b.replicas)
    for (double t : rep.species[0].temperature) EXPECT_NEAR(t, rep.species[0].temperature.front(), 1e-12);
  EXPECT_LT(a.replicas[0].species[0].temperature.back(), 0.01);  // the cooling run did cool
  const MeanCI theta_cooling = replica_mean(stationary_theta(a)), theta_heated = replica_mean(stationary_theta(b));
  std::printf("theta: cooling %.5f +- %.5f, Gaussian thermostat %.5f +- %.5f\n", theta_cooling.mean, theta_cooling.ci,
              theta_heated.mean, theta_heated.ci);
  const MeanCI difference{theta_heated.mean - theta_cooling.mean, std::hypot(theta_heated.ci, theta_cooling.ci)};
  // Bound: the CI of the difference measured today, 0.0062, times 1.5.
  EXPECT_TRUE(within_ci("theta, Gaussian thermostat minus cooling", difference, 0.0, 0.0093));
}

TEST(RoughParticles, TwoSpeciesOfTheSameParticlesAreTheMonodisperseGas) {
  // The species label does not change the physics: rough disks (alpha = 0.9, beta = 0) split into two species of
  // the same particles hold, under the Gaussian thermostat, the theta of the one-species gas, in each species.
  // It checks the mixture's pair selection with spins (the four ordered pairs, their rates and coefficients).
  Scene one = rough_disks(0.9, 0.0, 0.01, false, 10000, 16, 16.0);
  one.thermostat.kind = ThermostatKind::gaussian;
  one.thermostat.zeta_is_cooling_rate = true;
  const RunResult a = run_scene(one, {}), b = run_scene(split_into_two_species(one), {});
  const MeanCI theta = replica_mean(stationary_theta(a));
  for (std::size_t i = 0; i < 2; ++i) {
    const MeanCI theta_i = replica_mean(stationary_theta(b, i));
    std::printf("theta: one species %.5f +- %.5f, species %zu of two %.5f +- %.5f\n", theta.mean, theta.ci, i,
                theta_i.mean, theta_i.ci);
    const MeanCI difference{theta_i.mean - theta.mean, std::hypot(theta_i.ci, theta.ci)};
    // Bound: the CIs of the difference measured today, 0.0048 and 0.0047, times 1.5.
    EXPECT_TRUE(within_ci("theta, species i of two minus one species", difference, 0.0, 0.0072));
  }
}

namespace {

/// theta at dt -> 0 (2 theta(dt/2) - theta(dt) per replica) of white-noise-driven rough disks against the
/// published value and its error (one standard error, taken lambda_p times as the reference's own interval).
void expect_published_theta(double alpha, double beta, double published, double published_error, double ci_bound,
                            double rotational_share = 0.0) {
  const double dt = 0.005;
  const RunResult coarse = run_scene(rough_disks(alpha, beta, dt, true, 10000, 16, 16.0, rotational_share), {});
  const RunResult fine = run_scene(rough_disks(alpha, beta, dt / 2.0, true, 10000, 16, 16.0, rotational_share), {});
  const std::vector<double> at_dt = stationary_theta(coarse), at_half = stationary_theta(fine);
  std::vector<double> extrapolated;
  for (std::size_t r = 0; r < at_dt.size(); ++r) extrapolated.push_back(2.0 * at_half[r] - at_dt[r]);
  const MeanCI theta = replica_mean(extrapolated);
  std::printf(
      "alpha = %g, beta = %g, epsilon = %g: theta(dt) = %.5f, theta(dt/2) = %.5f, theta(0) = %.5f +- %.5f; published "
      "%.5f\n",
      alpha, beta, rotational_share, replica_mean(at_dt).mean, replica_mean(at_half).mean, theta.mean, theta.ci,
      published);
  EXPECT_TRUE(within_ci("theta", theta, published, ci_bound, confidence_lambda_p * published_error));
}

}  // namespace

// Bounds: the CIs measured today (0.00218 and 0.00056) times 1.5.
TEST(RoughParticles, WhiteNoiseThetaOfRoughDisksIsThePublishedOne) {
  expect_published_theta(0.7, 0.0, 0.2441882371, 4.743e-05, 0.0033);
}

TEST(RoughParticles, WhiteNoiseThetaOfNearlySmoothDisksIsThePublishedOne) {
  expect_published_theta(0.9, -0.7, 0.0543255042, 3.320e-05, 0.00084);
}

// Half of the power on the spins (the splitting thermostat), the same files' row epsilon = 0.5. Bounds: the CIs
// measured today (0.0170 and 0.0214) times 1.5.
TEST(RoughParticles, SplitNoiseThetaOfRoughDisksIsThePublishedOne) {
  expect_published_theta(0.7, 0.0, 1.593904337, 4.372e-04, 0.0255, 0.5);
}

TEST(RoughParticles, SplitNoiseThetaOfNearlySmoothDisksIsThePublishedOne) {
  expect_published_theta(0.9, -0.7, 1.543915877, 1.265e-03, 0.032, 0.5);
}
