#include "kernel/analysis/intruder_report.hpp"

#include <cmath>

#include "kernel/theory/intruder.hpp"

namespace granmc {

namespace {

double speed2(const IntruderSeries& in, std::size_t k) {
  return in.velocity[k] * in.velocity[k] + in.velocity_y[k] * in.velocity_y[k];
}

/// Per shell, counts / (histogram samples x shell width) for each replica, then mean and CI.
MeanCISeries count_density(const RunResult& result, double width,
                           const std::vector<double>& (*counts)(const ReplicaSeries&)) {
  std::vector<std::vector<double>> density;
  for (const ReplicaSeries& s : result.replicas) {
    std::vector<double> d;
    for (double c : counts(s)) d.push_back(c / (static_cast<double>(s.histogram_samples) * width));
    density.push_back(std::move(d));
  }
  return per_index(
      density.size(), density.front().size(), [&](std::size_t r) -> const auto& { return density[r]; });
}

/// The length of the stationary window [t_K/2, t_end] of the samples.
double stationary_window_length(const RunResult& result) {
  const auto [from, to] = stationary_window(result.times);
  return to - from;
}

NeedleReport needle_report(const Scene& scene, const RunResult& result) {
  const IntruderConfig& in = *scene.intruder;
  const double inertia = needle_inertia(in);
  const double tb = theory::bath_temperature(in);
  NeedleReport out;
  out.rotational_temperature_ratio = last_half_average(result, [&](const ReplicaSeries& s, std::size_t k) {
    const double w = s.intruder->angular_velocity[k];
    return inertia * w * w / tb;
  });
  const std::size_t first = first_stationary_sample(result.times.size());
  std::vector<double> r;
  for (const ReplicaSeries& s : result.replicas) {
    CompensatedSum v2, w2, v2w2;
    for (std::size_t k = first; k < result.times.size(); ++k) {
      const double a = speed2(*s.intruder, k), w = s.intruder->angular_velocity[k];
      v2.add(a);
      w2.add(w * w);
      v2w2.add(a * w * w);
    }
    const double samples = static_cast<double>(result.times.size() - first);
    r.push_back(v2w2.value() * samples / (v2.value() * w2.value()));  // 002 eq. (34)
    out.newton_iterations += s.intruder->newton_iterations;
    out.bisection_fallbacks += s.intruder->bisection_fallbacks;
  }
  out.correlation = replica_mean(r);
  // The same from the exact time integrals (v1 and omega are constant between events).
  const double window = stationary_window_length(result);
  std::vector<double> rotational, correlation;
  for (const ReplicaSeries& s : result.replicas) {
    const IntruderSeries& i = *s.intruder;
    if (!(window > 0.0 && i.v2_time_integral > 0.0 && i.w2_time_integral > 0.0)) break;
    rotational.push_back(inertia * i.w2_time_integral / window / tb);
    correlation.push_back(i.v2w2_time_integral * window / (i.v2_time_integral * i.w2_time_integral));  // eq. (34)
  }
  if (rotational.size() == result.replicas.size()) {
    out.rotational_temperature_ratio_time_average = replica_mean(rotational);
    out.correlation_time_average = replica_mean(correlation);
  }
  const std::size_t shells = result.replicas.front().intruder->angular_counts.size();
  const double width = scene.histogram.radius / static_cast<double>(shells);
  for (std::size_t k = 0; k <= shells; ++k) out.angular_shell_edges.push_back(width * static_cast<double>(k));
  out.angular_distribution = count_density(
      result, width, [](const ReplicaSeries& s) -> const std::vector<double>& { return s.intruder->angular_counts; });
  return out;
}

}  // namespace

/// T/T_B over the last half, and the distribution of |v1| per unit speed over the same samples.
IntruderReport intruder_report(const Scene& scene, const RunResult& result) {
  IntruderReport out;
  out.bath_temperature = theory::bath_temperature(*scene.intruder);
  out.temperature_ratio_exact = theory::intruder_temperature_ratio(*scene.intruder);
  const double tb = out.bath_temperature;
  if (scene.intruder->dimension == 1) {
    out.temperature_ratio =
        last_half_average(result, [&](const ReplicaSeries& s, std::size_t k) { return s.temperature[k] / tb; });
  } else {
    out.temperature_ratio = last_half_average(result, [&](const ReplicaSeries& s, std::size_t k) {
      return 0.5 * scene.intruder->mass * speed2(*s.intruder, k) / tb;  // T_tr = M <|v1|^2> / 2
    });
    out.needle = needle_report(scene, result);
  }
  // The exact time average where the scheme kept it: M / (d (t_end - t_K/2)) int |v1|^2 dt, then over replicas.
  const double window = stationary_window_length(result);
  const double dof = scene.intruder->dimension == 1 ? 1.0 : 2.0;
  std::vector<double> ratio;
  for (const ReplicaSeries& s : result.replicas)
    if (s.intruder->v2_time_integral > 0.0 && window > 0.0)
      ratio.push_back(scene.intruder->mass * s.intruder->v2_time_integral / (dof * window) / tb);
  if (ratio.size() == result.replicas.size()) out.temperature_ratio_time_average = replica_mean(ratio);
  const std::size_t shells = result.replicas.front().intruder->speed_counts.size();
  const double width = scene.histogram.radius / static_cast<double>(shells);
  for (std::size_t k = 0; k <= shells; ++k) out.speed_shell_edges.push_back(width * static_cast<double>(k));
  out.speed_distribution = count_density(
      result, width, [](const ReplicaSeries& s) -> const std::vector<double>& { return s.intruder->speed_counts; });
  for (const ReplicaSeries& s : result.replicas)
    out.events += static_cast<std::uint64_t>(std::llround(s.collisions.back()));
  return out;
}

}  // namespace granmc
