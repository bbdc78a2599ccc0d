#pragma once
// The state of one replica of a spatially homogeneous gas, with velocities stored in Real (the scene's
// run.storage; core/species_store.hpp).
#include <cstdint>
#include <vector>

#include "kernel/core/species_store.hpp"
#include "kernel/core/velocity_scale.hpp"

namespace granmc {

template <class Real>
struct BasicGasState {
  std::vector<BasicSpeciesStore<Real>> species;  // stored velocities c, V = u c
  VelocityScale scale;
  double time = 0.0;       // scene time
  std::uint64_t step = 0;  // time steps taken (a random-stream counter)
};

using GasState = BasicGasState<double>;
using FloatGasState = BasicGasState<float>;

}  // namespace granmc
