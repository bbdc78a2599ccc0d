#pragma once
#include <cstdint>

#include "kernel/core/philox_stream.hpp"
#include "kernel/core/scene.hpp"
#include "kernel/schemes/gas_state.hpp"

namespace granmc {

/// Particles `first` + k of species i of the Maxwellian start (000 eq. 13), before the mean is removed,
/// into particle k of `store`, for every k of the store: normals from the block (initial_velocity, i, 0,
/// first + k) (core/batch_variates.hpp ParticleNormals, 64 particles at a time in SIMD) times `width`, the
/// thermal width 1/sqrt(m) in stored units; in d = `dimension` = 2 (disks) the z component is 0. A system
/// spread over ranks fills its part with first = its first particle, and gets the velocities of the
/// one-process start. `threads` fill blocks of 64 particles each; every particle's velocity comes from its own
/// block, so the result is the same for any number.
template <class Real>
void maxwellian_velocities(BasicSpeciesStore<Real>& store, const RandomStream& rng, std::uint16_t species,
                           std::uint64_t first, double width, int dimension, int threads = 1) noexcept;

/// The spins of rough particles `first` + k of species i at equipartition, T_rot = T(0), into particle k of
/// `store` (which it gives spins): s = (sigma / 2) omega with <s_c^2> = T(0) / (kappa m) per rotational degree of
/// freedom (I = kappa m sigma^2 / 4), three for spheres, one (z) for disks; normals from the blocks
/// (initial_spin, i, 0, first + k). A system spread over ranks fills its part as for the velocities.
template <class Real>
void maxwellian_spins(BasicSpeciesStore<Real>& store, const RandomStream& rng, std::uint16_t species,
                      std::uint64_t first, const Scene& scene, double mass);

/// Maxwellian velocities at the scene's initial temperature for every species (000 eq. 13), then each
/// species' mean velocity subtracted so the total momentum vanishes (000 sec. 3); rough particles also get
/// Maxwellian spins at the same temperature (core/species_store.hpp). The velocity scale is
/// u = sqrt(T(0)), so stored velocities have m <c^2> / d = 1 on average.
/// Real is the storage precision (GasState or FloatGasState): the draws are the same, rounded when stored.
/// `threads`: the replica's threads, which clear the stores' memory and draw the velocities (the same bits for
/// any number).
template <class Real = double>
BasicGasState<Real> maxwellian_state(const Scene& scene, const RandomStream& rng, int threads = 1);

}  // namespace granmc
