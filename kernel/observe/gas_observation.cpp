#include "kernel/observe/gas_observation.hpp"

#include <cmath>

#include "kernel/observe/speed_histogram.hpp"

namespace granmc {

template <class Real>
std::vector<SpeciesMoments> gas_moments(const BasicGasState<Real>& state, const Vec3& centre) {
  std::vector<SpeciesMoments> m;
  for (const BasicSpeciesStore<Real>& s : state.species) m.push_back(species_moments(s, centre));
  return m;
}

GasTotals gas_totals(const Scene& scene, const std::vector<SpeciesMoments>& moments) noexcept {
  GasTotals t;
  for (std::size_t i = 0; i < moments.size(); ++i) {
    const double m = scene.species[i].mass;
    t.mass += m * static_cast<double>(moments[i].particles);
    t.twice_energy += m * moments[i].sum_c2;
    t.momentum += m * moments[i].sum_c;
  }
  return t;
}

Observed record_observation(const Scene& scene, const VelocityScale& scale,
                            const std::vector<SpeciesMoments>& about_origin,
                            const std::vector<SpeciesMoments>& about_flow, ReplicaSeries& series) {
  const double n = total_density(scene);
  const GasTotals totals = gas_totals(scene, about_origin);
  const std::vector<SpeciesMoments>& moments = about_flow;
  const int d = scene.run.dimension;
  double theta_mix = 0.0;  // sum_i x_i m_i <c^2> / d, the mixture temperature in stored units
  for (std::size_t i = 0; i < moments.size(); ++i) {
    const SpeciesConfig& sp = scene.species[i];
    const double theta = sp.mass * moments[i].mean_c2() / d;
    const double log_t = scale.log_temperature(theta);
    SpeciesSeries& s = series.species[i];
    s.temperature.push_back(std::exp(log_t));
    s.log_temperature.push_back(log_t);
    s.a2.push_back(moments[i].a2(d));
    s.a3.push_back(moments[i].a3(d));
    theta_mix += sp.density / n * theta;
  }
  const double log_t = scale.log_temperature(theta_mix);
  series.temperature.push_back(std::exp(log_t));
  series.log_temperature.push_back(log_t);
  series.momentum.push_back(scale.u() * totals.momentum);
  series.momentum_relative.push_back(norm(totals.momentum) / std::sqrt(totals.mass * totals.twice_energy));
  return {totals, theta_mix};
}

void record_spin_observation(const Scene& scene, const VelocityScale& scale, std::size_t i, const SpinMoments& m,
                             double mean_c2, SpeciesSeries& s) {
  const int d_r = scene.run.dimension == 3 ? 3 : 1;  // rotational degrees of freedom
  const double theta = scene.collision.reduced_inertia * scene.species[i].mass * m.mean_s2() / d_r;
  s.rotational_temperature.push_back(std::exp(scale.log_temperature(theta)));
  s.a02.push_back(m.a02(d_r));
  s.a11.push_back(m.a11(mean_c2));
}

template <class Real>
GasTotals observe_gas(const Scene& scene, const BasicGasState<Real>& state, ReplicaSeries& series, bool histogram) {
  // Temperatures and cumulants are of the peculiar velocity, about the mixture's flow velocity: zero to
  // rounding where collisions conserve momentum, but not under white noise (001 eq. 13, Remark 1).
  const std::vector<SpeciesMoments> about_origin = gas_moments(state);
  const GasTotals totals = gas_totals(scene, about_origin);
  const Vec3 flow = (1.0 / totals.mass) * totals.momentum;
  const std::vector<SpeciesMoments> about_flow = gas_moments(state, flow);
  const Observed o = record_observation(scene, state.scale, about_origin, about_flow, series);
  for (std::size_t i = 0; i < state.species.size(); ++i)
    if (state.species[i].has_spins())
      record_spin_observation(scene, state.scale, i, spin_moments(state.species[i], flow), about_flow[i].mean_c2(),
                              series.species[i]);
  if (histogram) {
    const double unit = histogram_speed_unit(scene, state.scale, o.theta_mixture);
    for (std::size_t i = 0; i < state.species.size(); ++i) {
      std::vector<double>& counts = series.species[i].speed_counts;
      counts.resize(static_cast<std::size_t>(scene.histogram.shells), 0.0);
      add_speeds(state.species[i], unit, scene.histogram.radius, counts);
    }
    ++series.histogram_samples;
  }
  return o.totals;
}

template std::vector<SpeciesMoments> gas_moments(const GasState&, const Vec3&);
template std::vector<SpeciesMoments> gas_moments(const FloatGasState&, const Vec3&);
template GasTotals observe_gas(const Scene&, const GasState&, ReplicaSeries&, bool);
template GasTotals observe_gas(const Scene&, const FloatGasState&, ReplicaSeries&, bool);

}  // namespace granmc
