#pragma once
// One replica of the time-step-free white-noise scheme (001 sec. 4) from t = 0 to t_end, observed at the
// sample times.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "kernel/observe/gas_observation.hpp"
#include "kernel/schemes/event_rounds.hpp"
#include "kernel/schemes/event_scheme.hpp"
#include "kernel/schemes/run_options.hpp"

namespace granmc {

/// From a state options.restored_in_flight gives, it goes on from there; when options.in_flight_wanted asks,
/// it hands its state to options.on_in_flight (RunOptions, schemes/replica_in_flight.hpp). With `threads` > 1
/// the candidates run in concurrent rounds (schemes/event_rounds.hpp), whose counts `rounds` receives.
template <class Real, class Kernel>
ReplicaSeries run_event_replica(const Scene& scene, std::uint64_t replica, const std::vector<double>& times,
                                const RunOptions& options, Kernel kernel, int threads = 1,
                                CollisionRoundCounts* rounds = nullptr) {
  using Scheme = BasicEventScheme<Real, Kernel>;
  Scheme sim(scene, replica, kernel, threads);
  EventRounds<Scheme> in_rounds(threads);
  ReplicaSeries series;
  series.species.resize(1);
  for (std::size_t k = resume_in_flight<EventSnapshot>(options, replica, sim, series); k < times.size(); ++k) {
    in_rounds.advance_to(sim, times[k]);
    observe_gas(scene, sim.state(), series, k >= first_stationary_sample(times.size()));
    series.collisions.push_back(static_cast<double>(sim.tally().collisions));
    if (in_flight_wanted(options, replica, k, times.size()))
      options.on_in_flight(replica, ReplicaInFlight{series, k + 1, {}, sim.snapshot()});
    if (options.on_sample) options.on_sample();
  }
  series.pair_collisions.push_back(sim.tally().collisions);
  series.candidates = sim.tally().candidates;
  series.majorant_updates = sim.tally().majorant_updates;
  series.majorant_violations = sim.tally().majorant_violations;
  if (rounds != nullptr) *rounds = in_rounds.counts();
  return series;
}

}  // namespace granmc
