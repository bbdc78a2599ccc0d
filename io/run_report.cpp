#include "io/run_report.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "kernel/observe/compensated_sum.hpp"
#include "kernel/observe/pressure_tensor.hpp"
#include "kernel/theory/intruder.hpp"

namespace granmc {
namespace {

void require_length(std::size_t got, std::size_t want, const char* what, std::size_t replica) {
  if (got != want)
    throw std::invalid_argument("run result: replica " + std::to_string(replica) + " has " + std::to_string(got) +
                                " values of " + what + ", expected " + std::to_string(want));
}

void check_shapes(const RunResult& result) {
  const std::size_t samples = result.times.size();
  const std::size_t species = result.species_names.size();
  if (result.replicas.empty()) throw std::invalid_argument("run result: no replicas");
  for (std::size_t r = 0; r < result.replicas.size(); ++r) {
    const ReplicaSeries& s = result.replicas[r];
    require_length(s.temperature.size(), samples, "temperature", r);
    require_length(s.log_temperature.size(), samples, "log_temperature", r);
    if (s.intruder) {
      require_length(s.intruder->velocity.size(), samples, "intruder velocity", r);
      if (!s.intruder->velocity_y.empty() || !s.intruder->angular_velocity.empty()) {  // the needle
        require_length(s.intruder->velocity_y.size(), samples, "needle velocity_y", r);
        require_length(s.intruder->angular_velocity.size(), samples, "needle angular_velocity", r);
      }
    } else {
      require_length(s.momentum.size(), samples, "momentum", r);
      require_length(s.momentum_relative.size(), samples, "momentum_relative", r);
      if (!s.pressure_kinetic.empty() || !result.replicas.front().pressure_kinetic.empty()) {  // shear
        require_length(s.pressure_kinetic.size(), samples, "pressure_kinetic", r);
        require_length(s.pressure_collisional.size(), samples, "pressure_collisional", r);
        require_length(s.reduced_shear_rate.size(), samples, "reduced_shear_rate", r);
      }
    }
    require_length(s.collisions.size(), samples, "collisions", r);
    require_length(s.species.size(), species, "species", r);
    for (const SpeciesSeries& sp : s.species) {
      require_length(sp.temperature.size(), samples, "species temperature", r);
      require_length(sp.log_temperature.size(), samples, "species log_temperature", r);
      require_length(sp.a2.size(), samples, "species a2", r);
      require_length(sp.a3.size(), samples, "species a3", r);
    }
  }
}

/// Replica mean and CI at each index k < n of the series pick(r) of replica r.
template <class Pick>
MeanCISeries per_index(std::size_t replicas, std::size_t n, Pick pick) {
  MeanCISeries out;
  std::vector<double> values(replicas);
  for (std::size_t k = 0; k < n; ++k) {
    for (std::size_t r = 0; r < replicas; ++r) values[r] = pick(r)[k];
    const MeanCI m = replica_mean(values);
    out.mean.push_back(m.mean);
    out.ci.push_back(m.ci);
  }
  return out;
}

/// Replica mean and CI at each sample time.
template <class Pick>
MeanCISeries per_time(const RunResult& result, Pick pick) {
  return per_index(
      result.replicas.size(),
      result.times.size(), [&](std::size_t r) -> const auto& { return pick(result.replicas[r]); });
}

/// Phi_i(v*) = counts / (N_i samples shell volume) for every replica: the scaled speed distribution,
/// normalised so that its integral over d^3 v* is the fraction of particles inside the radius.
std::vector<std::vector<double>> speed_distributions(const RunResult& result, std::size_t i,
                                                     const std::vector<double>& edges, double particles) {
  std::vector<std::vector<double>> phi;
  for (const ReplicaSeries& s : result.replicas) {
    const std::vector<double>& counts = s.species[i].speed_counts;
    std::vector<double> p(counts.size());
    for (std::size_t k = 0; k < counts.size(); ++k) {
      const double volume = 4.0 * std::numbers::pi / 3.0 * (std::pow(edges[k + 1], 3) - std::pow(edges[k], 3));
      p[k] = counts[k] / (particles * static_cast<double>(s.histogram_samples) * volume);
    }
    phi.push_back(std::move(p));
  }
  return phi;
}

/// value(series, k) averaged over the samples k >= (S-1)/2 in each replica (the last half of the run,
/// where a heated or scaled cooling state is stationary), then over replicas.
template <class Value>
MeanCI last_half_average(const RunResult& result, Value value) {
  const std::size_t samples = result.times.size();
  const std::size_t first = first_stationary_sample(samples);
  std::vector<double> per_replica;
  for (const ReplicaSeries& s : result.replicas) {
    CompensatedSum sum;
    for (std::size_t k = first; k < samples; ++k) sum.add(value(s, k));
    per_replica.push_back(sum.value() / static_cast<double>(samples - first));
  }
  return replica_mean(per_replica);
}

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
  const std::size_t shells = result.replicas.front().intruder->angular_counts.size();
  const double width = scene.histogram.radius / static_cast<double>(shells);
  for (std::size_t k = 0; k <= shells; ++k) out.angular_shell_edges.push_back(width * static_cast<double>(k));
  out.angular_distribution = count_density(
      result, width, [](const ReplicaSeries& s) -> const std::vector<double>& { return s.intruder->angular_counts; });
  return out;
}

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
  const std::size_t shells = result.replicas.front().intruder->speed_counts.size();
  const double width = scene.histogram.radius / static_cast<double>(shells);
  for (std::size_t k = 0; k <= shells; ++k) out.speed_shell_edges.push_back(width * static_cast<double>(k));
  out.speed_distribution = count_density(
      result, width, [](const ReplicaSeries& s) -> const std::vector<double>& { return s.intruder->speed_counts; });
  for (const ReplicaSeries& s : result.replicas)
    out.events += static_cast<std::uint64_t>(std::llround(s.collisions.back()));
  return out;
}

}  // namespace

