#pragma once
// Observes a replica of weighted particles (schemes/swpm_scheme.hpp) at a sample time: the moments and the
// speed histogram of the measure sum_k w_k delta(v - v_k), in the units of an equal-weight gas of
// N = species.particles particles, so that the temperatures, cumulants and speed distribution are read as
// the event scheme's are (observe/gas_observation.hpp, analysis/run_report.hpp).
#include "kernel/core/scene.hpp"
#include "kernel/core/velocity_scale.hpp"
#include "kernel/observe/gas_series.hpp"
#include "kernel/schemes/weighted_particles.hpp"

namespace granmc {

/// Appends the temperature, a2, a3 and momentum of the weighted measure to `series` (one species); with
/// `histogram`, adds each shell's weight, in units of 1 / N of the total, to the species' speed_counts.
void observe_weighted(const Scene& scene, const WeightedParticles& particles, const VelocityScale& scale,
                      ReplicaSeries& series, bool histogram);

}  // namespace granmc
