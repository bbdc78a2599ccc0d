#pragma once
// Stationary time averages of the intruder's velocity, shared by the intruder tests.
#include <cstddef>
#include <vector>

#include "kernel/analysis/replica_statistics.hpp"
#include "kernel/observe/gas_series.hpp"

namespace granmc::testing {

/// Per replica, the time average of value(v1) over the last half of the samples; then mean and CI.
template <class F>
MeanCI velocity_average(const RunResult& r, F value) {
  std::vector<double> per_replica;
  for (const ReplicaSeries& rep : r.replicas) {
    const std::vector<double>& v = rep.intruder->velocity;
    double sum = 0.0;
    const std::size_t first = first_stationary_sample(v.size());
    for (std::size_t k = first; k < v.size(); ++k) sum += value(v[k]);
    per_replica.push_back(sum / static_cast<double>(v.size() - first));
  }
  return replica_mean(per_replica);
}

}  // namespace granmc::testing
