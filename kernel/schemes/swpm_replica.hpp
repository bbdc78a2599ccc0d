#pragma once
// One replica of weighted particles (schemes/swpm_scheme.hpp) from t = 0 to t_end, observed at the sample
// times.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "kernel/observe/weighted_observation.hpp"
#include "kernel/schemes/run_options.hpp"
#include "kernel/schemes/swpm_scheme.hpp"

namespace granmc {

/// From a state options.restored_in_flight gives, it goes on from there; when options.in_flight_wanted asks,
/// it hands its state to options.on_in_flight (RunOptions, schemes/replica_in_flight.hpp).
template <class Kernel>
ReplicaSeries run_swpm_replica(const Scene& scene, std::uint64_t replica, const std::vector<double>& times,
                               const RunOptions& options, Kernel kernel) {
  SwpmScheme<Kernel> sim(scene, replica, kernel);
  ReplicaSeries series;
  series.species.resize(1);
  series.weighted.emplace();
  const std::size_t first = resume_in_flight<SwpmSnapshot>(options, replica, sim, series);
  WeightedSeries& weighted = *series.weighted;
  for (std::size_t k = first; k < times.size(); ++k) {
    sim.advance_to(times[k]);
    observe_weighted(scene, sim.particles(), sim.scale(), series, k >= first_stationary_sample(times.size()));
    series.collisions.push_back(static_cast<double>(sim.tally().collisions));
    weighted.particles.push_back(static_cast<double>(sim.particles().size()));
    if (in_flight_wanted(options, replica, k, times.size()))
      options.on_in_flight(replica, ReplicaInFlight{series, k + 1, {}, sim.snapshot()});
    if (options.on_sample) options.on_sample();
  }
  series.pair_collisions.push_back(sim.tally().collisions);
  series.candidates = sim.tally().candidates;
  series.majorant_updates = sim.tally().majorant_updates;
  series.majorant_violations = sim.tally().majorant_violations;
  series.rescales = sim.rescales();
  const WeightControlTally& control = sim.control_tally();
  weighted.transfers = sim.tally().transfers;
  weighted.controls = control.controls;
  weighted.split_copies = control.split_copies;
  weighted.reductions = control.reductions;
  weighted.reduced = control.reduced;
  weighted.conservation_residual = control.residual;
  return series;
}

}  // namespace granmc
