#include "kernel/observe/moments.hpp"

#include "kernel/observe/compensated_sum.hpp"

namespace granmc {

template <class Real>
SpeciesMoments species_moments(const BasicSpeciesStore<Real>& store, const Vec3& centre, std::size_t first,
                               std::size_t last) noexcept {
  // SimdDouble::size particles at a time, one per lane (a scalar CompensatedSum per moment ran at 6 ns per
  // particle, a third of a cooling-state run with 40 samples: docs/performance.md).
  constexpr std::size_t lanes = SimdDouble::size;
  LaneCompensatedSum s2, s4, s6, px, py, pz;
  alignas(64) double x[lanes], y[lanes], z[lanes];
  const SimdDouble cx(centre.x), cy(centre.y), cz(centre.z);
  auto add = [&](const SimdDouble& in_range) {  // in_range: 1 in the lanes that hold a particle, else 0
    const SimdDouble vx = SimdDouble::load_aligned(x), vy = SimdDouble::load_aligned(y), vz = SimdDouble::load_aligned(z);
    const SimdDouble dx = vx - cx, dy = vy - cy, dz = vz - cz;
    const SimdDouble c2 = in_range * (dx * dx + dy * dy + dz * dz);
    const SimdDouble c4 = c2 * c2;
    s2.add(c2);
    s4.add(c4);
    s6.add(c4 * c2);
    px.add(vx);
    py.add(vy);
    pz.add(vz);
  };
  std::size_t k = first;
  for (; k + lanes <= last; k += lanes) {
    for (std::size_t l = 0; l < lanes; ++l) {
      const Vec3 c = store.velocity(k + l);
      x[l] = c.x;
      y[l] = c.y;
      z[l] = c.z;
    }
    add(SimdDouble(1.0));
  }
  if (k < last) {  // the last particles, the other lanes zero (their c2 masked out)
    alignas(64) double in_range[lanes];
    for (std::size_t l = 0; l < lanes; ++l) {
      const Vec3 c = k + l < last ? store.velocity(k + l) : Vec3{};
      x[l] = c.x;
      y[l] = c.y;
      z[l] = c.z;
      in_range[l] = k + l < last ? 1.0 : 0.0;
    }
    add(SimdDouble::load_aligned(in_range));
  }
  SpeciesMoments m;
  m.particles = last - first;
  m.sum_c2 = s2.value();
  m.sum_c4 = s4.value();
  m.sum_c6 = s6.value();
  m.sum_c = {px.value(), py.value(), pz.value()};
  return m;
}

template SpeciesMoments species_moments(const SpeciesStore&, const Vec3&, std::size_t, std::size_t) noexcept;
template SpeciesMoments species_moments(const FloatSpeciesStore&, const Vec3&, std::size_t, std::size_t) noexcept;

}  // namespace granmc
