#pragma once
// The one place that maps a validated scene to the kernel instantiation that runs it.
#include <string>

#include "kernel/core/scene.hpp"
#include "kernel/observe/gas_series.hpp"
#include "kernel/schemes/run_options.hpp"

namespace granmc {

/// Empty if granmc can run the scene; otherwise why not, and what is supported.
std::string unsupported_reason(const Scene& scene);

/// Empty if granmc can spread each replica of the scene over ranks (RunOptions::spread,
/// schemes/spread_dsmc.hpp); otherwise why not, and what is supported.
std::string unsupported_spread_reason(const Scene& scene);

/// Runs the scene (precondition: unsupported_reason(scene) is empty, and unsupported_spread_reason(scene)
/// too when options.spread is set).
RunResult run_scene(const Scene& scene, const RunOptions& options);

/// Whether the collision stage shifts the contact velocity (shear in the Enskog gas,
/// collide/enskog_shear_shift.hpp); it then keeps the paper's order of the acceptance
/// (schemes/collision_stage.hpp).
inline bool has_enskog_shear_shift(const Scene& scene) noexcept {
  return scene.shear_rate != 0.0 && scene.collision.packing_fraction > 0.0;
}

/// A one-line name of the instantiation chosen for the scene, e.g. "dsmc<hard-sphere>".
std::string instantiation_name(const Scene& scene);

}  // namespace granmc
