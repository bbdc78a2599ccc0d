#pragma once
// RunReport: the statistics of a finished run over its replicas, computed once and shared by the HDF5 file
// and the JSON summary (io/output_schema.hpp), so both outputs say the same numbers. Every mean comes with its
// confidence half-width ci = lambda_p sqrt(Var / R) (001 eq. 31, lambda_p = 3.2,
// analysis/replica_statistics.hpp) over the R replicas.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "kernel/analysis/intruder_report.hpp"
#include "kernel/analysis/series_statistics.hpp"
#include "kernel/analysis/tail_fit.hpp"
#include "kernel/analysis/viscosity_report.hpp"
#include "kernel/core/scene.hpp"
#include "kernel/observe/gas_series.hpp"
#include "kernel/theory/scene_theory.hpp"

namespace granmc {

struct SpeciesReport {
  std::string name;
  MeanCISeries temperature;  // T_i(t) = m_i <V^2> / 3, energy units
  MeanCISeries a2;           // (3/5) <V^4>/<V^2>^2 - 1, dimensionless
  MeanCI a2_last_half;       // a2 over the last half of the samples (as temperature_ratio)
  MeanCISeries a3;           // 1 + 3 a2 - (9/35) <V^6>/<V^2>^3, dimensionless
  MeanCI a3_last_half;
  MeanCISeries speed_distribution;  // Phi_i(v*) per speed shell over the last half (000 eq. 19), per d^3 v*
  // Rough particles only (empty otherwise):
  MeanCISeries rotational_temperature;     // T_rot,i(t) = I_i <omega^2> / d_r, energy units
  std::optional<MeanCI> rotational_ratio;  // theta = T_rot,i / T_i over the last half (as temperature_ratio)
  MeanCISeries a02;                        // d_r/(d_r+2) <omega^4>/<omega^2>^2 - 1
  std::optional<MeanCI> a02_last_half;
  MeanCISeries a11;  // <V^2 omega^2> / (<V^2> <omega^2>) - 1
  std::optional<MeanCI> a11_last_half;
};

struct RunReport {
  std::string method;                     // "dsmc" | "event" | "gillespie", as spelled in scene files
  double wall_seconds = 0.0;              // wall-clock time of the run, s
  MeanCISeries temperature;               // mixture T(t) = sum_i x_i T_i, energy units
  MeanCI temperature_last_half;           // T over the last half of the samples (as temperature_ratio): a steady T
  MeanCISeries log_temperature;           // <ln T>(t) over replicas (finite where T underflows)
  MeanCISeries temperature_uncentred;     // T + (sum_i x_i m_i) |V|^2 / 3, V = P / M: without removing the
                                          // bulk velocity, 001's T = (1/3) int |v|^2 f (eq. 35); gas only
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

  /// One species with a speed histogram: the tail exponent b of f ~ v^gamma exp(-a v^b) where the density is
  /// below 10^-3 of its maximum, out to the last shell every replica has weight in (analysis/tail_fit.hpp),
  /// and b against the window's inner edge.
  std::optional<TailWindow> tail;
  std::vector<TailWindow> tail_profile;

  std::optional<IntruderReport> intruder;    // method "gillespie"
  std::optional<ViscosityReport> viscosity;  // shear runs
};

/// Computes the report of `result`. Throws std::invalid_argument if `result` is not consistent (no
/// replicas, or a series whose length differs from the number of sample times or species).
RunReport make_run_report(const Scene& scene, const RunResult& result, double wall_seconds);

}  // namespace granmc
