// The block loops (block_loop_impl.h) compiled for AVX2, BMI1 and BMI2: one block row of eight
// pixels is one 256-bit register. select_block_fn (fragment_ops.cpp) takes them when
// simd_level() says the processor has these extensions (simd_level.h); the rest of the build
// targets plain x86-64.
//
// Only the code defined between the target pragmas below is compiled for AVX2. Every header is
// included before them, so the inline functions and templates they define keep the baseline
// target in this file too: any out-of-line copy the linker might pick for another file is the
// same baseline code there. The block loops, all in an unnamed namespace, can still inline
// those baseline helpers (a subset of AVX2). No FMA is enabled, so no a * b + c is contracted
// and the float results equal the baseline ones.
#include "fragment/fragment_ops.h"

#if PINEDA_HAVE_AVX2

#include <immintrin.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <utility>

#include "fragment/blend_simd.h"
#include "fragment/shade.h"
#include "core/simd.h"

#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx2,bmi,bmi2"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx2,bmi,bmi2")
#endif

#define PINEDA_BLOCK_AVX2 1
#include "fragment/block_loop_impl.h"

namespace pineda {

BlockFn select_block_fn_avx2(const StateKey& key, ShadePath shade) {
  return select_from_tables(key, shade);
}

} // namespace pineda

#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif

#endif // PINEDA_HAVE_AVX2
