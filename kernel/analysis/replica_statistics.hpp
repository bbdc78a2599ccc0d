#pragma once
// Statistics over independent replicas: the empirical mean and the confidence half-width
// lambda_p sqrt(Var / N) of 001 eq. (31), with the empirical variance eta_2 - eta_1^2 (001 after eq. 32)
// and lambda_p = 3.2 (confidence level p = 0.999). Sums run in replica order, so the result does not
// depend on which thread ran which replica.
#include <span>

namespace granmc {

inline constexpr double confidence_lambda_p = 3.2;  // 001 sec. 5.1

struct MeanCI {
  double mean = 0.0;
  double ci = 0.0;  // half-width: the mean lies in [mean - ci, mean + ci] with probability ~ p
};

MeanCI replica_mean(std::span<const double> values) noexcept;

}  // namespace granmc
