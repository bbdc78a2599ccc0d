#include "kernel/schemes/dispatch.hpp"

#include <stdexcept>

#include "kernel/collide/bath_gaussian.hpp"
#include "kernel/collide/bath_power_law.hpp"
#include "kernel/collide/enskog_shear_shift.hpp"
#include "kernel/collide/hard_sphere.hpp"
#include "kernel/collide/isotropic_kernels.hpp"
#include "kernel/collide/maxwell_pseudomolecules.hpp"
#include "kernel/collide/variable_hard_spheres.hpp"
#include "kernel/effects/bgk_relaxation.hpp"
#include "kernel/effects/gaussian_thermostat.hpp"
#include "kernel/effects/lagrangian_shear.hpp"
#include "kernel/effects/white_noise.hpp"
#include "kernel/schemes/dsmc_replica.hpp"
#include "kernel/schemes/event_replica.hpp"
#include "kernel/schemes/intruder_1d.hpp"
#include "kernel/schemes/intruder_dsmc_1d.hpp"
#include "kernel/schemes/intruder_needle.hpp"
#include "kernel/schemes/replica_runner.hpp"
#include "kernel/schemes/sample_times.hpp"
#include "kernel/schemes/spread_dsmc.hpp"
#include "kernel/theory/sonine.hpp"

