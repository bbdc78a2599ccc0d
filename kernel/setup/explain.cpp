#include "kernel/setup/explain.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <tuple>

#include "kernel/collide/pair_coefficients.hpp"
#include "kernel/core/species_store.hpp"
#include "kernel/schemes/replica_runner.hpp"
#include "kernel/setup/run_scene.hpp"
#include "kernel/theory/intruder.hpp"
#include "kernel/theory/scene_theory.hpp"
#include "kernel/theory/white_noise.hpp"

namespace granmc {

namespace {

template <class... Effects, class F>
void for_each_effect(const EffectList<Effects...>& list, F&& f) {
  std::apply([&](const auto&... effect) { (f(effect), ...); }, list.effects);
}

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

/// Whether every candidate collides (Maxwell's kernel, any dimension).
template <class Choice>
bool constant_rate(const Choice& kernel) {
  return std::visit([](const auto& k) { return std::decay_t<decltype(k)>::constant_rate; }, kernel);
}

/// The rate classes of drivers/explain_rates.toml: a replica of more than 100 MB of particles misses the caches
/// at every candidate; Maxwell's kernel collides at every candidate and keeps no majorant.
std::string event_rate_class(const EventPlan& plan, bool beyond_caches) {
  const std::string maxwell = constant_rate(plan.kernel) ? "maxwell_" : "";
  if (!beyond_caches) return "event." + maxwell + "in_cache";
  return "event." + maxwell +
         (std::holds_alternative<StoredAs<float>>(plan.storage) ? "beyond_caches_float" : "beyond_caches_double");
}
std::string weighted_rate_class(const WeightedPlan& plan) {
  return constant_rate(plan.kernel) ? "weighted.maxwell" : "weighted.rate_dependent";
}
std::string stepped_rate_class(bool beyond_caches) {
  return beyond_caches ? "stepped.beyond_caches" : "stepped.in_cache";
}
/// Weighted particles (schemes/swpm_scheme.hpp): velocity, update time, weight, weight class, place in the
/// class and the class's entry.
constexpr std::size_t weighted_bytes_per_particle = 3 * 8 + 8 + 8 + 4 + 4 + 4;

void explain_gas_memory(const Scene& scene, PlanExplanation& out) {
  out.bytes_per_particle = stored_bytes_per_particle(scene);
  out.particle_bytes = static_cast<std::uint64_t>(total_particles(scene)) * out.bytes_per_particle *
                       static_cast<std::uint64_t>(out.replicas_in_flight);
}

bool beyond_caches(const Scene& scene) {
  return static_cast<double>(total_particles(scene)) * static_cast<double>(stored_bytes_per_particle(scene)) > 100e6;
}

/// The gas of 001's kernel form (collide/rate_form_scattering.hpp).
std::string rate_form_kernel(const Scene& scene) {
  char kernel[128];
  const bool disks = scene.run.dimension == 2;
  std::snprintf(kernel, sizeof kernel, "one species%s, kernel rate |u|^lambda with lambda = %g, %s",
                disks ? " of disks" : "", scene.collision.lambda,
                disks && scene.collision.lambda == 1.0 ? "e by the hard-disk law" : "e uniform (001 eqs. 4, 8)");
  return kernel;
}

/// The time-step-free scheme (001 sec. 4): candidates at pi_hat = |S^(d-1)| / 2 rate (n - 1) U_max^lambda
/// (2 pi for spheres, pi for disks), U_max estimated as 2 x the expected largest speed at the larger of T(0)
/// and the steady temperature.
void explain(const EventPlan& plan, const Scene& scene, PlanExplanation& out) {
  const CollisionConfig& c = scene.collision;
  out.effects.push_back(rate_form_kernel(scene));
  if (plan.white_noise)
    out.effects.push_back("white noise by lazy Brownian updates at collision and sample times (001 eq. 23)");
  else
    out.absent.push_back("white noise");
  out.effects.push_back(constant_rate(plan.kernel) ? "every candidate collides (Maxwell kernel: no majorant)"
                                                   : "constant majorant U_max, raised at candidates, reset at samples");
  explain_gas_memory(scene, out);
  const double n = static_cast<double>(scene.species[0].particles);
  double temperature = scene.initial_temperature;
  if (plan.white_noise)
    temperature =
        std::max(temperature, theory::white_noise_steady_temperature(c.lambda, c.rate, c.restitution[0][0],
                                                                     scene.thermostat.beta, 0.0, scene.run.dimension));
  const double majorant = 2.0 * expected_max_speed(n) * std::sqrt(temperature);
  out.candidates = scene.run.replicas * scene.run.t_end * 0.5 * unit_sphere_area(scene.run.dimension) * c.rate *
                   (n - 1.0) * std::pow(majorant, c.lambda);
  out.candidates_upper_bound = false;
  out.rate_class = event_rate_class(plan, beyond_caches(scene));
}

/// Weighted particles: about M particles in each histogram shell (every shell once the tail has grown), at
/// most growth times that between controls; candidates at |S^(d-1)| rate U_max^lambda W_hat (n - 1) with
/// W_hat <= 2 (weights summing to 1) and U_max at most twice the histogram's radius.
void explain(const WeightedPlan& plan, const Scene& scene, PlanExplanation& out) {
  const CollisionConfig& c = scene.collision;
  const WeightsConfig& w = *scene.weights;
  char text[160];
  std::snprintf(text, sizeof text,
                "weighted particles (SWPM): about %d per histogram shell, weight transfer gamma = min(w_i, w_j), "
                "reduction of shells above %d",
                w.particles_per_shell, 2 * w.particles_per_shell);
  out.effects.push_back(text);
  out.effects.push_back(rate_form_kernel(scene));
  if (plan.white_noise)
    out.effects.push_back("white noise by lazy Brownian updates at candidate and control times (001 eq. 23)");
  else
    out.absent.push_back("white noise");
  const double n = w.growth * w.particles_per_shell * scene.histogram.shells;
  out.bytes_per_particle = weighted_bytes_per_particle;
  out.particle_bytes =
      static_cast<std::uint64_t>(n) * out.bytes_per_particle * static_cast<std::uint64_t>(out.replicas_in_flight);
  out.candidates = scene.run.replicas * scene.run.t_end * unit_sphere_area(scene.run.dimension) * c.rate * 2.0 * n *
                   std::pow(2.0 * scene.histogram.radius, c.lambda);
  out.candidates_upper_bound = true;
  out.rate_class = weighted_rate_class(plan);
}

/// The time-stepped scheme: candidates, summed over pairs, 1/2 N_i omega_max^(ij) int u dt, omega_max from the
/// expected largest initial speeds (stored units, unit temperature), int u dt from Haff's law when it
/// applies, else u(0) t_end (exact with the compensating thermostat, an upper bound for a cooling mixture).
void explain(const SteppedPlan& plan, const Scene& scene, PlanExplanation& out) {
  out.effects.push_back(scene.species.size() == 1
                            ? "one species"
                            : "two species: 4 ordered pairs, candidates interleaved within each step");
  std::visit([&](const auto& kernel) { out.effects.push_back(kernel.explanation); }, plan.kernel);
  if (scene.collision.packing_fraction > 0.0)
    out.effects.push_back("Enskog chi_ij (Carnahan-Starling), folded into the pair rates");
  const auto add = [&](const auto& effect) { out.effects.push_back(effect.explanation()); };
  bool sheared = false, shift = false, thermostat = false, relaxation = false;
  std::visit(
      [&](const auto& list) {
        for_each_effect(list, add);
        sheared = !list.empty;
        shift = list.template has<EnskogShearShift>;
      },
      plan.shear);
  if (sheared && !shift) out.effects.push_back("no shift of the contact velocity (Boltzmann limit, P^c = 0)");
  std::visit(
      [&](const auto& list) {
        for_each_effect(list, add);
        thermostat = !list.empty;
        relaxation = list.template has<BgkRelaxation>;
      },
      plan.thermostat);
  if (!thermostat) out.absent.push_back("thermostat");
  if (!sheared) out.absent.push_back("shear");
  if (!relaxation) out.absent.push_back("relaxation term");
  if (scene.collision.packing_fraction == 0.0) out.absent.push_back("Enskog chi");
  if (scene.run.dt_scaling == DtScaling::thermal)
    out.effects.push_back(scene.shear_rate != 0.0 ? "time step following the thermal speed, capped at run.dt"
                                                  : "time step following the thermal speed");
  explain_gas_memory(scene, out);

  double u_time = scene.run.t_end;  // int_0^t_end u(t)/u(0) dt
  out.candidates_upper_bound = scene.thermostat.kind != ThermostatKind::gaussian;
  if (const auto hcs = theory::cooling_state(scene, {})) {
    const double zeta0 = hcs->cooling_rate0;  // 0 for elastic particles, whose temperature stays at T(0)
    u_time = zeta0 > 0.0 ? 2.0 / zeta0 * std::log1p(0.5 * zeta0 * scene.run.t_end) : scene.run.t_end;
    out.candidates_upper_bound = false;
  }
  const double u0 = std::sqrt(scene.initial_temperature);
  // The majorant bounds the mean of omega_kl over sigma-hat, the kernel's mean angular weight times omega_kl's
  // bound (collide/collision_kernel.hpp), except with the Enskog shear shift (schemes/collision_stage.hpp,
  // majorant_bound).
  const double mean_form =
      shift ? 1.0 : std::visit([](const auto& k) { return k.mean_bound(1.0) / k.bound(1.0); }, plan.kernel);
  for (const PairCoefficients& p : pair_coefficients(scene)) {
    const SpeciesConfig& a = scene.species[p.i];
    const SpeciesConfig& b = scene.species[p.j];
    const double max_a = expected_max_speed(static_cast<double>(a.particles)) / std::sqrt(a.mass);
    const double max_b = expected_max_speed(static_cast<double>(b.particles)) / std::sqrt(b.mass);
    const double half_n = 0.5 * static_cast<double>(a.particles);
    out.candidates += std::visit(
        [&](const auto& kernel) {
          using K = std::decay_t<decltype(kernel)>;
          if constexpr (K::constant_rate)  // Maxwell: omega_max = prefactor, whatever T
            return half_n * p.rate_prefactor * scene.run.t_end;
          else if constexpr (std::is_same_v<K, VhsKernel<K::dimension>>)  // omega_max = prefactor U^lambda, T at T(0)
            return half_n * p.rate_prefactor * std::pow((max_a + max_b) * u0, kernel.lambda) * scene.run.t_end;
          else
            return half_n * p.rate_prefactor * (max_a + max_b) * u0 * u_time;
        },
        plan.kernel);
  }
  out.candidates *= mean_form * static_cast<double>(scene.run.replicas);
  out.rate_class = stepped_rate_class(beyond_caches(scene));
}

/// An intruder: one per replica; the work is its collision events, at the mean rate rho <|v1 - v|> with both
/// Maxwellian at T_B, rho sqrt(2 T_B (1 + 1/M) / pi), times the length for the needle (per unit length,
/// ignoring the rotation: an estimate).
void explain_intruder(const std::string& bath, const Scene& scene, PlanExplanation& out) {
  const IntruderConfig& in = *scene.intruder;
  out.gas = false;
  out.effects.push_back(bath);
  const double tb = theory::bath_temperature(in);
  out.events = scene.run.replicas * scene.run.t_end * in.bath_density * (in.dimension == 2 ? in.length : 1.0) *
               std::sqrt(2.0 * tb * (1.0 + 1.0 / in.mass) / std::numbers::pi);
}

void explain(const IntruderLinePlan& plan, const Scene& scene, PlanExplanation& out) {
  explain_intruder(std::visit([](const auto& bath) { return bath.explanation; }, plan.bath), scene, out);
  out.effects.push_back("colliding bath velocities sampled exactly (no window)");
}

void explain(const NeedlePlan& plan, const Scene& scene, PlanExplanation& out) {
  explain_intruder(std::visit([](const auto& bath) { return bath.explanation; }, plan.bath), scene, out);
  out.effects.push_back("colliding bath velocities sampled exactly (no window)");
  out.effects.push_back(
      "needle of length L: event times from the integrated flux by Newton with a bisection "
      "fallback (002 eqs. 27-28), impact point sampled exactly (002 eq. 29)");
}

void explain(const IntruderDsmcPlan& plan, const Scene& scene, PlanExplanation& out) {
  explain_intruder(std::visit([](const auto& bath) { return bath.explanation; }, plan.bath), scene, out);
  out.effects.push_back(
      "DSMC alternative (002 sec. 4): candidates at rho (|v1| + <|v|>) with the exact majorant "
      "|v1 - v| <= |v1| + |v|, bath velocities drawn from f");
}

std::string storage_note(const StorageChoice& storage) {
  return std::holds_alternative<StoredAs<float>>(storage) ? ", float storage (16 bytes per particle)" : "";
}

template <class... Effects>
void append_names(const EffectList<Effects...>&, std::string& name) {
  ((name += std::string(", ") + Effects::name), ...);
}

std::string name_of(const SteppedPlan& plan, const Scene& scene) {
  std::string name = "dsmc<" + std::visit([](const auto& k) { return std::string(k.name); }, plan.kernel);
  std::visit([&](const auto& list) { append_names(list, name); }, plan.shear);
  std::visit([&](const auto& list) { append_names(list, name); }, plan.thermostat);
  name += ">";
  if (scene.collision.packing_fraction > 0.0) name += ", Enskog chi in the pair rates";
  if (std::holds_alternative<RankWaveStage>(plan.backend)) name += ", rank-wave stage over MPI ranks";
  return name + storage_note(plan.storage);
}

std::string name_of(const EventPlan& plan, const Scene&) {
  return std::string("event<") + std::visit([](const auto& k) { return k.name; }, plan.kernel) +
         (plan.white_noise ? ", white-noise>" : ">") + storage_note(plan.storage);
}

std::string name_of(const WeightedPlan& plan, const Scene&) {
  return std::string("swpm<") + std::visit([](const auto& k) { return k.name; }, plan.kernel) +
         (plan.white_noise ? ", white-noise>" : ">");
}

std::string bath_name(const BathChoice& bath) {
  return std::visit([](const auto& b) { return std::string(b.name); }, bath);
}

std::string name_of(const IntruderLinePlan& plan, const Scene&) { return "gillespie-1d<" + bath_name(plan.bath) + ">"; }
std::string name_of(const NeedlePlan& plan, const Scene&) { return "gillespie-needle<" + bath_name(plan.bath) + ">"; }
std::string name_of(const IntruderDsmcPlan& plan, const Scene&) {
  return "dsmc-intruder-1d<" + bath_name(plan.bath) + ">";
}

}  // namespace

std::size_t stored_bytes_per_particle(const Scene& scene) noexcept {
  const bool spins = !scene.intruder && rough(scene.collision);  // rough particles (core/species_store.hpp)
  return scene.run.storage == Storage::single_precision ? FloatSpeciesStore::bytes_per_particle(spins)
                                                        : SpeciesStore::bytes_per_particle(spins);
}

std::string instantiation_name(const RunPlan& plan, const Scene& scene) {
  return std::visit([&](const auto& scheme) { return name_of(scheme, scene); }, plan.scheme);
}

PlanExplanation explain_plan(const RunPlan& plan, const Scene& scene, int threads, int threads_per_replica) {
  PlanExplanation out;
  out.instantiation = instantiation_name(plan, scene);
  // The run's own share (run_plan).
  const ThreadsInside inside = threads_inside(plan);
  RunOptions options;
  options.threads = threads;
  options.threads_per_replica = threads_per_replica;
  const ThreadShare share = share_threads(scene, options, inside);
  out.replicas_in_flight = share.concurrent;
  out.threads_per_replica = share.inside;
  out.threads_inside = inside.most > 1;
  out.least_particles_inside = inside.least_particles;
  std::visit([&](const auto& scheme) { explain(scheme, scene, out); }, plan.scheme);
  return out;
}

}  // namespace granmc
