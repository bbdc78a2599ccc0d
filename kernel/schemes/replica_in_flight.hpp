#pragma once
// A replica stopped at a sample time, with what it needs to go on and give the same bits as a run that never
// stopped: its series so far and the state of its scheme. Checkpoints keep it (io/checkpoint.hpp,
// drivers/run_checkpoints.hpp); the time-stepped scheme (schemes/dsmc.hpp, schemes/dsmc_replica.hpp) and the
// time-step-free ones (schemes/event_scheme.hpp, event_replica.hpp; weighted particles, swpm_scheme.hpp,
// swpm_replica.hpp) make and restore it. The intruder schemes keep whole replicas only.
#include <cstdint>
#include <variant>
#include <vector>

#include "kernel/core/sym_tensor.hpp"
#include "kernel/core/velocity_scale.hpp"
#include "kernel/observe/gas_series.hpp"
#include "kernel/schemes/collision_stage.hpp"
#include "kernel/schemes/event_tallies.hpp"
#include "kernel/schemes/weight_control.hpp"
#include "kernel/schemes/weighted_particles.hpp"

namespace granmc {

/// The state of a time-stepped replica (schemes/dsmc.hpp) at a sample time, where no effect owes a half
/// step. The per-step scratch (candidates, step tallies) is rebuilt by the next step.
struct DsmcSnapshot {
  std::vector<std::vector<double>> velocities;  // per species: x, y, z of each particle, stored units
  std::vector<std::vector<double>> spins;       // rough particles, per species: s of each particle, as velocities
  double log_u = 0.0;                           // the velocity scale (core/velocity_scale.hpp)
  double time = 0.0;
  std::uint64_t step = 0;  // the random streams' step counter
  std::vector<double> omega_max;
  std::vector<double> carried;  // fractional candidates carried to the next step, per pair
  CollisionTally total;
  std::vector<CollisionTally> pair_totals;
  double twice_energy = 0.0;
  double reference_twice_energy = 0.0;
  double log_temperature0 = 0.0;
  double momentum_removed = 0.0;
  std::uint64_t rescales = 0;
  SymTensor transfer_integral;
  double transfer_since = 0.0;
};

/// The state of a time-step-free replica (schemes/event_scheme.hpp) at a sample time. What else it holds there
/// follows from this: every particle's last update is the time (with white noise), U_max is reset from the
/// velocities, and the draw batches are the draws from `draws` on.
struct EventSnapshot {
  std::vector<double> velocities;  // x, y, z of each particle, stored units
  double time = 0.0;
  std::uint64_t draws = 0;  // the candidates' random counter
  std::uint64_t syncs = 0;  // sample-time updates so far (the Brownian sync counter)
  EventTally tally;
};

/// The state of a replica of weighted particles (schemes/swpm_scheme.hpp) at a sample time: the particles with
/// their weight classes, the weight control, and the counters. U_max follows from the particles.
struct SwpmSnapshot {
  WeightedParticles particles;
  WeightControl control;
  VelocityScale scale;  // the stored unit
  std::uint64_t rescales = 0;
  double time = 0.0;
  std::uint64_t draws = 0;  // the candidates' random counter
  std::uint64_t syncs = 0;  // updates of every particle so far
  SwpmTally tally;
};

struct ReplicaInFlight {
  ReplicaSeries series;                  // the observations so far
  std::uint64_t samples_taken = 0;       // the next sample time is times[samples_taken]
  std::vector<double> initial_majorant;  // time-stepped scheme: per pair, for the series' majorant_growth
  std::variant<DsmcSnapshot, EventSnapshot, SwpmSnapshot> state;
};

// Every field, in one order (the checkpoint's packing walks it, io/replica_bytes.hpp).
template <class S, class Visit>
void visit_snapshot_fields(S& s, Visit&& visit) {
  visit("velocities", s.velocities);
  visit("spins", s.spins);
  visit("log_u", s.log_u);
  visit("time", s.time);
  visit("step", s.step);
  visit("omega_max", s.omega_max);
  visit("carried", s.carried);
  visit("total", s.total);
  visit("pair_totals", s.pair_totals);
  visit("twice_energy", s.twice_energy);
  visit("reference_twice_energy", s.reference_twice_energy);
  visit("log_temperature0", s.log_temperature0);
  visit("momentum_removed", s.momentum_removed);
  visit("rescales", s.rescales);
  visit("transfer_integral", s.transfer_integral);
  visit("transfer_since", s.transfer_since);
}

template <class S, class Visit>
void visit_event_snapshot_fields(S& s, Visit&& visit) {
  visit("velocities", s.velocities);
  visit("time", s.time);
  visit("draws", s.draws);
  visit("syncs", s.syncs);
  visit("tally", s.tally);
}

template <class S, class Visit>
void visit_swpm_snapshot_fields(S& s, Visit&& visit) {
  visit("particles", s.particles);
  visit("control", s.control);
  visit("scale", s.scale);
  visit("rescales", s.rescales);
  visit("time", s.time);
  visit("draws", s.draws);
  visit("syncs", s.syncs);
  visit("tally", s.tally);
}

#if defined(__GLIBCXX__) && defined(__x86_64__) && !defined(_GLIBCXX_DEBUG)
// Tripwires: a field added to a snapshot must be added to its list above; then update the size.
static_assert(sizeof(DsmcSnapshot) == 328, "DsmcSnapshot changed: add the new field to visit_snapshot_fields");
static_assert(sizeof(EventSnapshot) == 80, "EventSnapshot changed: add the new field to visit_event_snapshot_fields");
static_assert(sizeof(SwpmSnapshot) == 344, "SwpmSnapshot changed: add the new field to visit_swpm_snapshot_fields");
static_assert(sizeof(WeightedParticles) == 168, "WeightedParticles changed: add the new field to its visit_fields");
static_assert(sizeof(WeightControl) == 96, "WeightControl changed: add the new field to its visit_fields");
#endif

}  // namespace granmc
