// The block loops (block_loop_impl.h) compiled for AVX-512 (F, BW, DQ, VL) with AVX2, BMI1 and
// BMI2: the AVX2 instances' code, plus the AVX-512 forms of the few functions that gain from
// them (block_loop_impl.h, under PINEDA_BLOCK_AVX512): opmask registers for a row's coverage
// and depth-test result instead of lane masks and blends, a row's eight depth values as one
// 512-bit vector of doubles converted in one instruction (also for 32-bit buffers), the colours
// of four pixels per 512-bit register narrowed to bytes with vpmovdb, and the over-blend of a
// whole row in one register. A block is still walked one row of eight pixels at a time.
// select_block_fn (fragment_ops.cpp) takes them when simd_level() is Avx512 (simd_level.h).
//
// As in fragment_ops_avx2.cpp, only the code defined between the target pragmas is compiled for
// these extensions; every header is included before them. No FMA is enabled, so no a * b + c
// is contracted and the results equal the baseline ones.
#include "fragment/fragment_ops.h"

#if PINEDA_HAVE_AVX512

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
#pragma clang attribute push(                                                                      \
    __attribute__((target("avx512f,avx512bw,avx512dq,avx512vl,avx2,bmi,bmi2"))),                   \
    apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx512f,avx512bw,avx512dq,avx512vl,avx2,bmi,bmi2")
#endif

#define PINEDA_BLOCK_AVX2 1
#define PINEDA_BLOCK_AVX512 1
#include "fragment/block_loop_impl.h"

namespace pineda {

BlockFn select_block_fn_avx512(const StateKey& key, ShadePath shade) {
  return select_from_tables(key, shade);
}

} // namespace pineda

#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif

#endif // PINEDA_HAVE_AVX512
