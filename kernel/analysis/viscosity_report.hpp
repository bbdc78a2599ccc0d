#pragma once
// The report of a uniform shear flow run (000 secs. 2-3, 003): the reduced pressure tensor, the shear
// viscosity over the stationary window and the Navier-Stokes plateau test.
#include <optional>

#include "kernel/analysis/series_statistics.hpp"
#include "kernel/core/scene.hpp"
#include "kernel/observe/gas_series.hpp"

namespace granmc {

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
  double window_start = 0.0;  // first sample time of the window
  MeanCI eta;                 // eta* over the window
  MeanCI eta_kinetic;         // eta^k* over the window
  /// One species: eta / eta0 and eta^k / eta0, eta0 = (5/16 sigma^2) sqrt(m T / pi) (003), so eta / eta0 =
  /// eta* 16 / (5 sqrt 2); disks: eta0 = (1 / (2 sigma)) sqrt(m T / pi) and eta / eta0 = eta* 2 sqrt 2
  /// (theory/viscosity.hpp).
  std::optional<MeanCI> eta_over_eta0;
  std::optional<MeanCI> eta_kinetic_over_eta0;
  double reduced_shear_rate_min = 0.0;  // a* range over the window (replica means)
  double reduced_shear_rate_max = 0.0;
  MeanCI eta_scene_units;          // eta = eta* n T / nu at the final mixture temperature (replica mean):
  MeanCI eta_kinetic_scene_units;  // -P_xy / a in scene units, long-time value (the summary's "eta",
                                   // docs/formats/output-format.md)
  MeanCI drift;                    // eta* over the second half of the window minus over the first half
  bool steady = false;             // |drift| within its confidence half-width: the Navier-Stokes plateau
};

/// The report of a shear run (precondition: every replica has its pressure tensors and a*).
ViscosityReport viscosity_report(const Scene& scene, const RunResult& result);

}  // namespace granmc
