#pragma once
// xsimd, and the register of doubles the build targets (AVX-512: 8 lanes, AVX2: 4).

// GCC 12 warns inside its own AVX-512 headers (the _mm512_undefined_* idiom) wherever xsimd inlines them.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <xsimd/xsimd.hpp>
#pragma GCC diagnostic pop

namespace granmc {

using SimdDouble = xsimd::batch<double>;  // the widest registers the build targets

}  // namespace granmc
