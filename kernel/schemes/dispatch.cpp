#include "kernel/schemes/dispatch.hpp"

#include <stdexcept>

#include "kernel/collide/hard_sphere.hpp"
#include "kernel/schemes/dsmc_replica.hpp"
#include "kernel/schemes/replica_runner.hpp"

namespace granmc {

namespace {

// The supported instantiations. Every scene outside this list is refused at start-up.
constexpr const char* supported_list =
    "supported: method = \"dsmc\" with kernel = \"hard-sphere\", one species, thermostat kind = \"none\", "
    "shear rate = 0, relaxation disabled, any packing_fraction in [0, 1) (Enskog chi)";

}  // namespace

std::string unsupported_reason(const Scene& scene) {
  std::string what;
  if (scene.run.method != Method::dsmc) what = "run.method other than \"dsmc\"";
  else if (scene.collision.kernel != CollisionKernel::hard_sphere) what = "collision.kernel other than \"hard-sphere\"";
  else if (scene.species.size() != 1) what = "more than one [[species]]";
  else if (scene.thermostat.kind != ThermostatKind::none) what = "a [thermostat]";
  else if (scene.shear_rate != 0.0) what = "a [shear] rate";
  else if (scene.relaxation) what = "the [relaxation] term";
  if (what.empty()) return {};
  return "this version of granmc cannot run " + what + " yet; " + supported_list;
}

std::string instantiation_name(const Scene& scene) {
  return scene.collision.packing_fraction > 0.0 ? "dsmc<hard-sphere>, Enskog chi in the pair rate"
                                                : "dsmc<hard-sphere>";
}

RunResult run_scene(const Scene& scene, const RunOptions& options) {
  if (const std::string why = unsupported_reason(scene); !why.empty()) throw std::invalid_argument(why);
  return run_replicas(scene, options, [&](std::uint64_t replica, const std::vector<double>& times) {
    return run_dsmc_replica<HardSphere>(scene, replica, times, options);
  });
}

}  // namespace granmc
