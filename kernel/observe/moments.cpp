#include "kernel/observe/moments.hpp"

#include "kernel/observe/compensated_sum.hpp"
#include "kernel/observe/velocity_lanes.hpp"

namespace granmc {

template <class Real>
SpeciesMoments species_moments(const BasicSpeciesStore<Real>& store, const Vec3& centre, std::size_t first,
                               std::size_t last) noexcept {
  // SimdDouble::size particles at a time, one per lane: a scalar CompensatedSum per moment made the
  // observation a large part of a cooling-state run (docs/notebook/2026-12-06-performance-history.md, "The observations
  // lane by lane").
  LaneCompensatedSum s2, s4, s6, px, py, pz;
  const SimdDouble cx(centre.x), cy(centre.y), cz(centre.z);
  for_each_velocity_lanes(
      store, first, last,
      [&](const SimdDouble& x, const SimdDouble& y, const SimdDouble& z, const SimdDouble& in_range) {
        const SimdDouble dx = x - cx, dy = y - cy, dz = z - cz;
        const SimdDouble c2 = in_range * (dx * dx + dy * dy + dz * dz);
        const SimdDouble c4 = c2 * c2;
        s2.add(c2);
        s4.add(c4);
        s6.add(c4 * c2);
        px.add(x);
        py.add(y);
        pz.add(z);
      });
  SpeciesMoments m;
  m.particles = last - first;
  m.sum_c2 = s2.value();
  m.sum_c4 = s4.value();
  m.sum_c6 = s6.value();
  m.sum_c = {px.value(), py.value(), pz.value()};
  return m;
}

template <class Real>
SpinMoments spin_moments(const BasicSpeciesStore<Real>& store, const Vec3& centre, std::size_t first,
                         std::size_t last) noexcept {
  CompensatedSum s2, s4, c2s2;
  for (std::size_t k = first; k < last; ++k) {
    const double w2 = norm2(store.spin(k));
    s2.add(w2);
    s4.add(w2 * w2);
    c2s2.add(norm2(store.velocity(k) - centre) * w2);
  }
  return {last - first, s2.value(), s4.value(), c2s2.value()};
}

template SpinMoments spin_moments(const SpeciesStore&, const Vec3&, std::size_t, std::size_t) noexcept;
template SpinMoments spin_moments(const FloatSpeciesStore&, const Vec3&, std::size_t, std::size_t) noexcept;
template SpeciesMoments species_moments(const SpeciesStore&, const Vec3&, std::size_t, std::size_t) noexcept;
template SpeciesMoments species_moments(const FloatSpeciesStore&, const Vec3&, std::size_t, std::size_t) noexcept;

}  // namespace granmc
