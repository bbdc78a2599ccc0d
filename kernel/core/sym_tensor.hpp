#pragma once
// A symmetric 3x3 tensor (the pressure tensor and its parts, 000 eqs. 17-18), value type.
#include "kernel/core/vec3.hpp"

namespace granmc {

struct SymTensor {
  double xx = 0.0, yy = 0.0, zz = 0.0, xy = 0.0, xz = 0.0, yz = 0.0;

  constexpr SymTensor& operator+=(const SymTensor& o) noexcept {
    xx += o.xx;
    yy += o.yy;
    zz += o.zz;
    xy += o.xy;
    xz += o.xz;
    yz += o.yz;
    return *this;
  }
  constexpr SymTensor& operator*=(double s) noexcept {
    xx *= s;
    yy *= s;
    zz *= s;
    xy *= s;
    xz *= s;
    yz *= s;
    return *this;
  }
  [[nodiscard]] constexpr double trace() const noexcept { return xx + yy + zz; }
};

constexpr SymTensor operator*(double s, SymTensor t) noexcept { return t *= s; }
constexpr SymTensor operator+(SymTensor a, const SymTensor& b) noexcept { return a += b; }

/// w v v (the dyadic product of v with itself, weighted by w).
constexpr SymTensor weighted_dyad(double w, const Vec3& v) noexcept {
  const Vec3 wv = w * v;
  return {wv.x * v.x, wv.y * v.y, wv.z * v.z, wv.x * v.y, wv.x * v.z, wv.y * v.z};
}

}  // namespace granmc
