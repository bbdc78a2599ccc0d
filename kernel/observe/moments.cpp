#include "kernel/observe/moments.hpp"

#include "kernel/observe/compensated_sum.hpp"

namespace granmc {

template <class Real>
SpeciesMoments species_moments(const BasicSpeciesStore<Real>& store, const Vec3& centre, std::size_t first,
                               std::size_t last) noexcept {
  CompensatedSum s2, s4, s6, px, py, pz;
  for (std::size_t k = first; k < last; ++k) {
    const Vec3 c = store.velocity(k);
    const double c2 = norm2(c - centre);
    s2.add(c2);
    s4.add(c2 * c2);
    s6.add(c2 * c2 * c2);
    px.add(c.x);
    py.add(c.y);
    pz.add(c.z);
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
