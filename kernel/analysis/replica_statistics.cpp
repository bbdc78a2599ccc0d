#include "kernel/analysis/replica_statistics.hpp"

#include <cmath>

#include "kernel/observe/compensated_sum.hpp"

namespace granmc {

MeanCI replica_mean(std::span<const double> values) noexcept {
  const double n = static_cast<double>(values.size());
  if (values.empty()) return {};
  CompensatedSum s1;
  for (double v : values) s1.add(v);
  const double mean = s1.value() / n;
  CompensatedSum s2;  // centred second moment: eta_2 - eta_1^2 without cancellation
  for (double v : values) s2.add((v - mean) * (v - mean));
  const double variance = s2.value() / n;                        // NaN if a replica is NaN: no false precision
  return {mean, confidence_lambda_p * std::sqrt(variance / n)};  // 001 eq. (31)
}

}  // namespace granmc
