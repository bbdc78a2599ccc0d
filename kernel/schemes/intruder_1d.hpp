#pragma once
// The Gillespie algorithm for a point intruder of mass M in a bath of point particles of mass m = 1 on a
// line (002 sec. 3.1), one replica. Between collisions the intruder's velocity v1 is constant, so the
// collision rate phi(v1) = phi_+(v1) + phi_-(v1) (002 eq. 7) is too:
//   1. waiting time dt = -ln(xi_1) / phi(v1) (002 eq. 10); observations that fall inside it see v1;
//   2. side: right with probability phi_+ / phi (002 eq. 11);
//   3. the bath particle's velocity from g_+ or g_- (002 eqs. 14, 17), sampled exactly by the bath law
//      (collide/bath_*.hpp; g_-(v; v1) = g_+(-v; -v1) by symmetry of the bath);
//   4. v1 -> v1 + (1 + alpha) / (1 + M) (v - v1) (002 eq. 21).
// Random numbers: event e uses block (intruder_event, e, 0) for xi_1, xi_2 and blocks 1, 2, ... for the
// rejection attempts of step 3.
#include <cmath>
#include <cstdint>
#include <vector>

#include "kernel/core/philox_stream.hpp"
#include "kernel/core/sampling.hpp"
#include "kernel/core/scene.hpp"
#include "kernel/observe/gas_series.hpp"
#include "kernel/schemes/run_options.hpp"

namespace granmc {

template <class Bath>
ReplicaSeries run_intruder_1d(const Scene& scene, std::uint64_t replica, const std::vector<double>& times,
                              const RunOptions& options, const Bath& bath) {
  const IntruderConfig& in = *scene.intruder;
  const RandomStream rng(scene.run.seed, replica);
  const double kick = (1.0 + in.restitution) / (1.0 + in.mass);  // 002 eq. (21), m = 1
  const double radius = scene.histogram.radius;
  const std::size_t shells = static_cast<std::size_t>(scene.histogram.shells);
  const std::size_t first_stationary = first_stationary_sample(times.size());

  ReplicaSeries series;
  IntruderSeries record;
  record.speed_counts.assign(shells, 0.0);
  // Start from a Maxwellian at the scene's initial temperature: v1 ~ N(0, T(0) / M).
  const RandomBlock start = rng.block(RngPurpose::initial_velocity, 0, 0, 0);
  double z, unused;
  standard_normal_pair(uniform_open(start[0]), uniform_open(start[1]), z, unused);
  double v1 = z * std::sqrt(scene.initial_temperature / in.mass);

  double t = 0.0;
  std::uint64_t event = 0;
  std::size_t k = 0;
  auto observe = [&] {
    const double temperature = in.mass * v1 * v1;
    series.temperature.push_back(temperature);
    series.log_temperature.push_back(std::log(temperature));
    series.collisions.push_back(static_cast<double>(event));
    record.velocity.push_back(v1);
    if (k >= first_stationary) {
      const double shell = std::fabs(v1) / radius * static_cast<double>(shells);
      if (shell < static_cast<double>(shells)) record.speed_counts[static_cast<std::size_t>(shell)] += 1.0;
      ++series.histogram_samples;
    }
    if (options.on_sample) options.on_sample();
    ++k;
  };
  while (k < times.size()) {
    const double flux_plus = bath.flux_right(v1), flux_minus = bath.flux_right(-v1);
    const double flux = flux_plus + flux_minus;  // 002 eq. (7)
    const RandomBlock draw = rng.block(RngPurpose::intruder_event, 0, event, 0);
    const double next = t - std::log(uniform_open(draw[0])) / flux;  // 002 eq. (10)
    while (k < times.size() && times[k] <= next) observe();
    if (k == times.size()) break;
    t = next;
    const bool right = uniform_open(draw[1]) * flux < flux_plus;  // 002 eq. (11)
    double v = 0.0;
    for (std::uint64_t attempt = 1;; ++attempt) {
      ++record.sampling_attempts;
      const RandomBlock u = rng.block(RngPurpose::intruder_event, 0, event, attempt);
      if (right ? bath.try_sample_right(v1, u, v) : bath.try_sample_right(-v1, u, v)) break;
    }
    if (!right) v = -v;       // g_-(v; v1) = g_+(-v; -v1)
    v1 += kick * (v - v1);    // 002 eq. (21)
    ++event;
  }
  series.candidates = record.sampling_attempts;
  series.intruder = std::move(record);
  return series;
}

}  // namespace granmc
