#include "kernel/observe/pressure_tensor.hpp"

#include <cmath>
#include <numbers>

#include "kernel/observe/compensated_sum.hpp"
#include "kernel/observe/gas_observation.hpp"
#include "kernel/observe/velocity_lanes.hpp"

namespace granmc {

template <class Real>
SymTensor reduced_kinetic_pressure(const Scene& scene, const BasicGasState<Real>& state) {
  // About the flow velocity (zero to rounding: collisions and the shear map conserve momentum).
  const GasTotals totals = gas_totals(scene, gas_moments(state));
  const Vec3 flow = (1.0 / totals.mass) * totals.momentum;
  LaneCompensatedSum xx, yy, zz, xy, xz, yz;  // lane by lane (docs/developer-guide/performance.md)
  const SimdDouble fx(flow.x), fy(flow.y), fz(flow.z);
  for (std::size_t i = 0; i < state.species.size(); ++i) {
    const double m = scene.species[i].mass;
    for_each_velocity_lanes(
        state.species[i], 0, state.species[i].size(),
        [&](const SimdDouble& x, const SimdDouble& y, const SimdDouble& z, const SimdDouble& in_range) {
          const SimdDouble w = m * in_range;  // the terms of weighted_dyad(m, c - flow)
          const SimdDouble dx = x - fx, dy = y - fy, dz = z - fz;
          const SimdDouble wx = w * dx, wy = w * dy, wz = w * dz;
          xx.add(wx * dx);
          yy.add(wy * dy);
          zz.add(wz * dz);
          xy.add(wx * dy);
          xz.add(wx * dz);
          yz.add(wy * dz);
        });
  }
  const SymTensor sum{xx.value(), yy.value(), zz.value(), xy.value(), xz.value(), yz.value()};
  return (scene.run.dimension / sum.trace()) * sum;
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
  if (scene.run.dimension == 2)  // sigma_12^(d-1) and half the prefactor (pressure_tensor.hpp)
    return 0.5 * std::sqrt(std::numbers::pi) * total_density(scene) * sigma_12 * thermal_speed(scene, temperature);
  return std::sqrt(std::numbers::pi) * total_density(scene) * sigma_12 * sigma_12 * thermal_speed(scene, temperature);
}

}  // namespace granmc
