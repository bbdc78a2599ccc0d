#include "kernel/schemes/initial_state.hpp"

#include <algorithm>
#include <cmath>

#include "kernel/core/batch_variates.hpp"
#include "kernel/observe/moments.hpp"

namespace granmc {

template <class Real>
void maxwellian_velocities(BasicSpeciesStore<Real>& store, const RandomStream& rng, std::uint16_t species,
                           std::uint64_t first, double width, int dimension, int threads) noexcept {
  constexpr std::size_t block = 64;
  const std::size_t blocks = (store.size() + block - 1) / block;
#pragma omp parallel for num_threads(threads) schedule(static) if (threads > 1)
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::size_t from = b * block;
    for_each_particle_normal<block>(rng, RngPurpose::initial_velocity, species, 0, first + from,
                                    std::min(block, store.size() - from), [&](std::size_t k, const Vec3& z) {
                                      store.set_velocity(from + k, width * (dimension == 3 ? z : Vec3{z.x, z.y, 0.0}));
                                    });
  }
}

template <class Real>
void maxwellian_spins(BasicSpeciesStore<Real>& store, const RandomStream& rng, std::uint16_t species,
                      std::uint64_t first, const Scene& scene, double mass) {
  store.enable_spins();
  const double width = 1.0 / std::sqrt(scene.collision.reduced_inertia * mass);  // stored units, as for c
  const bool disk = scene.run.dimension == 2;
  for_each_particle_normal<64>(rng, RngPurpose::initial_spin, species, 0, first, store.size(),
                               [&](std::size_t k, const Vec3& z) {
                                 store.set_spin(k, width * (disk ? Vec3{0.0, 0.0, z.x} : z));
                               });
}

template <class Real>
BasicGasState<Real> maxwellian_state(const Scene& scene, const RandomStream& rng, int threads) {
  BasicGasState<Real> state;
  state.scale.log_u = 0.5 * std::log(scene.initial_temperature);
  for (std::size_t i = 0; i < scene.species.size(); ++i) {
    const SpeciesConfig& sp = scene.species[i];
    BasicSpeciesStore<Real> store(static_cast<std::size_t>(sp.particles), threads);
    const double width = 1.0 / std::sqrt(sp.mass);  // stored units: <c_x^2> = T(0) / (m u^2) = 1 / m
    maxwellian_velocities(store, rng, static_cast<std::uint16_t>(i), 0, width, scene.run.dimension, threads);
    if (scene.initial_zero_momentum) {
      const SpeciesMoments m = species_moments(store);
      const Vec3 mean = (1.0 / static_cast<double>(store.size())) * m.sum_c;
      store.for_each_velocity([&](Vec3& c) { c -= mean; });
    }
    if (rough(scene.collision)) maxwellian_spins(store, rng, static_cast<std::uint16_t>(i), 0, scene, sp.mass);
    state.species.push_back(std::move(store));
  }
  return state;
}

template void maxwellian_velocities(SpeciesStore&, const RandomStream&, std::uint16_t, std::uint64_t, double, int,
                                    int) noexcept;
template void maxwellian_velocities(FloatSpeciesStore&, const RandomStream&, std::uint16_t, std::uint64_t, double, int,
                                    int) noexcept;
template void maxwellian_spins(SpeciesStore&, const RandomStream&, std::uint16_t, std::uint64_t, const Scene&, double);
template void maxwellian_spins(FloatSpeciesStore&, const RandomStream&, std::uint16_t, std::uint64_t, const Scene&,
                               double);
template GasState maxwellian_state(const Scene&, const RandomStream&, int);
template FloatGasState maxwellian_state(const Scene&, const RandomStream&, int);

}  // namespace granmc
