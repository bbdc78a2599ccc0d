#include "kernel/analysis/viscosity_report.hpp"

#include <algorithm>
#include <cmath>

#include "kernel/observe/pressure_tensor.hpp"

namespace granmc {

namespace {

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

}  // namespace

ViscosityReport viscosity_report(const Scene& scene, const RunResult& result) {
  ViscosityReport out;
  const std::size_t samples = result.times.size();
  // eta*(t_k) = -(P^k_xy + P^c_xy) / (n T a*): P^k at t_k, P^c averaged over (t_{k-1}, t_k].
  std::vector<std::vector<double>> p_xy, pk_xy, eta, eta_k;
  for (const ReplicaSeries& s : result.replicas) {
    std::vector<double> p(samples), pk(samples), e(samples), ek(samples);
    for (std::size_t k = 0; k < samples; ++k) {
      pk[k] = s.shear->pressure_kinetic[k].xy;
      p[k] = pk[k] + s.shear->pressure_collisional[k].xy;
      const double a_star = s.shear->reduced_shear_rate[k];
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
      result, [](const ReplicaSeries& s) -> const auto& { return s.shear->reduced_shear_rate; });
  out.pressure_xy = rows(p_xy);
  out.pressure_kinetic_xy = rows(pk_xy);
  out.eta_star = rows(eta);
  out.eta_kinetic_star = rows(eta_k);

  const std::size_t first = std::max<std::size_t>(1, first_stationary_sample(samples));
  out.window_start = result.times[first];
  out.eta = window_mean(eta, first, samples);
  out.eta_kinetic = window_mean(eta_k, first, samples);
  if (scene.species.size() == 1) {
    // eta / eta0 = eta* 16 / ((d + 2) sqrt 2) (theory/viscosity.hpp, reduced_viscosity_one_species)
    const double to_eta0 = 16.0 / ((scene.run.dimension + 2) * std::sqrt(2.0));
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

}  // namespace granmc
