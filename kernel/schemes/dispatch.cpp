#include "kernel/schemes/dispatch.hpp"

#include <stdexcept>

#include "kernel/collide/bath_gaussian.hpp"
#include "kernel/collide/bath_power_law.hpp"
#include "kernel/collide/hard_sphere.hpp"
#include "kernel/effects/gaussian_thermostat.hpp"
#include "kernel/schemes/dsmc_replica.hpp"
#include "kernel/schemes/intruder_1d.hpp"
#include "kernel/schemes/replica_runner.hpp"

namespace granmc {

namespace {

// The supported instantiations. Every scene outside this list is refused at start-up. One or two
// species and the Enskog chi need no instantiation of their own: both only change the pair constants.
constexpr const char* supported_list =
    "supported: method = \"dsmc\" with kernel = \"hard-sphere\", one or two species, any packing_fraction in "
    "[0, 1) (Enskog chi), thermostat kind = \"none\" or \"gaussian\" (a fixed zeta or \"cooling-rate\"), "
    "shear rate = 0, relaxation disabled; method = \"gillespie\" with an [intruder] of dimension 1 in a "
    "\"gaussian\" or \"power-law\" bath";

}  // namespace

std::string unsupported_reason(const Scene& scene) {
  std::string what;
  if (scene.run.method == Method::gillespie) {
    if (scene.intruder->dimension != 1) what = "the 2D needle intruder";
  } else if (scene.run.method != Method::dsmc) what = "run.method = \"event\"";
  else if (scene.intruder) what = "the DSMC alternative for the intruder";
  else if (scene.collision.kernel != CollisionKernel::hard_sphere) what = "collision.kernel other than \"hard-sphere\"";
  else if (scene.species.empty() || scene.species.size() > 2) what = "a scene without one or two [[species]]";
  else if (scene.thermostat.kind == ThermostatKind::white_noise) what = "the white-noise [thermostat]";
  else if (scene.shear_rate != 0.0) what = "a [shear] rate";
  else if (scene.relaxation) what = "the [relaxation] term";
  if (what.empty()) return {};
  return "this version of granmc cannot run " + what + " yet; " + supported_list;
}

std::string instantiation_name(const Scene& scene) {
  if (scene.run.method == Method::gillespie)
    return scene.intruder->bath == BathKind::gaussian ? "gillespie-1d<gaussian-bath>" : "gillespie-1d<power-law-bath>";
  std::string name = scene.thermostat.kind == ThermostatKind::gaussian ? "dsmc<hard-sphere, gaussian-thermostat>"
                                                                       : "dsmc<hard-sphere>";
  if (scene.collision.packing_fraction > 0.0) name += ", Enskog chi in the pair rates";
  return name;
}

RunResult run_scene(const Scene& scene, const RunOptions& options) {
  if (const std::string why = unsupported_reason(scene); !why.empty()) throw std::invalid_argument(why);
  if (scene.run.method == Method::gillespie) {
    const IntruderConfig& in = *scene.intruder;
    auto run = [&](const auto& bath) {
      return run_replicas(scene, options, [&](std::uint64_t replica, const std::vector<double>& times) {
        return run_intruder_1d(scene, replica, times, options, bath);
      });
    };
    if (in.bath == BathKind::gaussian) return run(GaussianBath{in.bath_a, in.bath_density});
    return run(PowerLawBath{in.bath_a, in.bath_density});
  }
  if (scene.thermostat.kind == ThermostatKind::gaussian) {
    const GaussianThermostat thermostat{scene.thermostat.zeta_is_cooling_rate, scene.thermostat.zeta};
    return run_replicas(scene, options, [&](std::uint64_t replica, const std::vector<double>& times) {
      return run_dsmc_replica<HardSphere>(scene, replica, times, options, thermostat);
    });
  }
  return run_replicas(scene, options, [&](std::uint64_t replica, const std::vector<double>& times) {
    return run_dsmc_replica<HardSphere>(scene, replica, times, options);
  });
}

}  // namespace granmc
