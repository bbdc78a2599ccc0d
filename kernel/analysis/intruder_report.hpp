#pragma once
// The report of a Gillespie intruder run (002): T/T_B over the stationary half, the speed distribution, and
// for the needle (002 sec. 3.2) the rotational temperature, the correlation R (002 eq. 34) and the
// angular-velocity distribution.
#include <cstdint>
#include <optional>
#include <vector>

#include "kernel/analysis/series_statistics.hpp"
#include "kernel/core/scene.hpp"
#include "kernel/observe/gas_series.hpp"

namespace granmc {

/// The 2D needle (002 sec. 3.2), over the last half of the samples.
struct NeedleReport {
  MeanCI rotational_temperature_ratio;  // T_rot/T_B, T_rot = I <omega^2>
  MeanCI correlation;                   // R = <v^2 w^2> / (<v^2> <w^2>) (002 eq. 34), per replica
  // The same two with the exact time averages over the window of the samples (v1, omega constant between
  // events); absent when the window is empty (one sample) or the intruder never moved in it.
  std::optional<MeanCI> rotational_temperature_ratio_time_average;
  std::optional<MeanCI> correlation_time_average;
  std::vector<double> angular_shell_edges;  // |omega| shells (1/time)
  MeanCISeries angular_distribution;        // density of |omega| per unit angular speed
  std::uint64_t newton_iterations = 0;      // all replicas (002 eq. 28)
  std::uint64_t bisection_fallbacks = 0;    // bisection steps taken instead of Newton steps
};

struct IntruderReport {
  double bath_temperature = 0.0;  // T_B = m <v^2> of the bath (m = 1)
  MeanCI temperature_ratio;       // T/T_B, T = M <v1^2> per degree of freedom (the needle's
                                  // translational temperature), over the last half of the samples
  std::optional<MeanCI> temperature_ratio_time_average;  // Gillespie intruder and needle: T/T_B with <|v1|^2>
                                                         // the exact time average over the same window
  std::optional<double> temperature_ratio_exact;         // 002 eq. (22), or alpha for the power law with M = alpha
  std::vector<double> speed_shell_edges;                 // |v1| shells (velocity units)
  MeanCISeries speed_distribution;                       // density of |v1| per unit speed (twice that of v1)
  std::uint64_t events = 0;                              // collisions, all replicas
  std::optional<NeedleReport> needle;                    // dimension 2
};

/// The report of an intruder scene's run (precondition: every replica has an IntruderSeries).
IntruderReport intruder_report(const Scene& scene, const RunResult& result);

}  // namespace granmc
