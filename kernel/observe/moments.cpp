#include "kernel/observe/moments.hpp"

#include "kernel/observe/compensated_sum.hpp"

namespace granmc {

template <class Real>
SpeciesMoments species_moments(const BasicSpeciesStore<Real>& store, const Vec3& centre) noexcept {
  CompensatedSum s2, s4, s6, px, py, pz;
  store.for_each_velocity([&](const Vec3& c) {
    const double c2 = norm2(c - centre);
    s2.add(c2);
    s4.add(c2 * c2);
    s6.add(c2 * c2 * c2);
    px.add(c.x);
    py.add(c.y);
    pz.add(c.z);
  });
  SpeciesMoments m;
  m.particles = store.size();
  m.sum_c2 = s2.value();
  m.sum_c4 = s4.value();
  m.sum_c6 = s6.value();
  m.sum_c = {px.value(), py.value(), pz.value()};
  return m;
}

template SpeciesMoments species_moments(const SpeciesStore&, const Vec3&) noexcept;
template SpeciesMoments species_moments(const FloatSpeciesStore&, const Vec3&) noexcept;

}  // namespace granmc
