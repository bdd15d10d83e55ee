// The instruction set Pineda's hot loops run with, chosen once per process at run time: the
// default build runs on any x86-64 (SSE2), and the code compiled for wider vectors runs where
// the processor has it. Three levels, each a superset of the one before:
// - Baseline: SSE2 (NEON on AArch64), four float lanes.
// - Avx2: AVX2, BMI1, BMI2: the block loops (fragment/fragment_ops_avx2.cpp, a block row of
//   eight pixels per 256-bit register), the vertex transform and lighting eight vertices at a
//   time (geometry/vertex_simd_avx2.cpp), the quad sampler (texture/sampler_quad.cpp) and the
//   per-fragment shading (fragment/shade.cpp).
// - Avx512: AVX-512 F, BW, DQ and VL on top of that: the block loops with opmask coverage,
//   masked stores and 512-bit depth and colour conversion (fragment/fragment_ops_avx512.cpp)
//   and the vertex transform and lighting sixteen vertices at a time
//   (geometry/vertex_simd_avx512.cpp). The sampler and the shading keep their AVX2 forms there.
// Every level gives the same bytes; code that exists for a level runs at that level and above
// (compare with >=).
#pragma once

#include <cstdint>

// Whether this build has AVX2 and AVX-512 variants to choose: x86-64 with GCC or Clang.
#if defined(__x86_64__) && defined(__GNUC__)
#define PINEDA_HAVE_AVX2 1
#define PINEDA_HAVE_AVX512 1
#else
#define PINEDA_HAVE_AVX2 0
#define PINEDA_HAVE_AVX512 0
#endif

namespace pineda {

enum class SimdLevel : uint8_t {
  Baseline, // what the build targets: SSE2 on x86-64, NEON on AArch64
  Avx2,     // x86-64 with AVX2, BMI1 and BMI2 (and the OS saving the YMM registers)
  Avx512,   // Avx2 plus AVX-512 F, BW, DQ, VL (and the OS saving the opmask and ZMM registers)
};

// The best level this build and this processor support.
SimdLevel simd_level_supported();

// The level the hot loops use: the supported one, capped by the environment variable
// PINEDA_SIMD when set: "sse2" or "baseline" (Baseline), "avx2" (at most Avx2), "avx512" (at
// most Avx512); tests and benchmarks compare the paths this way. Read once, on first use.
SimdLevel simd_level();

// Overrides the level (clamped to the supported one) for FragCtx set up, vertices transformed
// and blocks shaded from now on; tests use it to render the same scene through every path in
// one process.
void set_simd_level(SimdLevel level);

// The level PINEDA_SIMD names with the supported level `supported` (nullptr or an unknown name:
// `supported`), clamped to `supported`. Exposed for tests.
SimdLevel simd_level_from_env(const char* env, SimdLevel supported);

} // namespace pineda
