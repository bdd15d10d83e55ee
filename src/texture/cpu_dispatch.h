// Run-time choice of the AVX2 variants of the texturing code (texture/sampler_quad.cpp,
// fragment/shade.cpp): the default build targets any x86-64, and the AVX2 forms run at
// SimdLevel::Avx2 and above (core/simd_level.h; these have no AVX-512 forms; PINEDA_SIMD=sse2
// keeps the SSE2 forms, to test or compare them on an AVX2 machine); both give the same
// results.
#pragma once

#include "core/simd_level.h"

namespace pineda {

inline bool use_avx2() {
#if PINEDA_HAVE_AVX2
  return simd_level() >= SimdLevel::Avx2;
#else
  return false;
#endif
}

} // namespace pineda
