#include "kernel/analysis/run_report.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

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
      if (s.shear.has_value() != result.replicas.front().shear.has_value())
        throw std::invalid_argument("run result: replica " + std::to_string(r) + " differs from replica 0 in shear");
      if (s.shear) {
        require_length(s.shear->pressure_kinetic.size(), samples, "pressure_kinetic", r);
        require_length(s.shear->pressure_collisional.size(), samples, "pressure_collisional", r);
        require_length(s.shear->reduced_shear_rate.size(), samples, "reduced_shear_rate", r);
      }
    }
    require_length(s.collisions.size(), samples, "collisions", r);
    require_length(s.species.size(), species, "species", r);
    for (const SpeciesSeries& sp : s.species) {
      require_length(sp.temperature.size(), samples, "species temperature", r);
      require_length(sp.log_temperature.size(), samples, "species log_temperature", r);
      require_length(sp.a2.size(), samples, "species a2", r);
      require_length(sp.a3.size(), samples, "species a3", r);
      if (!sp.rotational_temperature.empty() || !s.species.front().rotational_temperature.empty()) {
        require_length(sp.rotational_temperature.size(), samples, "species rotational_temperature", r);
        require_length(sp.a02.size(), samples, "species a02", r);
        require_length(sp.a11.size(), samples, "species a11", r);
      }
    }
  }
}

/// Phi_i(v*) = counts / (N_i samples shell volume) for every replica: the scaled speed distribution,
/// normalised so that its integral over d^d v* is the fraction of particles inside the radius (shells of
/// volume 4 pi (b^3 - a^3) / 3 for spheres, annuli of area pi (b^2 - a^2) for disks).
std::vector<std::vector<double>> speed_distributions(const RunResult& result, std::size_t i,
                                                     const std::vector<double>& edges, double particles,
                                                     int dimension) {
  std::vector<std::vector<double>> phi;
  for (const ReplicaSeries& s : result.replicas) {
    const std::vector<double>& counts = s.species[i].speed_counts;
    std::vector<double> p(counts.size());
    for (std::size_t k = 0; k < counts.size(); ++k) {
      const double volume = dimension == 3
                                ? 4.0 * std::numbers::pi / 3.0 * (std::pow(edges[k + 1], 3) - std::pow(edges[k], 3))
                                : std::numbers::pi * (std::pow(edges[k + 1], 2) - std::pow(edges[k], 2));
      p[k] = counts[k] / (particles * static_cast<double>(s.histogram_samples) * volume);
    }
    phi.push_back(std::move(p));
  }
  return phi;
}

/// T + (sum_i x_i m_i) |V|^2 / d per replica and sample, V = P / M the flow velocity: the mixture's
/// sum_i x_i m_i <|v|^2> / d about the origin (the cross terms sum_i x_i m_i (<v>_i - V) vanish by V's
/// definition).
MeanCISeries uncentred_temperature(const Scene& scene, const RunResult& result) {
  double mass = 0.0, mean_mass = 0.0;  // M = sum_i m_i N_i; sum_i x_i m_i
  for (const SpeciesConfig& sp : scene.species) {
    mass += sp.mass * static_cast<double>(sp.particles);
    mean_mass += sp.density / total_density(scene) * sp.mass;
  }
  std::vector<std::vector<double>> t(result.replicas.size());
  for (std::size_t r = 0; r < t.size(); ++r) {
    const ReplicaSeries& s = result.replicas[r];
    for (std::size_t k = 0; k < s.temperature.size(); ++k)
      t[r].push_back(s.temperature[k] + mean_mass * norm2((1.0 / mass) * s.momentum[k]) / scene.run.dimension);
  }
  return per_index(
      t.size(), result.times.size(), [&](std::size_t r) -> const auto& { return t[r]; });
}

}  // namespace

RunReport make_run_report(const Scene& scene, const RunResult& result, double wall_seconds) {
  check_shapes(result);
  RunReport report;
  report.method = method_name(scene.run.method);
  report.wall_seconds = wall_seconds;
  report.temperature = per_time(
      result, [](const ReplicaSeries& s) -> const auto& { return s.temperature; });
  report.temperature_last_half =
      last_half_average(result, [](const ReplicaSeries& s, std::size_t k) { return s.temperature[k]; });
  report.log_temperature = per_time(
      result, [](const ReplicaSeries& s) -> const auto& { return s.log_temperature; });
  if (!result.replicas.front().intruder) {
    report.momentum_relative = per_time(
        result, [](const ReplicaSeries& s) -> const auto& { return s.momentum_relative; });
    report.temperature_uncentred = uncentred_temperature(scene, result);
  }
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
    if (!result.replicas.front().species[i].rotational_temperature.empty()) {  // rough particles
      sp.rotational_temperature = per_time(
          result, [i](const ReplicaSeries& s) -> const auto& { return s.species[i].rotational_temperature; });
      sp.rotational_ratio = last_half_average(result, [i](const ReplicaSeries& s, std::size_t k) {
        return s.species[i].rotational_temperature[k] / s.species[i].temperature[k];
      });
      sp.a02 = per_time(
          result, [i](const ReplicaSeries& s) -> const auto& { return s.species[i].a02; });
      sp.a02_last_half =
          last_half_average(result, [i](const ReplicaSeries& s, std::size_t k) { return s.species[i].a02[k]; });
      sp.a11 = per_time(
          result, [i](const ReplicaSeries& s) -> const auto& { return s.species[i].a11; });
      sp.a11_last_half =
          last_half_average(result, [i](const ReplicaSeries& s, std::size_t k) { return s.species[i].a11[k]; });
    }
    const std::size_t shells = result.replicas.front().species[i].speed_counts.size();
    if (shells > 0 && i < scene.species.size()) {
      if (report.speed_shell_edges.empty())
        for (std::size_t k = 0; k <= shells; ++k)
          report.speed_shell_edges.push_back(scene.histogram.radius * static_cast<double>(k) / shells);
      const auto phi = speed_distributions(result, i, report.speed_shell_edges,
                                           static_cast<double>(scene.species[i].particles), scene.run.dimension);
      sp.speed_distribution = per_index(
          phi.size(), shells, [&](std::size_t r) -> const auto& { return phi[r]; });
      if (scene.species.size() == 1) {  // the tail exponent of one species' f (001 eqs. 19-21, 38)
        report.tail = fit_tail(report.speed_shell_edges, phi);
        report.tail_profile = tail_exponent_profile(report.speed_shell_edges, phi);
      }
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
  if (result.replicas.front().shear) report.viscosity = viscosity_report(scene, result);
  return report;
}

}  // namespace granmc
