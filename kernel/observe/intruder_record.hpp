#pragma once
// What an intruder replica records at the sample times, shared by the Gillespie and DSMC schemes of the
// 1D intruder (schemes/intruder_1d.hpp, intruder_dsmc_1d.hpp) and, for the shells, the needle.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "kernel/core/philox_stream.hpp"
#include "kernel/core/sampling.hpp"
#include "kernel/core/scene.hpp"
#include "kernel/observe/gas_series.hpp"

namespace granmc {

/// Adds |value| to equal-width shells from 0 to `radius` (values at or beyond the radius are not counted).
inline void add_to_shells(std::vector<double>& counts, double value, double radius) noexcept {
  const double shell = std::fabs(value) / radius * static_cast<double>(counts.size());
  if (shell < static_cast<double>(counts.size())) counts[static_cast<std::size_t>(shell)] += 1.0;
}

/// The length of [from, to) inside `window`, 0 if none.
inline double time_inside(double from, double to, const std::pair<double, double>& window) noexcept {
  return std::max(0.0, std::min(to, window.second) - std::max(from, window.first));
}

/// The 1D intruder's start: a Maxwellian at the scene's initial temperature, v1 ~ N(0, T(0) / M), from
/// block (initial_velocity, 0, 0, 0).
inline double initial_intruder_velocity(const Scene& scene, const RandomStream& rng) noexcept {
  const RandomBlock start = rng.block(RngPurpose::initial_velocity, 0, 0, 0);
  double z, unused;
  standard_normal_pair(uniform_open(start[0]), uniform_open(start[1]), z, unused);
  return z * std::sqrt(scene.initial_temperature / scene.intruder->mass);
}

/// The observations of a 1D intruder: T = M v1^2, ln T, the collisions so far, v1, and the |v1| histogram
/// over the stationary samples (gas_series.hpp, first_stationary_sample).
class IntruderRecord1D {
 public:
  IntruderRecord1D(const Scene& scene, std::size_t sample_times)
      : mass_(scene.intruder->mass),
        radius_(scene.histogram.radius),
        first_stationary_(first_stationary_sample(sample_times)) {
    record_.speed_counts.assign(static_cast<std::size_t>(scene.histogram.shells), 0.0);
  }

  /// Samples taken so far (the index of the next sample time).
  [[nodiscard]] std::size_t samples() const noexcept { return series_.temperature.size(); }
  /// Adds the integral of v1^2 dt over the part of [from, to) inside the stationary window [t_K/2, t_end]
  /// (`window`), v1 constant on [from, to).
  void add_stationary_v2(double v1, double from, double to, const std::pair<double, double>& window) noexcept {
    record_.v2_time_integral += v1 * v1 * time_inside(from, to, window);
  }
  /// Counts one draw of a bath velocity (accepted or not).
  void count_sampling_attempt() noexcept { ++record_.sampling_attempts; }

  void observe(double v1, std::uint64_t collisions) {
    const double temperature = mass_ * v1 * v1;
    if (samples() >= first_stationary_) {
      add_to_shells(record_.speed_counts, v1, radius_);
      ++series_.histogram_samples;
    }
    series_.temperature.push_back(temperature);
    series_.log_temperature.push_back(std::log(temperature));
    series_.collisions.push_back(static_cast<double>(collisions));
    record_.velocity.push_back(v1);
  }

  /// The replica's series, with `candidates` as its candidate count.
  ReplicaSeries finish(std::uint64_t candidates) {
    series_.candidates = candidates;
    series_.intruder = std::move(record_);
    return std::move(series_);
  }

  [[nodiscard]] std::uint64_t sampling_attempts() const noexcept { return record_.sampling_attempts; }

 private:
  double mass_;
  double radius_;
  std::size_t first_stationary_;
  ReplicaSeries series_;
  IntruderSeries record_;
};

}  // namespace granmc
