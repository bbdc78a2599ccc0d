#pragma once
// What a gas replica records at each sample time, and the run's results over all replicas.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "kernel/core/sym_tensor.hpp"
#include "kernel/core/vec3.hpp"

namespace granmc {

/// The samples k >= S / 2 (integer division) of S sample times t_0 .. t_{S-1}: the times in the last half
/// of a run, t_k >= t_end / 2 for linear spacing, where heated and scaled cooling states are stationary.
/// Time averages and speed histograms are taken over them; with samples = 1 (S = 2), the final state only
/// (as 001 sec. 5.3 takes its histograms).
constexpr std::size_t first_stationary_sample(std::size_t sample_times) noexcept { return sample_times / 2; }

/// The same window in time, [t_{S/2}, t_{S-1}]: the exact time integrals of IntruderSeries run over it.
inline std::pair<double, double> stationary_window(const std::vector<double>& times) noexcept {
  return {times[first_stationary_sample(times.size())], times.back()};
}

struct SpeciesSeries {
  std::vector<double> temperature;      // T_i = m_i <V^2> / d (energy units)
  std::vector<double> log_temperature;  // ln T_i, finite where T_i underflows
  std::vector<double> a2;               // d/(d+2) <V^4> / <V^2>^2 - 1 (observe/moments.hpp)
  std::vector<double> a3;               // third Sonine coefficient (observe/moments.hpp)
  std::vector<double> speed_counts;     // histogram of v* = |V| / v0 over the stationary samples
                                        // (observe/speed_histogram.hpp), output.histogram shells; for
                                        // weighted particles the weight in each shell in units of 1 / N_i
  // Rough particles (collide/rough_rule.hpp), empty for smooth ones:
  std::vector<double> rotational_temperature;  // T_rot,i = I_i <omega^2> / d_r (d_r = 3 spheres, 1 disks)
  std::vector<double> a02;                     // d_r/(d_r+2) <omega^4> / <omega^2>^2 - 1 (observe/moments.hpp)
  std::vector<double> a11;                     // <V^2 omega^2> / (<V^2> <omega^2>) - 1
};

/// What an intruder replica records (method "gillespie", 002).
struct IntruderSeries {
  std::vector<double> velocity;         // v1 at each sample time (1D)
  std::vector<double> speed_counts;     // histogram of |v1| over the stationary samples (output.histogram,
                                        // radius in velocity units)
  std::uint64_t sampling_attempts = 0;  // rejection attempts for the colliding bath velocities
  // The needle (002 sec. 3.2) also counts its impact-point attempts in sampling_attempts.
  std::vector<double> velocity_y;         // needle: v1_y at each sample time (velocity holds v1_x)
  std::vector<double> angular_velocity;   // needle: omega at each sample time
  std::vector<double> angular_counts;     // needle: histogram of |omega| over the stationary samples
                                          // (output.histogram shells, radius in 1/time units)
  std::uint64_t newton_iterations = 0;    // needle: Newton steps for the event times (002 eq. 28)
  std::uint64_t bisection_fallbacks = 0;  // needle: bisection steps taken instead of a Newton step
  // Gillespie intruder and needle: exact integrals over the stationary window [t_K/2, t_end] (the velocities
  // are constant between events) of |v1|^2 dt and, for the needle, omega^2 dt and |v1|^2 omega^2 dt; 0 where
  // the scheme does not track them.
  double v2_time_integral = 0.0;
  double w2_time_integral = 0.0;
  double v2w2_time_integral = 0.0;
};

/// What a sheared replica records (000 secs. 2-3; observe/pressure_tensor.hpp), each at every sample time.
struct ShearSeries {
  std::vector<SymTensor> pressure_kinetic;      // P^k / (n T) at the sample (000 eq. 17)
  std::vector<SymTensor> pressure_collisional;  // P^c / (n T) averaged since the previous sample (eq. 18);
                                                // zero at t = 0 and in the Boltzmann limit
  std::vector<double> reduced_shear_rate;       // a* = a / nu, nu = sqrt(pi) n sigma_12^2 v_0 (000 Fig. 10)
};

/// What a replica of weighted particles records (schemes/swpm_scheme.hpp, schemes/weight_control.hpp).
struct WeightedSeries {
  std::vector<double> particles;       // particles at each sample time, after the weight control
  std::uint64_t transfers = 0;         // collisions of unequal weights, each adding a particle
  std::uint64_t controls = 0;          // whole-system weight controls
  std::uint64_t split_copies = 0;      // particles added by splitting
  std::uint64_t reductions = 0;        // groups replaced by two particles
  std::uint64_t reduced = 0;           // particles removed by the reductions
  double conservation_residual = 0.0;  // largest relative change of mass, momentum or energy at a control
};

/// The documented bound on ReplicaSeries::energy_residual (docs/methods/physics.md, "Energy balance"). The suite
/// measures 2e-16 to 1.3e-15; rounding that added up linearly (1e-16 per step) over the 10^5 steps of a long
/// heated run, which never rescales, would reach 1e-11. An effect that does not report its energy change
/// misses by 1e-2 to 0.2 in tests/test_shear.cpp (checked by breaking the shear map's return).
inline constexpr double energy_balance_tolerance = 1e-10;

struct ReplicaSeries {
  std::vector<double> temperature;      // mixture T = sum_i x_i T_i (intruder: T = M v1^2 per degree
                                        // of freedom)
  std::vector<double> log_temperature;  // ln T
  std::vector<SpeciesSeries> species;
  std::vector<Vec3> momentum;                  // total momentum sum_i m_i sum_k V_k (scene units); gas only
  std::vector<double> momentum_relative;       // |P| / sqrt(M_total 2 E_kin): centre-of-mass speed / rms speed
  std::vector<double> collisions;              // accepted collisions since t = 0, at each sample
  std::vector<std::uint64_t> pair_collisions;  // accepted collisions per ordered species pair (i, j),
                                               // in the order i * species + j, whole run
  std::uint64_t histogram_samples = 0;         // samples added to the speed histograms (gas or intruder)
  std::uint64_t candidates = 0;                // candidate pairs tested
  std::uint64_t majorant_updates = 0;          // times omega_max (U_max for the event scheme) was raised
  std::uint64_t majorant_violations = 0;       // event scheme: candidates whose relative speed exceeded the
                                               // U_max their waiting time was drawn with (schemes/event_scheme.hpp)
  std::vector<double> majorant_growth;         // per ordered pair: final / initial omega_max (stored units)
  std::uint64_t rescales = 0;                  // velocity rescalings (long cooling runs)
  double momentum_removed_relative = 0.0;      // sum over rescalings of the removed |P| / sqrt(M 2 E)
  // Time-stepped gas (schemes/dsmc.hpp): the largest |E_tracked / E_summed - 1| over the sample times, where
  // E_tracked is the step's energy bookkeeping (start, minus collisional losses, plus each effect's returned
  // change) and E_summed = sum_i m_i sum_k |c_k|^2 summed afresh; closes to rounding when every effect
  // reports what it did (docs/methods/physics.md, "Energy balance"). Empty for schemes that do not track energy.
  std::optional<double> energy_residual;
  std::optional<ShearSeries> shear;        // uniform shear flow
  std::optional<IntruderSeries> intruder;  // method "gillespie"
  std::optional<WeightedSeries> weighted;  // [weights]
};

// Every field of a replica's series, each under its name, in one order: the one list that packing a replica
// for another process (drivers/mpi_replicas.cpp) walks, so that a field added to the structs above and not here
// is caught by the sizes asserted below. visit(name, field) is called for each; an optional record is one
// field (the visitor walks its fields with the visit_*_fields below).

template <class S, class Visit>
void visit_species_fields(S& s, Visit&& visit) {
  visit("temperature", s.temperature);
  visit("log_temperature", s.log_temperature);
  visit("a2", s.a2);
  visit("a3", s.a3);
  visit("speed_counts", s.speed_counts);
  visit("rotational_temperature", s.rotational_temperature);
  visit("a02", s.a02);
  visit("a11", s.a11);
}

template <class S, class Visit>
void visit_shear_fields(S& s, Visit&& visit) {
  visit("pressure_kinetic", s.pressure_kinetic);
  visit("pressure_collisional", s.pressure_collisional);
  visit("reduced_shear_rate", s.reduced_shear_rate);
}

template <class S, class Visit>
void visit_intruder_fields(S& s, Visit&& visit) {
  visit("velocity", s.velocity);
  visit("speed_counts", s.speed_counts);
  visit("sampling_attempts", s.sampling_attempts);
  visit("velocity_y", s.velocity_y);
  visit("angular_velocity", s.angular_velocity);
  visit("angular_counts", s.angular_counts);
  visit("newton_iterations", s.newton_iterations);
  visit("bisection_fallbacks", s.bisection_fallbacks);
  visit("v2_time_integral", s.v2_time_integral);
  visit("w2_time_integral", s.w2_time_integral);
  visit("v2w2_time_integral", s.v2w2_time_integral);
}

template <class S, class Visit>
void visit_weighted_fields(S& s, Visit&& visit) {
  visit("particles", s.particles);
  visit("transfers", s.transfers);
  visit("controls", s.controls);
  visit("split_copies", s.split_copies);
  visit("reductions", s.reductions);
  visit("reduced", s.reduced);
  visit("conservation_residual", s.conservation_residual);
}

template <class S, class Visit>
void visit_replica_fields(S& s, Visit&& visit) {
  visit("temperature", s.temperature);
  visit("log_temperature", s.log_temperature);
  visit("species", s.species);
  visit("momentum", s.momentum);
  visit("momentum_relative", s.momentum_relative);
  visit("collisions", s.collisions);
  visit("pair_collisions", s.pair_collisions);
  visit("histogram_samples", s.histogram_samples);
  visit("candidates", s.candidates);
  visit("majorant_updates", s.majorant_updates);
  visit("majorant_violations", s.majorant_violations);
  visit("majorant_growth", s.majorant_growth);
  visit("rescales", s.rescales);
  visit("momentum_removed_relative", s.momentum_removed_relative);
  visit("energy_residual", s.energy_residual);
  visit("shear", s.shear);
  visit("intruder", s.intruder);
  visit("weighted", s.weighted);
}

#if defined(__GLIBCXX__) && defined(__x86_64__) && !defined(_GLIBCXX_DEBUG)
// Tripwire: a field added to these structs must be added to the lists above (and to the round trip in
// tests/test_mpi.cpp); then update the sizes.
static_assert(sizeof(SpeciesSeries) == 192, "SpeciesSeries changed: add the new field to visit_species_fields");
static_assert(sizeof(ShearSeries) == 72, "ShearSeries changed: add the new field to visit_shear_fields");
static_assert(sizeof(IntruderSeries) == 168, "IntruderSeries changed: add the new field to visit_intruder_fields");
static_assert(sizeof(WeightedSeries) == 72, "WeightedSeries changed: add the new field to visit_weighted_fields");
static_assert(sizeof(ReplicaSeries) == 592, "ReplicaSeries changed: add the new field to visit_replica_fields");
#endif

/// The time-stepped scheme's concurrent collision rounds (schemes/concurrent_rounds.hpp), summed over replicas:
/// how the threads inside a replica went, which depends on the thread count (the results do not).
struct CollisionRoundCounts {
  std::uint64_t rounds = 0;    // rounds run on several threads
  std::uint64_t deferred = 0;  // candidates deferred to the round's end and replayed in order
  std::uint64_t in_order = 0;  // rounds run again in order on one thread after a majorant raise
};

struct RunResult {
  std::vector<double> times;  // sample times
  std::vector<std::string> species_names;
  std::vector<ReplicaSeries> replicas;  // in replica order
  int threads = 1;                      // OpenMP threads (of rank 0 over MPI)
  int threads_per_replica = 1;          // of those, each replica's own (share_threads)
  int ranks = 1;                        // MPI ranks the replicas were spread over (1 without MPI)
  CollisionRoundCounts rounds;          // threads inside replicas (threads_per_replica > 1)
};

}  // namespace granmc
