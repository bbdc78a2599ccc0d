#pragma once
// A double as a value the optimiser cannot fuse into a neighbouring operation.
//
// GCC 12.2 (Debian 12's compiler) turns the scalar pair a x - b y, a y + b x (a complex product) into one
// vfmaddsub instruction when its SLP vectoriser recognises the pattern, even with -ffp-contract=off: the
// difference is rounded once instead of twice, so the scalar form of a formula stops being the same bits
// as its SIMD form, which the collision stage relies on (collide/impact_direction.hpp; the disks' impact
// direction differed in the last bit, tests/test_rough_rule.cpp). The empty asm statement costs no
// instruction; the value is the same. Batches of xsimd pass through untouched.
#include <type_traits>

namespace granmc {

template <class T>
inline T unfused(T x) noexcept {
#if defined(__GNUC__) && !defined(__clang__) && (defined(__x86_64__) || defined(__i386__))
  if constexpr (std::is_same_v<T, double>) __asm__("" : "+x"(x));
#endif
  return x;
}

}  // namespace granmc
