#include "kernel/setup/run_plan.hpp"

#include <vector>

#include "kernel/core/philox_stream.hpp"
#include "kernel/theory/sonine.hpp"

namespace granmc {

namespace {

// What granmc runs, for the refusal message. Every scene outside it is refused at start-up. One or two
// species and the Enskog chi need no plan of their own: both only change the pair constants.
constexpr const char* supported_list =
    "supported: method = \"dsmc\" with kernel = \"hard-sphere\", one or two species, any packing_fraction in "
    "[0, 1) (Enskog chi), or kernel = \"maxwell\" or \"vhs\" with collision.rate > 0 and one species; thermostat "
    "kind = \"none\", \"gaussian\" (a fixed zeta or \"cooling-rate\") or \"white-noise\"; a [shear] rate with "
    "hard spheres or disks and thermostat \"none\" or \"gaussian\" (Boltzmann, or Enskog with the shifted contact "
    "velocity when packing_fraction > 0); the [relaxation] term of 003 for one species of hard spheres or disks with "
    "the Gaussian thermostat compensating the cooling rate; method = \"event\" with one species, collision.rate > "
    "0 (the form of 001) and mass 1, kernel \"maxwell\", \"vhs\" or \"hard-sphere\", thermostat \"none\" or "
    "\"white-noise\", packing_fraction = 0, no shear or relaxation; method = \"gillespie\" with an [intruder] of "
    "dimension 1 or 2 (the needle) in a \"gaussian\" or \"power-law\" bath; "
    "method = \"dsmc\" with an [intruder] of dimension 1 (002 sec. 4); run.storage \"double\" or \"float\" for "
    "every gas scene; disks (run.dimension = 2) as spheres (with a packing_fraction: "
    "Henderson's chi, Jenkins and Mancini's chi_ij); rough spheres or "
    "disks (collision.tangential_restitution > "
    "-1) with method = \"dsmc\", one or two species, "
    "thermostat \"none\", \"gaussian\" (scaling velocities and spins alike) or \"white-noise\" (on translation, or "
    "a share on the spins), a dilute [shear] rate (no packing_fraction)";

[[noreturn]] void refuse(const std::string& what) {
  throw PlanRefusal("this version of granmc cannot run " + what + " yet; " + supported_list);
}

[[noreturn]] void refuse_spread(const std::string& what) {
  throw PlanRefusal("one system over several ranks (--spread particles) is not implemented for " + what +
                    "; it runs method \"dsmc\" with one species, any kernel and packing_fraction, any thermostat, "
                    "double storage (docs/user-guide/parallel-runs.md)");
}

StorageChoice storage_choice(const Scene& scene) {
  if (scene.run.storage == Storage::single_precision) return StoredAs<float>{};
  return StoredAs<double>{};
}

BathChoice bath_choice(const IntruderConfig& in) {
  if (in.bath == BathKind::power_law) return PowerLawBath{in.bath_a, in.bath_density};
  return GaussianBath{in.bath_a, in.bath_density};
}

SchemeChoice intruder_plan(const Scene& scene) {
  const IntruderConfig& in = *scene.intruder;
  if (scene.run.storage != Storage::double_precision)
    refuse("run.storage = \"float\" for an intruder scene (it stores no gas)");
  if (scene.run.method == Method::gillespie) {
    if (in.dimension == 1) return IntruderLinePlan{bath_choice(in)};
    return NeedlePlan{bath_choice(in)};
  }
  if (scene.run.method == Method::event) refuse("the event scheme with an [intruder]");
  if (in.dimension != 1) refuse("the DSMC alternative for the 2D needle");
  if (!(scene.run.t_end / scene.run.dt < static_cast<double>(RandomStream::counter_limit)))
    refuse("an intruder DSMC run with more than 2^48 time steps (raise run.dt)");
  return IntruderDsmcPlan{bath_choice(in)};
}

/// The event scheme's kernel in d dimensions: it follows lambda (the scene file fixes it for "maxwell" and
/// "hard-sphere").
template <int d, class Choice>
Choice kernel_of_lambda(const CollisionConfig& c) {
  if (c.lambda == 0.0) return MaxwellKernel<d>{};
  if (c.lambda == 1.0) return HardCore<d>{};
  return VhsKernel<d>{c.lambda};
}

EventPlan event_plan(const Scene& scene) {
  const CollisionConfig& c = scene.collision;
  if (scene.species.size() != 1) refuse("the event scheme with other than one [[species]]");
  if (scene.species[0].mass != 1.0) refuse("the event scheme with a species mass other than 1 (001 has unit mass)");
  if (!(c.rate > 0.0)) refuse("the event scheme with collision.rate = 0 (the 000 hard-sphere form)");
  if (scene.thermostat.kind == ThermostatKind::gaussian) refuse("the event scheme with the Gaussian thermostat");
  if (c.packing_fraction > 0.0) refuse("the event scheme with a packing_fraction (Enskog)");
  if (scene.shear_rate != 0.0) refuse("the event scheme with a [shear] rate");
  if (scene.relaxation) refuse("the event scheme with the [relaxation] term");
  const EventKernelChoice kernel =
      scene.run.dimension == 2 ? kernel_of_lambda<2, EventKernelChoice>(c) : kernel_of_lambda<3, EventKernelChoice>(c);
  return {kernel, storage_choice(scene), scene.thermostat.kind == ThermostatKind::white_noise};
}

KernelChoice stepped_kernel(const Scene& scene) {
  switch (scene.collision.kernel) {
    case CollisionKernel::maxwell:
      return scene.run.dimension == 2 ? KernelChoice{MaxwellDisks{}} : KernelChoice{MaxwellPseudomolecules{}};
    case CollisionKernel::vhs:
      return scene.run.dimension == 2 ? KernelChoice{VariableHardDisks{scene.collision.lambda}}
                                      : KernelChoice{VariableHardSpheres{scene.collision.lambda}};
    case CollisionKernel::hard_sphere:
      break;
  }
  const bool spins = rough(scene.collision);  // collide/rough_rule.hpp
  if (scene.run.dimension == 2) return spins ? KernelChoice{RoughHardDisk{}} : KernelChoice{HardDisk{}};
  return spins ? KernelChoice{RoughHardSphere{}} : KernelChoice{HardSphere{}};
}

ShearChoice shear_effects(const Scene& scene) {
  if (scene.shear_rate == 0.0) return EffectList<>{};
  const LagrangianShear shear{scene.shear_rate, species_masses(scene)};
  // The Enskog shift of the contact velocity only in the dense gas (collide/enskog_shear_shift.hpp).
  if (scene.collision.packing_fraction > 0.0)
    return EffectList<LagrangianShear, EnskogShearShift>{{shear, EnskogShearShift{scene.shear_rate}}};
  return EffectList<LagrangianShear>{{shear}};
}

ThermostatChoice thermostat_effects(const Scene& scene) {
  const ThermostatConfig& th = scene.thermostat;
  switch (th.kind) {
    case ThermostatKind::gaussian: {
      const GaussianThermostat thermostat{th.zeta_is_cooling_rate, th.zeta};
      if (!scene.relaxation) return EffectList<GaussianThermostat>{{thermostat}};
      // 003: the thermostat, then the relaxation term to f^(0) with the first-Sonine a2 unless the scene sets it.
      const int d = scene.run.dimension;
      const double a2 = scene.relaxation_a2.value_or(theory::hcs_a2(scene.collision.restitution[0][0], d));
      return EffectList<GaussianThermostat, BgkRelaxation>{
          {thermostat, BgkRelaxation{SonineMaxwellian(a2, d), scene.species[0].mass, d}}};
    }
    case ThermostatKind::white_noise:
      return EffectList<WhiteNoise>{{WhiteNoise{th.beta, species_masses(scene), scene.run.dimension,
                                                th.rotational_share, scene.collision.reduced_inertia}}};
    case ThermostatKind::none:
      break;
  }
  return EffectList<>{};
}

SteppedPlan stepped_plan(const Scene& scene, Spread spread) {
  if (scene.collision.kernel != CollisionKernel::hard_sphere && !(scene.collision.rate > 0.0))
    refuse("method = \"dsmc\" with kernel = \"maxwell\" or \"vhs\" and collision.rate = 0 (set the rate of 001)");
  if (scene.species.empty() || scene.species.size() > 2) refuse("a scene without one or two [[species]]");
  if (scene.relaxation && (scene.species.size() != 1 || !scene.thermostat.zeta_is_cooling_rate))
    refuse(relaxation_refusal);
  SteppedPlan plan{stepped_kernel(scene), shear_effects(scene), thermostat_effects(scene), storage_choice(scene),
                   BatchedStage{}};
  std::visit(
      [](const auto& kernel, const auto& shear, const auto& thermostat) {
        using K = std::decay_t<decltype(kernel)>;
        using S = std::decay_t<decltype(shear)>;
        using T = std::decay_t<decltype(thermostat)>;
        if constexpr (stepped_refusal<K, S, T>() != nullptr) refuse(stepped_refusal<K, S, T>());
      },
      plan.kernel, plan.shear, plan.thermostat);
  if (spread == Spread::particles) {
    if (scene.species.size() != 1) refuse_spread("two species");
    plan.backend = RankWaveStage{};
    std::visit(
        [](const auto& kernel, const auto& shear, const auto& thermostat, const auto& storage) {
          using K = std::decay_t<decltype(kernel)>;
          using S = std::decay_t<decltype(shear)>;
          using T = std::decay_t<decltype(thermostat)>;
          using R = std::decay_t<decltype(storage)>;
          if constexpr (spread_refusal<K, S, T, R, RankWaveStage>() != nullptr)
            refuse_spread(spread_refusal<K, S, T, R, RankWaveStage>());
        },
        plan.kernel, plan.shear, plan.thermostat, plan.storage);
  }
  return plan;
}

}  // namespace

RunPlan make_plan(const Scene& scene, Spread spread) {
  if (!scene.intruder && rough(scene.collision)) {
    if (scene.run.method != Method::dsmc)
      refuse("rough particles (collision.tangential_restitution > -1) other than with method = \"dsmc\"");
    if (scene.collision.kernel != CollisionKernel::hard_sphere || scene.collision.rate > 0.0)
      refuse(
          "rough particles (collision.tangential_restitution > -1) other than hard spheres or disks with "
          "collision.rate = 0");
  }
  if (scene.intruder) {
    SchemeChoice scheme = intruder_plan(scene);
    if (spread == Spread::particles) refuse_spread("an [intruder] scene");
    return {scheme, spread};
  }
  if (scene.run.method == Method::event) {
    EventPlan event = event_plan(scene);
    if (spread == Spread::particles) refuse_spread("a method other than \"dsmc\"");
    if (!scene.weights) return {event, spread};
    if (scene.run.storage != Storage::double_precision) refuse("[weights] with run.storage = \"float\"");
    return {WeightedPlan{event.kernel, event.white_noise}, spread};
  }
  return {stepped_plan(scene, spread), spread};
}

std::string plan_refusal(const Scene& scene, Spread spread) {
  try {
    make_plan(scene, spread);
    return {};
  } catch (const PlanRefusal& e) {
    return e.what();
  }
}

}  // namespace granmc
