#pragma once
// A three-component velocity or direction, value type for the kernels.
#include <cmath>

namespace granmc {

struct Vec3 {
  double x = 0.0, y = 0.0, z = 0.0;

  constexpr Vec3& operator+=(const Vec3& o) noexcept {
    x += o.x;
    y += o.y;
    z += o.z;
    return *this;
  }
  constexpr Vec3& operator-=(const Vec3& o) noexcept {
    x -= o.x;
    y -= o.y;
    z -= o.z;
    return *this;
  }
  constexpr Vec3& operator*=(double s) noexcept {
    x *= s;
    y *= s;
    z *= s;
    return *this;
  }
};

constexpr Vec3 operator+(Vec3 a, const Vec3& b) noexcept { return a += b; }
constexpr Vec3 operator-(Vec3 a, const Vec3& b) noexcept { return a -= b; }
constexpr Vec3 operator*(double s, Vec3 a) noexcept { return a *= s; }
constexpr double dot(const Vec3& a, const Vec3& b) noexcept { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr double norm2(const Vec3& a) noexcept { return dot(a, a); }
inline double norm(const Vec3& a) noexcept { return std::sqrt(norm2(a)); }
constexpr Vec3 cross(const Vec3& a, const Vec3& b) noexcept {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

}  // namespace granmc
