#pragma once
// The velocities of particles [first, last) of a store, one SIMD register of particles at a time, for the
// sums over particles of the observations (moments, pressure tensor): f(x, y, z, in_range) gets the
// components of SimdDouble::size particles lane by lane, and in_range is 1 in the lanes that hold a
// particle, 0 in the lanes past the last one (whose components are 0).
#include <cstddef>

#include "kernel/core/simd.hpp"
#include "kernel/core/species_store.hpp"
#include "kernel/core/vec3.hpp"

namespace granmc {

template <class Real, class F>
void for_each_velocity_lanes(const BasicSpeciesStore<Real>& store, std::size_t first, std::size_t last, F&& f) {
  constexpr std::size_t lanes = SimdDouble::size;
  alignas(64) double x[lanes], y[lanes], z[lanes];
  auto load = [&](std::size_t k, std::size_t l) {
    const Vec3 c = store.velocity(k);
    x[l] = c.x;
    y[l] = c.y;
    z[l] = c.z;
  };
  auto call = [&](const SimdDouble& in_range) {
    f(SimdDouble::load_aligned(x), SimdDouble::load_aligned(y), SimdDouble::load_aligned(z), in_range);
  };
  std::size_t k = first;
  for (; k + lanes <= last; k += lanes) {
    for (std::size_t l = 0; l < lanes; ++l) load(k + l, l);
    call(SimdDouble(1.0));
  }
  if (k == last) return;
  alignas(64) double in_range[lanes];
  for (std::size_t l = 0; l < lanes; ++l) {
    if (k + l < last) {
      load(k + l, l);
    } else {
      x[l] = y[l] = z[l] = 0.0;
    }
    in_range[l] = k + l < last ? 1.0 : 0.0;
  }
  call(SimdDouble::load_aligned(in_range));
}

}  // namespace granmc
