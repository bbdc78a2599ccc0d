#include "kernel/observe/pressure_tensor.hpp"

#include <cmath>
#include <numbers>

#include "kernel/observe/compensated_sum.hpp"
#include "kernel/observe/gas_observation.hpp"

namespace granmc {

template <class Real>
SymTensor reduced_kinetic_pressure(const Scene& scene, const BasicGasState<Real>& state) {
  // About the flow velocity (zero to rounding: collisions and the shear map conserve momentum).
  const GasTotals totals = gas_totals(scene, gas_moments(state));
  const Vec3 flow = (1.0 / totals.mass) * totals.momentum;
  CompensatedSum xx, yy, zz, xy, xz, yz;
  for (std::size_t i = 0; i < state.species.size(); ++i) {
    const double m = scene.species[i].mass;
    state.species[i].for_each_velocity([&](const Vec3& c) {
      const SymTensor d = weighted_dyad(m, c - flow);
      xx.add(d.xx);
      yy.add(d.yy);
      zz.add(d.zz);
      xy.add(d.xy);
      xz.add(d.xz);
      yz.add(d.yz);
    });
  }
  const SymTensor sum{xx.value(), yy.value(), zz.value(), xy.value(), xz.value(), yz.value()};
  return (3.0 / sum.trace()) * sum;
}

template SymTensor reduced_kinetic_pressure(const Scene&, const GasState&);
template SymTensor reduced_kinetic_pressure(const Scene&, const FloatGasState&);

double thermal_speed(const Scene& scene, double temperature) {
  const double m1 = scene.species.front().mass;
  if (scene.species.size() == 1) return std::sqrt(2.0 * temperature / m1);
  const double m2 = scene.species[1].mass;
  return std::sqrt(2.0 * temperature * (m1 + m2) / (m1 * m2));
}

double effective_collision_frequency(const Scene& scene, double temperature) {
  const double sigma_12 = 0.5 * (scene.species.front().diameter + scene.species.back().diameter);
  return std::sqrt(std::numbers::pi) * total_density(scene) * sigma_12 * sigma_12 * thermal_speed(scene, temperature);
}

}  // namespace granmc
