#pragma once
// A statistical check against theory that has teeth both ways. A replica mean is compared with the expected
// value using its measured confidence half-width ci (001 eq. 31: lambda_p = 3.2 times the replica standard
// error, kernel/analysis/replica_statistics.hpp) as the tolerance. Alone, that check gets easier to pass as the
// variance grows: a change that makes the estimate noisier (or that corrupts the CI itself) would pass it more
// easily. So the check also bounds the CI: ci <= ci_bound.
//
// Each ci_bound is justified where it is used, preferably by the standard error expected from the physics
// (e.g. a temperature from N Maxwellian particles over R replicas has relative standard error sqrt(2 / (3 N R))),
// with expected_ci_bound() adding the scatter of the CI's own estimate from R replicas; otherwise by the CI
// measured today times a stated headroom ("measured today 0.0123; bound 1.5x"). A failing bound means the
// estimate lost resolution (or the bound's justification is wrong): it is never widened to pass.
#include <cmath>

#include <gtest/gtest.h>

#include "kernel/analysis/replica_statistics.hpp"

namespace granmc::testing {

/// Succeeds when |measured - expected| <= ci + model_error (the theory's documented model error, 0 for exact
/// results) and ci <= ci_bound; on failure the message gives both numbers and says which condition failed.
/// A NaN anywhere fails.
inline ::testing::AssertionResult within_ci(const char* what, double measured, double ci, double expected,
                                            double ci_bound, double model_error = 0.0) {
  const double deviation = std::fabs(measured - expected);
  const bool close = deviation <= ci + model_error;
  const bool sharp = ci <= ci_bound;
  if (close && sharp) return ::testing::AssertionSuccess();
  ::testing::AssertionResult failure = ::testing::AssertionFailure();
  failure << what << ": measured " << measured << " +- " << ci << ", expected " << expected;
  if (model_error != 0.0) failure << " (model error " << model_error << ")";
  if (!close) failure << "; |measured - expected| = " << deviation << " > ci + model error = " << ci + model_error;
  if (!sharp) {
    failure << "; ci = " << ci << " > its bound " << ci_bound
            << " (the estimate is noisier than it should be, so the comparison has lost its resolution)";
  }
  return failure;
}

/// The same for a replica mean and its CI.
inline ::testing::AssertionResult within_ci(const char* what, const MeanCI& m, double expected, double ci_bound,
                                            double model_error = 0.0) {
  return within_ci(what, m.mean, m.ci, expected, ci_bound, model_error);
}

/// A bound on the measured CI of a mean over `replicas` independent replicas whose standard deviation is known
/// to be `sigma` (one replica's): lambda_p sigma / sqrt(R) times the 0.999 quantile of the CI's own scatter.
/// The CI uses the empirical variance (1/R) sum (x - mean)^2, which for Gaussian replicas is
/// sigma^2 chi^2_{R-1} / R; its 0.999 quantile is taken from the Wilson-Hilferty approximation
/// chi^2_k(p) = k (1 - 2/(9k) + z_p sqrt(2/(9k)))^3, z_0.999 = 3.09 (within 1 % for k >= 7). The factor is
/// 1.75 for R = 8, 1.54 for R = 16, 1.38 for R = 32, 1.27 for R = 64 and 1.07 for R = 1000.
inline double expected_ci_bound(double sigma, int replicas) {
  const double k = replicas - 1.0, r = replicas;
  const double w = 1.0 - 2.0 / (9.0 * k) + 3.09 * std::sqrt(2.0 / (9.0 * k));
  const double quantile = std::sqrt(k * w * w * w / r);
  return confidence_lambda_p * sigma / std::sqrt(r) * quantile;
}

}  // namespace granmc::testing
