#include "kernel/schemes/initial_state.hpp"

#include <cmath>

#include "kernel/core/sampling.hpp"
#include "kernel/observe/moments.hpp"

namespace granmc {

Vec3 maxwellian_velocity(const RandomStream& rng, std::uint16_t species, std::uint64_t k, double width) noexcept {
  const RandomBlock r = rng.block(RngPurpose::initial_velocity, species, 0, k);
  double z[4];
  standard_normal_pair(uniform_open(r[0]), uniform_open(r[1]), z[0], z[1]);
  standard_normal_pair(uniform_open(r[2]), uniform_open(r[3]), z[2], z[3]);
  return {width * z[0], width * z[1], width * z[2]};
}

template <class Real>
BasicGasState<Real> maxwellian_state(const Scene& scene, const RandomStream& rng) {
  BasicGasState<Real> state;
  state.scale.log_u = 0.5 * std::log(scene.initial_temperature);
  for (std::size_t i = 0; i < scene.species.size(); ++i) {
    const SpeciesConfig& sp = scene.species[i];
    BasicSpeciesStore<Real> store(static_cast<std::size_t>(sp.particles));
    const double width = 1.0 / std::sqrt(sp.mass);  // stored units: <c_x^2> = T(0) / (m u^2) = 1 / m
    for (std::size_t k = 0; k < store.size(); ++k)
      store.set_velocity(k, maxwellian_velocity(rng, static_cast<std::uint16_t>(i), k, width));
    const SpeciesMoments m = species_moments(store);
    const Vec3 mean = (1.0 / static_cast<double>(store.size())) * m.sum_c;
    store.for_each_velocity([&](Vec3& c) { c -= mean; });
    state.species.push_back(std::move(store));
  }
  return state;
}

template GasState maxwellian_state(const Scene&, const RandomStream&);
template FloatGasState maxwellian_state(const Scene&, const RandomStream&);

}  // namespace granmc
