// Run-time choice of the AVX2 variants of the texturing code (texture/sampler_quad.cpp,
// fragment/shade.cpp): the default build targets any x86-64, and the AVX2 forms run only at
// SimdLevel::Avx2 (core/simd_level.h; PINEDA_SIMD=sse2 keeps the SSE2 forms, to test or
// compare them on an AVX2 machine); both give the same results.
#pragma once

#include "core/simd_level.h"

namespace pineda {

inline bool use_avx2() {
#if PINEDA_HAVE_AVX2
  return simd_level() == SimdLevel::Avx2;
#else
  return false;
#endif
}

} // namespace pineda