namespace granmc {

namespace {

// The supported instantiations. Every scene outside this list is refused at start-up. One or two
// species and the Enskog chi need no instantiation of their own: both only change the pair constants.
constexpr const char* supported_list =
    "supported: method = \"dsmc\" with kernel = \"hard-sphere\", one or two species, any packing_fraction in "
    "[0, 1) (Enskog chi), or kernel = \"maxwell\" or \"vhs\" with collision.rate > 0 and one species; thermostat kind = "
    "\"none\", \"gaussian\" (a fixed zeta or \"cooling-rate\") or \"white-noise\"; a [shear] rate with "
    "hard spheres and thermostat \"none\" or \"gaussian\" (Boltzmann, or Enskog with the shifted contact "
    "velocity when packing_fraction > 0); the [relaxation] term of 003 for one species of hard spheres with "
    "the Gaussian thermostat compensating the cooling rate; method = \"event\" with one species, collision.rate > 0 (the "
    "form of 001) and mass 1, kernel \"maxwell\", \"vhs\" or \"hard-sphere\", thermostat \"none\" or \"white-noise\", "
    "packing_fraction = 0, no shear or relaxation; method = \"gillespie\" with an [intruder] of dimension 1 in "
    "a \"gaussian\" or \"power-law\" bath, or of dimension 2 (the needle) in a \"gaussian\" bath; method = "
    "\"dsmc\" with an [intruder] of dimension 1 (002 sec. 4); run.storage \"double\" or \"float\" for every gas scene";

/// Why granmc cannot run an event-scheme scene, or empty.
std::string unsupported_event(const Scene& scene) {
  if (scene.species.size() != 1) return "the event scheme with other than one [[species]]";
  if (scene.species[0].mass != 1.0) return "the event scheme with a species mass other than 1 (001 has unit mass)";
  if (!(scene.collision.rate > 0.0)) return "the event scheme with collision.rate = 0 (the 000 hard-sphere form)";
  if (scene.thermostat.kind == ThermostatKind::gaussian) return "the event scheme with the Gaussian thermostat";
  if (scene.collision.packing_fraction > 0.0) return "the event scheme with a packing_fraction (Enskog)";
  if (scene.shear_rate != 0.0) return "the event scheme with a [shear] rate";
  if (scene.relaxation) return "the event scheme with the [relaxation] term";
  return {};
}

/// The time-stepped scheme with the kernel K, the effects `before` (shear) and the thermostat the scene
/// names (none is an empty pack), in the scene's storage precision; `white_noise` says whether that
/// instantiation exists.
template <class K, bool white_noise, class... Before>
RunResult run_dsmc(const Scene& scene, const RunOptions& options, Before... before) {
  auto run = [&](auto... effects) {
    auto in = [&](auto real) {
      using Real = decltype(real);
      return run_replicas(scene, options, [&](std::uint64_t replica, const std::vector<double>& times) {
        return run_dsmc_replica<Real, K>(scene, replica, times, options, before..., effects...);
      });
    };
    return scene.run.storage == Storage::single_precision ? in(float{}) : in(double{});
  };
  const ThermostatConfig& th = scene.thermostat;
  if (th.kind == ThermostatKind::gaussian && scene.relaxation)  // 003: thermostat, then the relaxation term
    return run(GaussianThermostat{th.zeta_is_cooling_rate, th.zeta},
               BgkRelaxation{SonineMaxwellian(scene.relaxation_a2.value_or(theory::hcs_a2(scene.collision.restitution[0][0]))),
                             scene.species[0].mass});
  if (th.kind == ThermostatKind::gaussian) return run(GaussianThermostat{th.zeta_is_cooling_rate, th.zeta});
  if constexpr (white_noise)
    if (th.kind == ThermostatKind::white_noise) return run(WhiteNoise{th.beta, &scene});
  return run();
}

/// Hard spheres with the shear the scene names: the inertial force alone in the Boltzmann limit, with
/// the Enskog shift of the contact velocity when packing_fraction > 0 (collide/enskog_shear_shift.hpp).
RunResult run_dsmc_hard_spheres(const Scene& scene, const RunOptions& options) {
  if (scene.shear_rate == 0.0) return run_dsmc<HardSphere, true>(scene, options);
  const LagrangianShear shear{scene.shear_rate, &scene};
  if (has_enskog_shear_shift(scene))
    return run_dsmc<HardSphere, false>(scene, options, shear, EnskogShearShift{scene.shear_rate});
  return run_dsmc<HardSphere, false>(scene, options, shear);
}

/// Every replica spread over options.spread, one after another (schemes/spread_dsmc.hpp).
RunResult run_spread(const Scene& scene, const RunOptions& options) {
  auto run = [&](auto kernel) {
    RunResult result;
    result.times = sample_times(scene.run);
    result.species_names.push_back(scene.species[0].name);
    result.threads = 1;
    for (int r = 0; r < scene.run.replicas; ++r)
      result.replicas.push_back(run_spread_replica<decltype(kernel)>(scene, static_cast<std::uint64_t>(r), result.times,
                                                                    *options.spread, options.on_sample));
    return result;
  };
  if (scene.collision.kernel == CollisionKernel::maxwell) return run(MaxwellPseudomolecules{});
  if (scene.collision.kernel == CollisionKernel::vhs) return run(VariableHardSpheres{});
  return run(HardSphere{});
}

/// The instantiation name's note on the storage precision (none for the default, double).
std::string storage_name(const Scene& scene) {
  return scene.run.storage == Storage::single_precision ? ", float storage (16 bytes per particle)" : "";
}

}  // namespace

std::string unsupported_reason(const Scene& scene) {
  std::string what;
  if (scene.intruder && scene.run.storage != Storage::double_precision) {
    what = "run.storage = \"float\" for an intruder scene (it stores no gas)";
  } else if (scene.run.method == Method::gillespie) {
    if (scene.intruder->dimension == 2 && scene.intruder->bath != BathKind::gaussian)
      what = "the 2D needle in a \"power-law\" bath";
  } else if (scene.run.method == Method::event) what = unsupported_event(scene);
  else if (scene.intruder && scene.intruder->dimension != 1) what = "the DSMC alternative for the 2D needle";
  else if (scene.intruder && !(scene.run.t_end / scene.run.dt < static_cast<double>(RandomStream::counter_limit)))
    what = "an intruder DSMC run with more than 2^48 time steps (raise run.dt)";
  else if (scene.intruder) what = {};
  else if (scene.collision.kernel != CollisionKernel::hard_sphere && !(scene.collision.rate > 0.0))
    what = "method = \"dsmc\" with kernel = \"maxwell\" or \"vhs\" and collision.rate = 0 (set the rate of 001)";
  else if (scene.species.empty() || scene.species.size() > 2) what = "a scene without one or two [[species]]";
  else if (scene.shear_rate != 0.0 && scene.collision.kernel != CollisionKernel::hard_sphere)
    what = "a [shear] rate with kernel = \"maxwell\" or \"vhs\"";
  else if (scene.shear_rate != 0.0 && scene.thermostat.kind == ThermostatKind::white_noise)
    what = "a [shear] rate with the white-noise thermostat";
  else if (scene.relaxation && (scene.species.size() != 1 || scene.collision.kernel != CollisionKernel::hard_sphere ||
                                !scene.thermostat.zeta_is_cooling_rate))
    what = "the [relaxation] term other than for one species of hard spheres with zeta = \"cooling-rate\" (003)";
  if (what.empty()) return {};
  return "this version of granmc cannot run " + what + " yet; " + supported_list;
}

std::string unsupported_spread_reason(const Scene& scene) {
  std::string what;
  if (scene.run.method != Method::dsmc) what = "a method other than \"dsmc\"";
  else if (scene.intruder) what = "an [intruder] scene";
  else if (scene.species.size() != 1) what = "two species";
  else if (scene.shear_rate != 0.0) what = "a [shear] rate";
  else if (scene.relaxation) what = "the [relaxation] term";
  else if (scene.run.storage != Storage::double_precision) what = "run.storage = \"float\"";
  if (what.empty()) return {};
  return "one system over several ranks (--spread particles) is not implemented for " + what +
         "; it runs method \"dsmc\" with one species, any kernel and packing_fraction, any thermostat, double "
         "storage (docs/scaling.md)";
}

std::string instantiation_name(const Scene& scene) {
  if (scene.run.method == Method::gillespie && scene.intruder->dimension == 2) return "gillespie-needle<gaussian-bath>";
  if (scene.run.method == Method::dsmc && scene.intruder)
    return scene.intruder->bath == BathKind::gaussian ? "dsmc-intruder-1d<gaussian-bath>" : "dsmc-intruder-1d<power-law-bath>";
  if (scene.run.method == Method::gillespie)
    return scene.intruder->bath == BathKind::gaussian ? "gillespie-1d<gaussian-bath>" : "gillespie-1d<power-law-bath>";
  if (scene.run.method == Method::event) {
    const char* kernel = scene.collision.lambda == 0.0 ? MaxwellKernel::name
                         : scene.collision.lambda == 1.0 ? IsotropicHardSphereKernel::name
                                                         : VhsKernel::name;
    return std::string("event<") + kernel + (scene.thermostat.kind == ThermostatKind::white_noise ? ", white-noise>" : ">") +
           storage_name(scene);
  }
  std::string name = std::string("dsmc<") +
                     (scene.collision.kernel == CollisionKernel::maxwell ? MaxwellPseudomolecules::name
                      : scene.collision.kernel == CollisionKernel::vhs  ? VariableHardSpheres::name
                                                                        : HardSphere::name);
  if (scene.shear_rate != 0.0) name += ", lagrangian-shear";
  if (has_enskog_shear_shift(scene)) name += ", enskog-shear-shift";
  if (scene.thermostat.kind == ThermostatKind::gaussian) name += ", gaussian-thermostat";
  if (scene.relaxation) name += ", bgk-relaxation";
  if (scene.thermostat.kind == ThermostatKind::white_noise) name += ", white-noise";
  name += ">";
  if (scene.collision.packing_fraction > 0.0) name += ", Enskog chi in the pair rates";
  return name + storage_name(scene);
}

RunResult run_scene(const Scene& scene, const RunOptions& options) {
  if (const std::string why = unsupported_reason(scene); !why.empty()) throw std::invalid_argument(why);
  if (options.spread) {
    if (const std::string why = unsupported_spread_reason(scene); !why.empty()) throw std::invalid_argument(why);
    return run_spread(scene, options);
  }
  if (scene.run.method == Method::gillespie) {
    const IntruderConfig& in = *scene.intruder;
    if (in.dimension == 2)
      return run_replicas(scene, options, [&](std::uint64_t replica, const std::vector<double>& times) {
        return run_intruder_needle(scene, replica, times, options);
      });
    auto run = [&](const auto& bath) {
      return run_replicas(scene, options, [&](std::uint64_t replica, const std::vector<double>& times) {
        return run_intruder_1d(scene, replica, times, options, bath);
      });
    };
    if (in.bath == BathKind::gaussian) return run(GaussianBath{in.bath_a, in.bath_density});
    return run(PowerLawBath{in.bath_a, in.bath_density});
  }
  if (scene.intruder) {  // method "dsmc": the intruder's DSMC alternative (002 sec. 4)
    const IntruderConfig& in = *scene.intruder;
    auto run = [&](const auto& bath) {
      return run_replicas(scene, options, [&](std::uint64_t replica, const std::vector<double>& times) {
        return run_intruder_dsmc_1d(scene, replica, times, options, bath);
      });
    };
    if (in.bath == BathKind::gaussian) return run(GaussianBath{in.bath_a, in.bath_density});
    return run(PowerLawBath{in.bath_a, in.bath_density});
  }
  if (scene.run.method == Method::event) {
    auto run = [&](auto kernel) {
      auto in = [&](auto real) {
        return run_replicas(scene, options, [&](std::uint64_t replica, const std::vector<double>& times) {
          return run_event_replica<decltype(real)>(scene, replica, times, options, kernel);
        });
      };
      return scene.run.storage == Storage::single_precision ? in(float{}) : in(double{});
    };
    if (scene.collision.lambda == 0.0) return run(MaxwellKernel{});
    if (scene.collision.lambda == 1.0) return run(IsotropicHardSphereKernel{});
    return run(VhsKernel{scene.collision.lambda});
  }
  if (scene.collision.kernel == CollisionKernel::maxwell) return run_dsmc<MaxwellPseudomolecules, true>(scene, options);
  if (scene.collision.kernel == CollisionKernel::vhs) return run_dsmc<VariableHardSpheres, true>(scene, options);
  return run_dsmc_hard_spheres(scene, options);
}

}  // namespace granmc
