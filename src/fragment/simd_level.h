// The instruction set the fragment stage's block loops run with, chosen once per process at
// run time: the default build runs on any x86-64 (SSE2), and machines with AVX2 get the
// instances compiled for it (fragment_ops_avx2.cpp). Both give the same bytes.
#pragma once

#include <cstdint>

namespace pineda {

enum class SimdLevel : uint8_t {
  Baseline, // what the build targets: SSE2 on x86-64, NEON on AArch64
  Avx2,     // x86-64 with AVX2, BMI1 and BMI2 (and the OS saving the YMM registers)
};

// The best level this build and this processor support.
SimdLevel simd_level_supported();

// The level the block loops use: the supported one, unless the environment variable
// PINEDA_SIMD is "sse2" or "baseline" (forces Baseline; tests compare the two paths this way).
// Read once, on first use.
SimdLevel simd_level();

// Overrides the level (clamped to the supported one) for FragCtx set up from now on; tests
// use it to render the same scene through both paths in one process.
void set_simd_level(SimdLevel level);

} // namespace pineda
