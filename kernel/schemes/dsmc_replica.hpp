#pragma once
// One replica of the time-stepped scheme from t = 0 to t_end, observed at the sample times, whatever its
// backend (schemes/dsmc.hpp).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

#include "kernel/observe/gas_observation.hpp"
#include "kernel/observe/pressure_tensor.hpp"
#include "kernel/schemes/dsmc.hpp"
#include "kernel/schemes/replica_in_flight.hpp"
#include "kernel/schemes/run_options.hpp"

namespace granmc {

/// Runs `sim` (a BasicDsmc just made for replica `replica`) to each sample time in turn and records the
/// replica's series; options.on_sample is called after each observation. From a state options.restored_in_flight
/// gives, it goes on from there; when options.in_flight_wanted asks, it hands its state to options.on_in_flight
/// (RunOptions, schemes/replica_in_flight.hpp).
template <class Sim>
ReplicaSeries run_dsmc_replica(Sim& sim, const Scene& scene, const std::vector<double>& times, std::uint64_t replica,
                               const RunOptions& options) {
  std::vector<double> initial_majorant = sim.omega_max();
  ReplicaSeries series;
  series.species.resize(scene.species.size());
  const std::size_t first = resume_in_flight<DsmcSnapshot>(options, replica, sim, series);
  if (first > 0) initial_majorant = restored_in_flight(options, replica)->initial_majorant;
  for (std::size_t k = first; k < times.size(); ++k) {
    sim.advance_to(times[k]);
    const GasTotals summed = sim.observe(series, k >= first_stationary_sample(times.size()));
    series.energy_residual = std::max(series.energy_residual.value_or(0.0),
                                      std::abs(sim.tracked_twice_energy() / summed.twice_energy - 1.0));
    if constexpr (Sim::sheared) {
      ShearSeries& shear = series.shear ? *series.shear : series.shear.emplace();
      shear.pressure_kinetic.push_back(reduced_kinetic_pressure(scene, sim.state()));
      shear.pressure_collisional.push_back(sim.take_collisional_pressure());
      shear.reduced_shear_rate.push_back(scene.shear_rate /
                                         effective_collision_frequency(scene, series.temperature.back()));
    }
    series.collisions.push_back(static_cast<double>(sim.tally().collisions));
    if (in_flight_wanted(options, replica, k, times.size()))
      options.on_in_flight(replica, ReplicaInFlight{series, k + 1, initial_majorant, sim.snapshot()});
    if (options.on_sample) options.on_sample();
  }
  for (const CollisionTally& pair : sim.pair_tallies()) series.pair_collisions.push_back(pair.collisions);
  for (std::size_t q = 0; q < initial_majorant.size(); ++q)
    series.majorant_growth.push_back(sim.omega_max()[q] / initial_majorant[q]);
  series.candidates = sim.tally().candidates;
  series.majorant_updates = sim.tally().majorant_updates;
  series.rescales = sim.rescales();
  series.momentum_removed_relative = sim.momentum_removed_relative();
  return series;
}

}  // namespace granmc
