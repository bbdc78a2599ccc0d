#pragma once
// Neumaier's compensated summation: the error stays O(eps) instead of O(N eps) for sums of squares
// over 10^7 particles. One sum, or one per SIMD lane.
#include <cmath>
#include <cstddef>

#include "kernel/core/simd.hpp"

namespace granmc {

class CompensatedSum {
 public:
  void add(double x) noexcept {
    const double t = sum_ + x;
    if (std::fabs(sum_) >= std::fabs(x))
      carry_ += (sum_ - t) + x;
    else
      carry_ += (x - t) + sum_;
    sum_ = t;
  }
  [[nodiscard]] double value() const noexcept { return sum_ + carry_; }

 private:
  double sum_ = 0.0;
  double carry_ = 0.0;
};

/// A CompensatedSum in every lane of a register: lane l sums the values added in lane l, without a
/// branch (the larger of the two magnitudes chosen by a select). value() sums the lanes' sums, then
/// their carries, with a CompensatedSum. The order of the additions differs from one CompensatedSum
/// over the same values, so the result can differ in the last bits; the error bound is the same.
class LaneCompensatedSum {
 public:
  void add(const SimdDouble& x) noexcept {
    const SimdDouble t = sum_ + x;
    const auto sum_larger = xsimd::abs(sum_) >= xsimd::abs(x);
    carry_ += (xsimd::select(sum_larger, sum_, x) - t) + xsimd::select(sum_larger, x, sum_);
    sum_ = t;
  }
  [[nodiscard]] double value() const noexcept {
    alignas(64) double sums[SimdDouble::size], carries[SimdDouble::size];
    sum_.store_aligned(sums);
    carry_.store_aligned(carries);
    CompensatedSum total;
    for (std::size_t l = 0; l < SimdDouble::size; ++l) total.add(sums[l]);
    for (std::size_t l = 0; l < SimdDouble::size; ++l) total.add(carries[l]);
    return total.value();
  }

 private:
  SimdDouble sum_ = SimdDouble(0.0);
  SimdDouble carry_ = SimdDouble(0.0);
};

}  // namespace granmc