/// The mean of row[k] over first <= k < last.
double range_mean(const std::vector<double>& row, std::size_t first, std::size_t last) {
  CompensatedSum sum;
  for (std::size_t k = first; k < last; ++k) sum.add(row[k]);
  return sum.value() / static_cast<double>(last - first);
}

/// Per replica r the mean of rows[r][k] over first <= k < last, then the replica mean.
MeanCI window_mean(const std::vector<std::vector<double>>& rows, std::size_t first, std::size_t last) {
  std::vector<double> per_replica;
  for (const std::vector<double>& row : rows) per_replica.push_back(range_mean(row, first, last));
  return replica_mean(per_replica);
}

ViscosityReport viscosity_report(const Scene& scene, const RunResult& result) {
  ViscosityReport out;
  const std::size_t samples = result.times.size();
  // eta*(t_k) = -(P^k_xy + P^c_xy) / (n T a*): P^k at t_k, P^c averaged over (t_{k-1}, t_k].
  std::vector<std::vector<double>> p_xy, pk_xy, eta, eta_k;
  for (const ReplicaSeries& s : result.replicas) {
    std::vector<double> p(samples), pk(samples), e(samples), ek(samples);
    for (std::size_t k = 0; k < samples; ++k) {
      pk[k] = s.pressure_kinetic[k].xy;
      p[k] = pk[k] + s.pressure_collisional[k].xy;
      const double a_star = s.reduced_shear_rate[k];
      e[k] = k == 0 ? std::nan("") : -p[k] / a_star;  // no collisional average at t = 0
      ek[k] = -pk[k] / a_star;
    }
    p_xy.push_back(std::move(p));
    pk_xy.push_back(std::move(pk));
    eta.push_back(std::move(e));
    eta_k.push_back(std::move(ek));
  }
  const std::size_t replicas = result.replicas.size();
  auto rows = [&](const std::vector<std::vector<double>>& v) {
    return per_index(
        replicas, samples, [&](std::size_t r) -> const auto& { return v[r]; });
  };
  out.reduced_shear_rate = per_time(
      result, [](const ReplicaSeries& s) -> const auto& { return s.reduced_shear_rate; });
  out.pressure_xy = rows(p_xy);
  out.pressure_kinetic_xy = rows(pk_xy);
  out.eta_star = rows(eta);
  out.eta_kinetic_star = rows(eta_k);

  const std::size_t first = std::max<std::size_t>(1, first_stationary_sample(samples));
  out.window_start = result.times[first];
  out.eta = window_mean(eta, first, samples);
  out.eta_kinetic = window_mean(eta_k, first, samples);
  if (scene.species.size() == 1) {
    const double to_eta0 = 16.0 / (5.0 * std::sqrt(2.0));  // eta / eta0 = eta* 16 / (5 sqrt 2) (theory/viscosity.hpp)
    out.eta_over_eta0 = MeanCI{to_eta0 * out.eta.mean, to_eta0 * out.eta.ci};
    out.eta_kinetic_over_eta0 = MeanCI{to_eta0 * out.eta_kinetic.mean, to_eta0 * out.eta_kinetic.ci};
  }
  const double t_final = per_time(
                             result, [](const ReplicaSeries& s) -> const auto& { return s.temperature; })
                             .mean.back();
  const double to_scene = total_density(scene) * t_final / effective_collision_frequency(scene, t_final);
  out.eta_scene_units = MeanCI{to_scene * out.eta.mean, to_scene * out.eta.ci};
  out.eta_kinetic_scene_units = MeanCI{to_scene * out.eta_kinetic.mean, to_scene * out.eta_kinetic.ci};
  out.reduced_shear_rate_min = out.reduced_shear_rate_max = out.reduced_shear_rate.mean[first];
  for (std::size_t k = first; k < samples; ++k) {
    out.reduced_shear_rate_min = std::min(out.reduced_shear_rate_min, out.reduced_shear_rate.mean[k]);
    out.reduced_shear_rate_max = std::max(out.reduced_shear_rate_max, out.reduced_shear_rate.mean[k]);
  }
  // The plateau test: eta* over the second half of the window against the first half, per replica.
  const std::size_t middle = first + (samples - first) / 2;
  if (middle > first && samples > middle) {
    std::vector<double> drift;
    for (const std::vector<double>& row : eta)
      drift.push_back(range_mean(row, middle, samples) - range_mean(row, first, middle));
    out.drift = replica_mean(drift);
    out.steady = replicas > 1 && std::fabs(out.drift.mean) <= out.drift.ci;
  }
  return out;
}

