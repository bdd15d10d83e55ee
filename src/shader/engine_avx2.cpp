// The engine's kernels compiled for AVX2: eight lanes per vector. Executable chooses them when
// simd_level() is Avx2 or above. Every header this file needs is included before the target
// pragma, except the math (vmath.h, lane_apply.h), which engine_kernels.h includes after it in
// this file's own namespace (PINEDA_SIMD_NS), so that it compiles for AVX2 and is never merged
// with the baseline copies. No FMA is enabled (and the file is built with -ffp-contract=off),
// so the results equal the baseline ones bit for bit.
#include "shader/engine_internal.h"
#include "shader/fp_env.h"

#if PINEDA_HAVE_AVX2

#include <immintrin.h>

#include <cstdint>
#include <cstring>
#include <utility>

#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx2,bmi,bmi2"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx2,bmi,bmi2")
#endif

#define PINEDA_SIMD_NS vm_avx2
#include "shader/engine_kernels.h"

namespace pineda::shader {

KernelTable kernels_avx2(bool block) {
  return block ? make_kernel_table<8, true>() : make_kernel_table<8, false>();
}

} // namespace pineda::shader

#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif

#else

namespace pineda::shader {
KernelTable kernels_avx2(bool block) {
  return kernels_baseline(block);
}
} // namespace pineda::shader

#endif
