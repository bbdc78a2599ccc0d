#pragma once
#include <vector>

#include "kernel/core/scene.hpp"

namespace granmc {

/// The observation times of a scene: t_k = k t_end / samples (linear), or t_0 = 0 and
/// t_k = dt (t_end / dt)^((k - 1) / (samples - 1)) for k = 1..samples (log), increasing, ending at t_end.
std::vector<double> sample_times(const RunConfig& run);

}  // namespace granmc
