#include "kernel/theory/scene_theory.hpp"

#include <cmath>
#include <numbers>

#include "kernel/collide/enskog_chi.hpp"
#include "kernel/theory/sonine.hpp"
#include "kernel/theory/sonine_hcs.hpp"

namespace granmc::theory {

namespace {

/// A homogeneous DSMC scene of smooth hard spheres whose scaled state is the HCS one (no shear, no relaxation,
/// no white noise).
bool hcs_scaled_state(const Scene& scene) {
  return scene.run.method == Method::dsmc && scene.collision.kernel == CollisionKernel::hard_sphere &&
         !rough(scene.collision) && scene.thermostat.kind != ThermostatKind::white_noise && scene.shear_rate == 0.0 &&
         !scene.relaxation;
}

}  // namespace

std::optional<ScaledStatePrediction> scaled_state(const Scene& scene) {
  if (scene.species.size() != 1 || !hcs_scaled_state(scene)) return std::nullopt;
  const double alpha = scene.collision.restitution[0][0];
  const int d = scene.run.dimension;
  const SecondSonine second = hcs_second_sonine(alpha, d);
  return ScaledStatePrediction{hcs_a2(alpha, d), hcs_a2_model_error(alpha, d), second.a2, second.a3};
}

MixtureParameters mixture_parameters(const Scene& scene) {
  const bool disks = scene.run.dimension == 2;
  MixtureParameters mp{};
  mp.dimension = scene.run.dimension;
  const double n = total_density(scene);
  std::vector<double> x, sigma;
  for (const SpeciesConfig& s : scene.species) {
    x.push_back(s.density / n);
    sigma.push_back(s.diameter);
  }
  for (int i = 0; i < 2; ++i) {
    mp.mass[i] = scene.species[i].mass;
    mp.diameter[i] = scene.species[i].diameter;
    mp.density[i] = scene.species[i].density;
    for (int j = 0; j < 2; ++j) {
      mp.alpha[i][j] = scene.collision.restitution[i][j];
      const double phi = scene.collision.packing_fraction;
      mp.chi[i][j] = !(phi > 0.0) ? 1.0
                     : disks      ? enskog_chi_disks(phi, x, sigma, i, j)
                                  : enskog_chi(phi, x, sigma, i, j);
    }
  }
  return mp;
}

std::optional<MixturePrediction> mixture_state(const Scene& scene) {
  // The mixture theory (docs/methods/derivations/mixture-hcs.md) is that of spheres; for disks its Maxwellian balance.
  if (scene.species.size() != 2 || !hcs_scaled_state(scene)) return std::nullopt;
  const MixtureParameters mp = mixture_parameters(scene);
  MixturePrediction p;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) p.chi[i][j] = mp.chi[i][j];
  p.temperature_ratio_maxwell = temperature_ratio_maxwell(mp);
  p.first_sonine = mixture_first_sonine(mp);
  return p;
}

std::optional<CoolingStatePrediction> cooling_state(const Scene& scene, const std::vector<double>& times) {
  const std::optional<ScaledStatePrediction> scaled = scaled_state(scene);
  if (!scaled || scene.thermostat.kind != ThermostatKind::none) return std::nullopt;
  const SpeciesConfig& s = scene.species[0];
  const int d = scene.run.dimension;
  const double phi = scene.collision.packing_fraction;
  CoolingStatePrediction p;
  p.alpha = scene.collision.restitution[0][0];
  p.chi = phi > 0.0 ? (d == 2 ? enskog_chi_disks(phi) : enskog_chi(phi, {1.0}, {s.diameter}, 0, 0)) : 1.0;
  p.a2 = scaled->a2;
  p.a2_model_error = scaled->a2_model_error;
  p.a2_second_sonine = scaled->a2_second_sonine;
  p.a3_second_sonine = scaled->a3_second_sonine;
  const double t0 = scene.initial_temperature;
  p.cooling_rate0_maxwell = cooling_rate(p.alpha, s.density, s.diameter, s.mass, t0, p.chi, 0.0, d);
  p.cooling_rate0_first_sonine = cooling_rate(p.alpha, s.density, s.diameter, s.mass, t0, p.chi, p.a2, d);
  const double factor = hcs_cooling_rate_factor(p.a2_second_sonine, p.a3_second_sonine);
  p.cooling_rate0 = p.cooling_rate0_maxwell * factor;
  // The run starts Maxwellian (factor 1) and relaxes to the HCS factor within a few collisions; the
  // factor itself is uncertain by about (3/16) of the a2 model error.
  p.cooling_rate_model_error = std::fabs(factor - 1.0) + 3.0 / 16.0 * p.a2_model_error;
  p.collision_frequency0 = collision_frequency(s.density, s.diameter, s.mass, t0, p.chi, d);
  for (double t : times) p.temperature.push_back(haff_temperature(t, t0, p.cooling_rate0));
  return p;
}

}  // namespace granmc::theory
