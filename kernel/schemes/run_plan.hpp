#pragma once
// What a run will do before it does it (`granmc run --explain`): the instantiation, the effects that
// will act, the memory and an estimate of the work.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "kernel/core/scene.hpp"

namespace granmc {

struct RunPlan {
  std::string instantiation;           // as dispatch.cpp names it
  std::vector<std::string> effects;    // every effect and option that will act, in words
  std::vector<std::string> absent;     // effects the scene does not name (not compiled into the run)
  std::uint64_t particle_bytes = 0;    // particle memory of the replicas in flight at once
  int replicas_in_flight = 1;          // min(threads, replicas)
  double candidates = 0.0;             // estimated candidate pairs, all replicas (gas)
  double events = 0.0;                 // estimated collision events, all replicas (intruder)
  bool candidates_upper_bound = false; // true when the estimate assumes T stays at T(0)
};

/// Bytes of particle state per particle in the scene's storage precision (32 for double, 16 for float).
std::size_t stored_bytes_per_particle(const Scene& scene) noexcept;

/// The plan for `scene` run on `threads` threads (precondition: the scene is supported).
RunPlan plan_run(const Scene& scene, int threads);

}  // namespace granmc
