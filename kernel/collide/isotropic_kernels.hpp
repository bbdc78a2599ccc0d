#pragma once
// Collision kernels of the form used by 001 (eqs. 6-8): B(|u|, mu) = rate |u|^lambda, independent of
// mu, so the scattering direction e is uniform on the sphere (collide/isotropic_scattering.hpp), with
// rate = gamma C_lambda (001 eq. 1). The event scheme draws candidates at the constant majorant rate of
// 001 eq. (25) and keeps a candidate with probability (|u| / U_max)^lambda (001 eq. 26); each kernel
// gives that probability, and says at compile time when it is always 1 (Maxwell pseudomolecules), in
// which case no relative speed and no majorant is computed at all.
#include <cmath>

namespace granmc {

/// Maxwell pseudomolecules, lambda = 0 (001 eq. 7): every candidate collides.
struct MaxwellKernel {
  static constexpr bool constant_rate = true;
  static constexpr const char* name = "maxwell";
  [[nodiscard]] double lambda() const noexcept { return 0.0; }
  [[nodiscard]] double acceptance(double) const noexcept { return 1.0; }
};

/// Hard spheres in the isotropic form, lambda = 1 (001 eq. 6).
struct IsotropicHardSphereKernel {
  static constexpr bool constant_rate = false;
  static constexpr const char* name = "hard-sphere";
  [[nodiscard]] double lambda() const noexcept { return 1.0; }
  [[nodiscard]] double acceptance(double speed_ratio) const noexcept { return speed_ratio; }
};

/// Variable hard spheres, 0 < lambda < 1 (001 eq. 8).
struct VhsKernel {
  static constexpr bool constant_rate = false;
  static constexpr const char* name = "vhs";
  double exponent = 0.5;
  [[nodiscard]] double lambda() const noexcept { return exponent; }
  [[nodiscard]] double acceptance(double speed_ratio) const noexcept { return std::pow(speed_ratio, exponent); }
};

}  // namespace granmc
