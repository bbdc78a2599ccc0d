#pragma once
// Velocity moments of one species, in stored (scaled) units, with compensated sums, about a given
// centre (the flow velocity, for peculiar-velocity moments; 001 eq. 13 subtracts the bulk velocity).
#include <cstddef>

#include "kernel/core/species_store.hpp"
#include "kernel/core/vec3.hpp"

namespace granmc {

/// The kurtosis cumulant n/(n + 2) <x^4> / <x^2>^2 - 1 of an isotropic vector with n components, zero for a
/// Gaussian one.
inline double kurtosis_cumulant(double n, double mean4, double mean2) noexcept {
  return n / (n + 2.0) * mean4 / (mean2 * mean2) - 1.0;
}

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
    return kurtosis_cumulant(dimension, sum_c4 / static_cast<double>(particles), mean_c2());
  }
  /// Third Sonine coefficient a3 = 1 + 3 a2 - d^2/((d+2)(d+4)) <c^6> / <c^2>^3 (9/35 for spheres, 1/6 for
  /// disks; zero for a Maxwellian; from <c^6> = (d/2)(d/2+1)(d/2+2)(1 + 3 a2 - a3) in units of sqrt(2T/m),
  /// docs/methods/derivations/sonine-hcs.md).
  [[nodiscard]] double a3(int dimension) const noexcept {
    const double m2 = mean_c2();
    const double d = dimension;
    return 1.0 + 3.0 * a2(dimension) -
           d * d / ((d + 2.0) * (d + 4.0)) * (sum_c6 / static_cast<double>(particles)) / (m2 * m2 * m2);
  }
};

/// The spin moments of one species of rough particles (core/species_store.hpp: s = (sigma / 2) omega, stored
/// units), with the velocities about a centre for their correlation.
struct SpinMoments {
  std::size_t particles = 0;
  double sum_s2 = 0.0;     // sum_k |s_k|^2
  double sum_s4 = 0.0;     // sum_k |s_k|^4
  double sum_c2_s2 = 0.0;  // sum_k |c_k - centre|^2 |s_k|^2

  [[nodiscard]] double mean_s2() const noexcept { return sum_s2 / static_cast<double>(particles); }
  /// The spins' kurtosis cumulant a02 = d_r/(d_r + 2) <omega^4> / <omega^2>^2 - 1 with d_r rotational degrees of
  /// freedom (3 spheres, 1 disks), zero for a Maxwellian.
  [[nodiscard]] double a02(int rotational_freedom) const noexcept {
    return kurtosis_cumulant(rotational_freedom, sum_s4 / static_cast<double>(particles), mean_s2());
  }
  /// The correlation of translation and rotation a11 = <V^2 omega^2> / (<V^2> <omega^2>) - 1, zero when they
  /// are independent; `mean_c2` is <|c - centre|^2> of the same particles.
  [[nodiscard]] double a11(double mean_c2) const noexcept {
    return sum_c2_s2 / static_cast<double>(particles) / (mean_c2 * mean_s2()) - 1.0;
  }
};

/// The spin moments of the particles [first, last) of a store with spins (a part of a system spread over ranks
/// sums these per chunk, schemes/rank_wave_backend.hpp). (Instantiated for SpeciesStore and FloatSpeciesStore.)
template <class Real>
SpinMoments spin_moments(const BasicSpeciesStore<Real>& store, const Vec3& centre, std::size_t first,
                         std::size_t last) noexcept;

/// The spin moments of every particle of a store with spins.
template <class Real>
SpinMoments spin_moments(const BasicSpeciesStore<Real>& store, const Vec3& centre) noexcept {
  return spin_moments(store, centre, 0, store.size());
}

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
