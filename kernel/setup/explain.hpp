#pragma once
// What a plan will do before it does it (`granmc run --explain`): the instantiation, the effects that will
// act, the memory and an estimate of the work and the time. Read off the plan (setup/run_plan.hpp).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "kernel/core/scene.hpp"
#include "kernel/setup/run_plan.hpp"

namespace granmc {

struct PlanExplanation {
  std::string instantiation;           // instantiation_name(plan, scene)
  std::vector<std::string> effects;    // every effect and option that will act, in words
  std::vector<std::string> absent;     // effects the scene does not name (not compiled into the run)
  bool gas = true;                     // false for an intruder (no particle store)
  std::size_t bytes_per_particle = 0;  // stored bytes per particle (gas)
  std::uint64_t particle_bytes = 0;    // particle memory of the replicas in flight at once
  int replicas_in_flight = 1;          // min(threads, replicas)
  int threads_per_replica = 1;         // threads inside each replica (share_threads)
  bool threads_inside = false;         // whether a replica can use more than one thread (batched stage, event scheme)
  std::uint64_t least_particles_inside = 0;  // the replica size from which it takes them by default (share_threads)
  double candidates = 0.0;                   // estimated candidate pairs, all replicas (gas)
  double events = 0.0;                       // estimated collision events, all replicas (intruder)
  bool candidates_upper_bound = false;       // true when the estimate assumes T stays at T(0)
  std::string rate_class;                    // the runs whose measured rate estimates the time (gas): a key of
                                             // drivers/explain_rates.toml, e.g. "stepped.beyond_caches"
};

/// Bytes of particle state per particle in the scene's storage precision (32 for double, 16 for float).
std::size_t stored_bytes_per_particle(const Scene& scene) noexcept;

/// The explanation of `plan` (made from `scene`) run on `threads` threads, `threads_per_replica` as
/// RunOptions::threads_per_replica (0: by the replicas' size).
PlanExplanation explain_plan(const RunPlan& plan, const Scene& scene, int threads, int threads_per_replica = 0);

/// A one-line name of what runs, e.g. "dsmc<hard-sphere, gaussian-thermostat>, float storage (16 bytes per
/// particle)".
std::string instantiation_name(const RunPlan& plan, const Scene& scene);

}  // namespace granmc
