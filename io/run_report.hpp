#pragma once
// RunReport: the statistics of a finished run over its replicas, computed once and shared by the HDF5
// file (io/hdf5_output) and the JSON summary (io/summary_json), so both outputs say the same numbers.
// Every mean comes with its confidence half-width ci = lambda_p sqrt(Var / R) (001 eq. 31, lambda_p = 3.2,
// kernel/observe/replica_statistics.hpp) over the R replicas.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "kernel/core/scene.hpp"
#include "kernel/observe/gas_series.hpp"
#include "kernel/observe/replica_statistics.hpp"
#include "kernel/theory/scene_theory.hpp"

namespace granmc {

/// A replica mean and its confidence half-width at each sample time (same length as RunResult::times).
struct MeanCISeries {
  std::vector<double> mean;
  std::vector<double> ci;

  [[nodiscard]] std::size_t size() const noexcept { return mean.size(); }
  [[nodiscard]] MeanCI at(std::size_t k) const { return {mean.at(k), ci.at(k)}; }
};

struct SpeciesReport {
  std::string name;
  MeanCISeries temperature;  // T_i(t) = m_i <V^2> / 3, energy units
  MeanCISeries a2;           // (3/5) <V^4>/<V^2>^2 - 1, dimensionless
  MeanCI a2_last_half;       // a2 over the last half of the samples (as temperature_ratio)
  MeanCISeries a3;           // 1 + 3 a2 - (9/35) <V^6>/<V^2>^3, dimensionless
  MeanCI a3_last_half;
  MeanCISeries speed_distribution;  // Phi_i(v*) per speed shell over the last half (000 eq. 19), per d^3 v*
};

/// A Gillespie intruder run (002).
/// The 2D needle (002 sec. 3.2), over the last half of the samples.
struct NeedleReport {
  MeanCI rotational_temperature_ratio;      // T_rot/T_B, T_rot = I <omega^2>
  MeanCI correlation;                       // R = <v^2 w^2> / (<v^2> <w^2>) (002 eq. 34), per replica
  std::vector<double> angular_shell_edges;  // |omega| shells (1/time)
  MeanCISeries angular_distribution;        // density of |omega| per unit angular speed
  std::uint64_t newton_iterations = 0;      // all replicas (002 eq. 28)
  std::uint64_t bisection_fallbacks = 0;    // bisection steps taken instead of Newton steps
};

struct IntruderReport {
  double bath_temperature = 0.0;                  // T_B = m <v^2> of the bath (m = 1)
  MeanCI temperature_ratio;                       // T/T_B, T = M <v1^2> per degree of freedom (the needle's
                                                  // translational temperature), over the last half of the samples
  std::optional<double> temperature_ratio_exact;  // 002 eq. (22), or alpha for the power law with M = alpha
  std::vector<double> speed_shell_edges;          // |v1| shells (velocity units)
  MeanCISeries speed_distribution;                // density of |v1| per unit speed (twice that of v1)
  std::uint64_t events = 0;                       // collisions, all replicas
  std::optional<NeedleReport> needle;             // dimension 2
};

/// A shear run (000 secs. 2-3, 003): the reduced pressure tensor and the shear viscosity eta = -P_xy / a
/// (000 eq. 11) in the reduced form eta* = nu eta / (n T) = -(P_xy / n T) / a* (000 Figs. 10-12).
struct ViscosityReport {
  MeanCISeries reduced_shear_rate;   // a* = a / nu at each sample
  MeanCISeries pressure_xy;          // P_xy / (n T), kinetic + collisional
  MeanCISeries pressure_kinetic_xy;  // P^k_xy / (n T)
  MeanCISeries eta_star;             // -P_xy / (n T a*) at each sample (undefined at t = 0: NaN)
  MeanCISeries eta_kinetic_star;     // -P^k_xy / (n T a*)
  /// Over the window (the last half of the samples, first_stationary_sample): per replica the time
  /// average, then the replica mean.
  double window_start = 0.0;                    // first sample time of the window
  MeanCI eta;                                   // eta* over the window
  MeanCI eta_kinetic;                           // eta^k* over the window
  std::optional<MeanCI> eta_over_eta0;          // one species: eta / eta0, eta0 = (5/16 sigma^2) sqrt(m T / pi)
  std::optional<MeanCI> eta_kinetic_over_eta0;  // (003), so eta / eta0 = eta* 16 / (5 sqrt 2)
  double reduced_shear_rate_min = 0.0;          // a* range over the window (replica means)
  double reduced_shear_rate_max = 0.0;
  MeanCI eta_scene_units;          // eta = eta* n T / nu at the final mixture temperature (replica mean):
  MeanCI eta_kinetic_scene_units;  // -P_xy / a in scene units, long-time value (SCENES.md "eta")
  MeanCI drift;                    // eta* over the second half of the window minus over the first half
  bool steady = false;             // |drift| within its confidence half-width: the Navier-Stokes plateau
};

struct RunReport {
  std::string method;                     // "dsmc" | "event" | "gillespie", as spelled in scene files
  double wall_seconds = 0.0;              // wall-clock time of the run, s
  MeanCISeries temperature;               // mixture T(t) = sum_i x_i T_i, energy units
  MeanCISeries log_temperature;           // <ln T>(t) over replicas (finite where T underflows)
  MeanCISeries momentum_relative;         // |P| / sqrt(M 2 E_kin), dimensionless; empty for an intruder
  std::vector<SpeciesReport> species;     // in scene order
  std::vector<double> speed_shell_edges;  // v* shell edges of the speed distributions (shells + 1 values)

  std::uint64_t collisions = 0;           // accepted collisions, summed over replicas (last sample)
  std::uint64_t candidates = 0;           // candidate pairs tested, all replicas
  std::uint64_t majorant_updates = 0;     // omega_max raises, all replicas
  std::uint64_t majorant_violations = 0;  // event scheme: candidates above their U_max, all replicas
  std::uint64_t rescales = 0;             // velocity rescalings, all replicas
  std::optional<double> energy_residual;  // largest ReplicaSeries::energy_residual over the replicas

  /// T_1/T_2 over the last half of the samples (k >= (S-1)/2 with S sample times): per replica the time
  /// average of T_1/T_2, then the replica mean. Only for two species.
  std::optional<MeanCI> temperature_ratio;

  /// Haff's law and the Sonine HCS a2 when the scene is a monodisperse hard-sphere cooling state.
  std::optional<theory::CoolingStatePrediction> theory;

  std::optional<IntruderReport> intruder;    // method "gillespie"
  std::optional<ViscosityReport> viscosity;  // shear runs
};

/// Computes the report of `result`. Throws std::invalid_argument if `result` is not consistent (no
/// replicas, or a series whose length differs from the number of sample times or species).
RunReport make_run_report(const Scene& scene, const RunResult& result, double wall_seconds);

}  // namespace granmc
