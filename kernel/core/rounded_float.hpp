#pragma once
// A double rounded to float, as a value the optimiser cannot trace back to the double it came from.
//
// GCC 12.2 (Debian 12's compiler) at -O2 and above converts two doubles to float as one pair and has
// code that reads the floats back get the doubles from before the conversion: a float store followed by
// a read of the same record (tests/test_species_store.cpp), and a register's lanes rounded one by one
// through a small array (core/simd.hpp, rounded_to; tests/test_numerics.cpp) returned unrounded values.
// The empty asm statement costs no instruction; the value is the same. docs/user-guide/accuracy-cost.md.
namespace granmc {

inline float rounded_float(double x) noexcept {
  float f = static_cast<float>(x);
#if defined(__GNUC__) && !defined(__clang__) && (defined(__x86_64__) || defined(__i386__))
  __asm__("" : "+x"(f));
#endif
  return f;
}

}  // namespace granmc
