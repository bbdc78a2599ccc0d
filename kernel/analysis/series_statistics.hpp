#pragma once
// Replica statistics of series: the replica mean and confidence half-width (001 eq. 31,
// analysis/replica_statistics.hpp) at each sample time or shell, and time averages over the stationary half of
// a run (observe/gas_series.hpp, first_stationary_sample), per replica and then over replicas.
#include <cstddef>
#include <vector>

#include "kernel/analysis/replica_statistics.hpp"
#include "kernel/observe/compensated_sum.hpp"
#include "kernel/observe/gas_series.hpp"

namespace granmc {

/// A replica mean and its confidence half-width at each sample time (same length as RunResult::times).
struct MeanCISeries {
  std::vector<double> mean;
  std::vector<double> ci;

  [[nodiscard]] std::size_t size() const noexcept { return mean.size(); }
  [[nodiscard]] MeanCI at(std::size_t k) const { return {mean.at(k), ci.at(k)}; }
};

/// Replica mean and CI at each index k < n of the series pick(r) of replica r.
template <class Pick>
MeanCISeries per_index(std::size_t replicas, std::size_t n, Pick pick) {
  MeanCISeries out;
  std::vector<double> values(replicas);
  for (std::size_t k = 0; k < n; ++k) {
    for (std::size_t r = 0; r < replicas; ++r) values[r] = pick(r)[k];
    const MeanCI m = replica_mean(values);
    out.mean.push_back(m.mean);
    out.ci.push_back(m.ci);
  }
  return out;
}

/// Replica mean and CI at each sample time.
template <class Pick>
MeanCISeries per_time(const RunResult& result, Pick pick) {
  return per_index(
      result.replicas.size(),
      result.times.size(), [&](std::size_t r) -> const auto& { return pick(result.replicas[r]); });
}

/// value(series, k) averaged over the samples k >= (S-1)/2 in each replica (the last half of the run,
/// where a heated or scaled cooling state is stationary), then over replicas.
template <class Value>
MeanCI last_half_average(const RunResult& result, Value value) {
  const std::size_t samples = result.times.size();
  const std::size_t first = first_stationary_sample(samples);
  std::vector<double> per_replica;
  for (const ReplicaSeries& s : result.replicas) {
    CompensatedSum sum;
    for (std::size_t k = first; k < samples; ++k) sum.add(value(s, k));
    per_replica.push_back(sum.value() / static_cast<double>(samples - first));
  }
  return replica_mean(per_replica);
}

}  // namespace granmc