RunReport make_run_report(const Scene& scene, const RunResult& result, double wall_seconds) {
  check_shapes(result);
  RunReport report;
  report.method = method_name(scene.run.method);
  report.wall_seconds = wall_seconds;
  report.temperature = per_time(
      result, [](const ReplicaSeries& s) -> const auto& { return s.temperature; });
  report.log_temperature = per_time(
      result, [](const ReplicaSeries& s) -> const auto& { return s.log_temperature; });
  if (!result.replicas.front().intruder)
    report.momentum_relative = per_time(
        result, [](const ReplicaSeries& s) -> const auto& { return s.momentum_relative; });
  for (std::size_t i = 0; i < result.species_names.size(); ++i) {
    SpeciesReport sp;
    sp.name = result.species_names[i];
    sp.temperature = per_time(
        result, [i](const ReplicaSeries& s) -> const auto& { return s.species[i].temperature; });
    sp.a2 = per_time(
        result, [i](const ReplicaSeries& s) -> const auto& { return s.species[i].a2; });
    sp.a2_last_half =
        last_half_average(result, [i](const ReplicaSeries& s, std::size_t k) { return s.species[i].a2[k]; });
    sp.a3 = per_time(
        result, [i](const ReplicaSeries& s) -> const auto& { return s.species[i].a3; });
    sp.a3_last_half =
        last_half_average(result, [i](const ReplicaSeries& s, std::size_t k) { return s.species[i].a3[k]; });
    const std::size_t shells = result.replicas.front().species[i].speed_counts.size();
    if (shells > 0 && i < scene.species.size()) {
      if (report.speed_shell_edges.empty())
        for (std::size_t k = 0; k <= shells; ++k)
          report.speed_shell_edges.push_back(scene.histogram.radius * static_cast<double>(k) / shells);
      const auto phi =
          speed_distributions(result, i, report.speed_shell_edges, static_cast<double>(scene.species[i].particles));
      sp.speed_distribution = per_index(
          phi.size(), shells, [&](std::size_t r) -> const auto& { return phi[r]; });
    }
    report.species.push_back(std::move(sp));
  }
  for (const ReplicaSeries& s : result.replicas) {
    if (!s.collisions.empty()) report.collisions += static_cast<std::uint64_t>(std::llround(s.collisions.back()));
    report.candidates += s.candidates;
    report.majorant_updates += s.majorant_updates;
    report.majorant_violations += s.majorant_violations;
    report.rescales += s.rescales;
    if (s.energy_residual) report.energy_residual = std::max(report.energy_residual.value_or(0.0), *s.energy_residual);
  }
  // T_1/T_2 as exp(ln T_1 - ln T_2), finite when both temperatures underflow in a long cooling run.
  if (result.species_names.size() == 2 && !result.times.empty())
    report.temperature_ratio = last_half_average(result, [](const ReplicaSeries& s, std::size_t k) {
      return std::exp(s.species[0].log_temperature[k] - s.species[1].log_temperature[k]);
    });
  report.theory = theory::cooling_state(scene, result.times);
  if (scene.intruder && result.replicas.front().intruder) report.intruder = intruder_report(scene, result);
  if (!result.replicas.front().pressure_kinetic.empty()) report.viscosity = viscosity_report(scene, result);
  return report;
}

}  // namespace granmc
