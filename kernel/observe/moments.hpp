#pragma once
// Velocity moments of one species, in stored (scaled) units, with compensated sums, about a given
// centre (the flow velocity, for peculiar-velocity moments; 001 eq. 13 subtracts the bulk velocity).
#include <cstddef>

#include "kernel/core/species_store.hpp"
#include "kernel/core/vec3.hpp"

namespace granmc {

struct SpeciesMoments {
  std::size_t particles = 0;
  double sum_c2 = 0.0;  // sum_k |c_k - centre|^2
  double sum_c4 = 0.0;  // sum_k |c_k - centre|^4
  double sum_c6 = 0.0;  // sum_k |c_k - centre|^6
  Vec3 sum_c;           // sum_k c_k (about the origin, whatever the centre)

  /// <c^2>
  [[nodiscard]] double mean_c2() const noexcept { return sum_c2 / static_cast<double>(particles); }
  /// Kurtosis cumulant a2 = d/(d+2) <c^4> / <c^2>^2 - 1 in d = `dimension` (3/5 for spheres, 1/2 for disks;
  /// zero for a Maxwellian; c_i = 2 a2, 000 Fig. 1).
  [[nodiscard]] double a2(int dimension) const noexcept {
    const double m2 = mean_c2();
    const double d = dimension;
    return d / (d + 2.0) * (sum_c4 / static_cast<double>(particles)) / (m2 * m2) - 1.0;
  }
  /// Third Sonine coefficient a3 = 1 + 3 a2 - d^2/((d+2)(d+4)) <c^6> / <c^2>^3 (9/35 for spheres, 1/6 for
  /// disks; zero for a Maxwellian; from <c^6> = (d/2)(d/2+1)(d/2+2)(1 + 3 a2 - a3) in units of sqrt(2T/m),
  /// docs/derivations/sonine-hcs.md).
  [[nodiscard]] double a3(int dimension) const noexcept {
    const double m2 = mean_c2();
    const double d = dimension;
    return 1.0 + 3.0 * a2(dimension) -
           d * d / ((d + 2.0) * (d + 4.0)) * (sum_c6 / static_cast<double>(particles)) / (m2 * m2 * m2);
  }
};

/// The moments of the particles [first, last) of the store (a part of a system spread over ranks sums
/// these per chunk, schemes/rank_wave_backend.hpp). (Instantiated for SpeciesStore and FloatSpeciesStore.)
template <class Real>
SpeciesMoments species_moments(const BasicSpeciesStore<Real>& store, const Vec3& centre, std::size_t first,
                               std::size_t last) noexcept;

/// The moments of every particle of the store.
template <class Real>
SpeciesMoments species_moments(const BasicSpeciesStore<Real>& store, const Vec3& centre = {}) noexcept {
  return species_moments(store, centre, 0, store.size());
}

}  // namespace granmc
