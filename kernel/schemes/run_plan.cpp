#include "kernel/schemes/run_plan.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <cstdio>
#include <string>

#include "kernel/collide/pair_coefficients.hpp"
#include "kernel/core/species_store.hpp"
#include "kernel/schemes/dispatch.hpp"
#include "kernel/theory/intruder.hpp"
#include "kernel/theory/scene_theory.hpp"
#include "kernel/theory/white_noise.hpp"

namespace granmc {

namespace {

/// The speed x (in units of the one-component thermal width) that one of N Maxwellian particles exceeds
/// on average: P(|c| > x) = erfc(x / sqrt 2) + sqrt(2 / pi) x exp(-x^2 / 2) = 1 / N. Sets the initial majorant.
double expected_max_speed(double particles) {
  double lo = 0.0, hi = 40.0;
  for (int it = 0; it < 200; ++it) {
    const double x = 0.5 * (lo + hi);
    const double tail = std::erfc(x / std::sqrt(2.0)) + std::sqrt(2.0 / std::numbers::pi) * x * std::exp(-0.5 * x * x);
    (tail > 1.0 / particles ? lo : hi) = x;
  }
  return 0.5 * (lo + hi);
}

/// The time-step-free scheme (001 sec. 4): candidates at pi_hat = 2 pi rate (n - 1) U_max^lambda, U_max
/// estimated as 2 x the expected largest speed at the larger of T(0) and the steady temperature.
RunPlan plan_event(const Scene& scene, RunPlan plan) {
  const CollisionConfig& c = scene.collision;
  char kernel[96];
  std::snprintf(kernel, sizeof kernel, "one species, kernel rate |u|^lambda with lambda = %g, e uniform (001 eqs. 4, 8)",
                c.lambda);
  plan.effects.push_back(kernel);
  if (scene.thermostat.kind == ThermostatKind::white_noise)
    plan.effects.push_back("white noise by lazy Brownian updates at collision and sample times (001 eq. 23)");
  else
    plan.absent.push_back("white noise");
  plan.effects.push_back(c.lambda == 0.0 ? "every candidate collides (Maxwell kernel: no majorant)"
                                         : "constant majorant U_max, raised at candidates, reset at samples");
  const double n = static_cast<double>(scene.species[0].particles);
  plan.particle_bytes = static_cast<std::uint64_t>(n) * stored_bytes_per_particle(scene) * plan.replicas_in_flight;
  double temperature = scene.initial_temperature;
  if (scene.thermostat.kind == ThermostatKind::white_noise)
    temperature = std::max(temperature, theory::white_noise_steady_temperature(c.lambda, c.rate, c.restitution[0][0],
                                                                               scene.thermostat.beta, 0.0));
  const double majorant = 2.0 * expected_max_speed(n) * std::sqrt(temperature);
  plan.candidates = scene.run.replicas * scene.run.t_end * 2.0 * std::numbers::pi * c.rate * (n - 1.0) *
                    std::pow(majorant, c.lambda);
  plan.candidates_upper_bound = false;
  return plan;
}

}  // namespace

std::size_t stored_bytes_per_particle(const Scene& scene) noexcept {
  return scene.run.storage == Storage::single_precision ? FloatSpeciesStore::bytes_per_particle()
                                                        : SpeciesStore::bytes_per_particle();
}

RunPlan plan_run(const Scene& scene, int threads) {
  RunPlan plan;
  plan.instantiation = instantiation_name(scene);
  plan.replicas_in_flight = std::max(1, std::min(threads, scene.run.replicas));
  if (scene.intruder) {  // Gillespie: one intruder per replica; work = collision events
    const IntruderConfig& in = *scene.intruder;
    plan.effects.push_back(in.bath == BathKind::gaussian ? "Gaussian bath (002 eq. 18)" : "power-law bath (002 eq. 23)");
    plan.effects.push_back(scene.run.method == Method::dsmc
                               ? "DSMC alternative (002 sec. 4): candidates at rho (|v1| + <|v|>) with the exact "
                                 "majorant |v1 - v| <= |v1| + |v|, bath velocities drawn from f"
                               : "colliding bath velocities sampled exactly (no window)");
    if (in.dimension == 2)
      plan.effects.push_back("needle of length L: event times from the integrated flux by Newton with a bisection "
                             "fallback (002 eqs. 27-28), impact point sampled exactly (002 eq. 29)");
    // Mean collision rate rho <|v1 - v|> with both Maxwellian at T_B: rho sqrt(2 T_B (1 + 1/M) / pi), times
    // the length for the needle (per unit length, ignoring the rotation: an estimate).
    const double tb = theory::bath_temperature(in);
    plan.events = scene.run.replicas * scene.run.t_end * in.bath_density * (in.dimension == 2 ? in.length : 1.0) *
                  std::sqrt(2.0 * tb * (1.0 + 1.0 / in.mass) / std::numbers::pi);
    return plan;
  }
  if (scene.run.method == Method::event) return plan_event(scene, plan);
  plan.effects.push_back(scene.species.size() == 1
                             ? "one species"
                             : "two species: 4 ordered pairs, candidates interleaved within each step");
  if (scene.collision.packing_fraction > 0.0)
    plan.effects.push_back("Enskog chi_ij (Carnahan-Starling), folded into the pair rates");
  if (scene.thermostat.kind == ThermostatKind::gaussian)
    plan.effects.push_back(scene.thermostat.zeta_is_cooling_rate
                               ? "Gaussian thermostat compensating the cooling rate (O(1) per step)"
                               : "Gaussian thermostat, fixed zeta (O(1) per step)");
  if (scene.thermostat.kind == ThermostatKind::white_noise)
    plan.effects.push_back("white noise after each collision stage (splitting, O(N) per step)");
  if (scene.collision.kernel == CollisionKernel::maxwell)
    plan.effects.push_back("Maxwell pseudomolecules in the impact-direction form (16 pi rate (g.sigma)/|g|)");
  if (scene.shear_rate != 0.0) {
    plan.effects.push_back("uniform shear flow: inertial force V_x -= a V_y dt in free flight (O(N) per step), "
                           "pressure tensor P^k at each sample");
    plan.effects.push_back(has_enskog_shear_shift(scene)
                               ? "Enskog shear shift of the contact velocity, collisional transfer P^c tallied"
                               : "no shift of the contact velocity (Boltzmann limit, P^c = 0)");
  }
  if (scene.relaxation)
    plan.effects.push_back("BGK-like relaxation to the first-Sonine HCS f^(0) (003), O(replaced) per step");
  if (scene.run.dt_scaling == DtScaling::thermal)
    plan.effects.push_back(scene.shear_rate != 0.0 ? "time step following the thermal speed, capped at run.dt"
                                                   : "time step following the thermal speed");
  if (scene.thermostat.kind == ThermostatKind::none) plan.absent.push_back("thermostat");
  if (scene.shear_rate == 0.0) plan.absent.push_back("shear");
  if (!scene.relaxation) plan.absent.push_back("relaxation term");
  if (scene.collision.packing_fraction == 0.0) plan.absent.push_back("Enskog chi");

  std::uint64_t particles = 0;
  for (const SpeciesConfig& s : scene.species) particles += static_cast<std::uint64_t>(s.particles);
  plan.particle_bytes = particles * stored_bytes_per_particle(scene) * plan.replicas_in_flight;

  // Candidates: sum over pairs of 1/2 N_i omega_max^(ij) int u dt, omega_max from the expected largest
  // initial speeds (stored units, unit temperature), int u dt from Haff's law when it applies, else
  // u(0) t_end (exact with the compensating thermostat, an upper bound for a cooling mixture).
  double u_time = scene.run.t_end;  // int_0^t_end u(t)/u(0) dt
  plan.candidates_upper_bound = scene.thermostat.kind != ThermostatKind::gaussian;
  if (const auto hcs = theory::cooling_state(scene, {})) {
    u_time = 2.0 / hcs->cooling_rate0 * std::log1p(0.5 * hcs->cooling_rate0 * scene.run.t_end);
    plan.candidates_upper_bound = false;
  }
  const double u0 = std::sqrt(scene.initial_temperature);
  // The majorant bounds the mean of omega_kl over sigma-hat, a quarter of omega_kl's bound, except with the
  // Enskog shear shift (schemes/collision_stage.hpp, majorant_bound).
  const double mean_form = has_enskog_shear_shift(scene) ? 1.0 : 0.25;
  for (const PairCoefficients& p : pair_coefficients(scene)) {
    const SpeciesConfig& a = scene.species[p.i];
    const SpeciesConfig& b = scene.species[p.j];
    const double max_a = expected_max_speed(static_cast<double>(a.particles)) / std::sqrt(a.mass);
    const double max_b = expected_max_speed(static_cast<double>(b.particles)) / std::sqrt(b.mass);
    if (scene.collision.kernel == CollisionKernel::maxwell)  // omega_max = prefactor, whatever T
      plan.candidates += 0.5 * static_cast<double>(a.particles) * p.rate_prefactor * scene.run.t_end;
    else if (scene.collision.kernel == CollisionKernel::vhs)  // omega_max = prefactor U^lambda, T held at T(0)
      plan.candidates += 0.5 * static_cast<double>(a.particles) * p.rate_prefactor *
                         std::pow((max_a + max_b) * u0, scene.collision.lambda) * scene.run.t_end;
    else
      plan.candidates += 0.5 * static_cast<double>(a.particles) * p.rate_prefactor * (max_a + max_b) * u0 * u_time;
  }
  plan.candidates *= mean_form * static_cast<double>(scene.run.replicas);
  return plan;
}

}  // namespace granmc
