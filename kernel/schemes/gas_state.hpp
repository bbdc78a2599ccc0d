#pragma once
// The state of one replica of a spatially homogeneous gas.
#include <cstdint>
#include <vector>

#include "kernel/core/species_store.hpp"
#include "kernel/core/velocity_scale.hpp"

namespace granmc {

struct GasState {
  std::vector<SpeciesStore> species;  // stored velocities c, V = u c
  VelocityScale scale;
  double time = 0.0;                  // scene time
  std::uint64_t step = 0;             // time steps taken (a random-stream counter)
};

}  // namespace granmc
