#pragma once
// Collision kernels of the form used by 001 (eqs. 6-8): B(|u|, mu) = rate |u|^lambda, independent of
// mu, so the scattering direction e is uniform on the sphere (collide/isotropic_scattering.hpp), with
// rate = gamma C_lambda (001 eq. 1). The event scheme draws candidates at the constant majorant rate of
// 001 eq. (25) and keeps a candidate with probability (|u| / U_max)^lambda (001 eq. 26), and each kernel
// says at compile time when that is always 1 (Maxwell pseudomolecules), in which case no relative speed
// and no majorant is computed at all. The scheme prepares its uniforms in batches and tests
// u < (|u| / U_max)^lambda in the equivalent form u^(1 / lambda) < |u| / U_max: acceptance_thresholds
// maps a batch of u to u^(1 / lambda).
#include <cstddef>
#include <span>

#include "kernel/collide/collision_kernel.hpp"
#include "kernel/core/batch_variates.hpp"

namespace granmc {

/// Maxwell pseudomolecules, lambda = 0 (001 eq. 7): every candidate collides.
struct MaxwellKernel {
  static constexpr bool constant_rate = true;
  static constexpr const char* name = "maxwell";
  [[nodiscard]] double lambda() const noexcept { return 0.0; }
  template <std::size_t N>
  void acceptance_thresholds(std::span<double, N>) const noexcept {}  // never tested
};

/// Hard spheres in the isotropic form, lambda = 1 (001 eq. 6).
struct IsotropicHardSphereKernel {
  static constexpr bool constant_rate = false;
  static constexpr const char* name = "hard-sphere";
  [[nodiscard]] double lambda() const noexcept { return 1.0; }
  template <std::size_t N>
  void acceptance_thresholds(std::span<double, N>) const noexcept {}  // u^(1 / 1) = u
};

/// Variable hard spheres, 0 < lambda < 1 (001 eq. 8).
struct VhsKernel {
  static constexpr bool constant_rate = false;
  static constexpr const char* name = "vhs";
  double exponent = 0.5;
  [[nodiscard]] double lambda() const noexcept { return exponent; }
  template <std::size_t N>
  void acceptance_thresholds(std::span<double, N> u) const noexcept {
    if (exponent == 0.5) {  // u^2 (001 Example 9): one rounding, and a tenth of xsimd's pow in time
      for (double& x : u) x *= x;
    } else {
      power_in_place(u, 1.0 / exponent);
    }
  }
};

static_assert(EventKernel<MaxwellKernel> && EventKernel<IsotropicHardSphereKernel> && EventKernel<VhsKernel>);

}  // namespace granmc
