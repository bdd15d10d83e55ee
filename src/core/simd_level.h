// The instruction set Pineda's hot loops run with, chosen once per process at run time: the
// default build runs on any x86-64 (SSE2), and machines with AVX2 get the code compiled for it:
// the block loops (fragment/fragment_ops_avx2.cpp), the vertex transform and lighting
// (geometry/vertex_simd_avx2.cpp), the quad sampler (texture/sampler_quad.cpp) and the
// per-fragment shading (fragment/shade.cpp). Both levels give the same bytes.
#pragma once

#include <cstdint>

// Whether this build has AVX2 variants to choose: x86-64 with GCC or Clang.
#if defined(__x86_64__) && defined(__GNUC__)
#define PINEDA_HAVE_AVX2 1
#else
#define PINEDA_HAVE_AVX2 0
#endif

namespace pineda {

enum class SimdLevel : uint8_t {
  Baseline, // what the build targets: SSE2 on x86-64, NEON on AArch64
  Avx2,     // x86-64 with AVX2, BMI1 and BMI2 (and the OS saving the YMM registers)
};

// The best level this build and this processor support.
SimdLevel simd_level_supported();

// The level the hot loops use: the supported one, unless the environment variable
// PINEDA_SIMD is "sse2" or "baseline" (forces Baseline; tests compare the two paths this way).
// Read once, on first use.
SimdLevel simd_level();

// Overrides the level (clamped to the supported one) for FragCtx set up, vertices transformed
// and blocks shaded from now on; tests use it to render the same scene through both paths in
// one process.
void set_simd_level(SimdLevel level);

} // namespace pineda
