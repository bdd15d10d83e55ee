// Four-lane vectors for the rasterizer and fragment loops, written with the GCC/Clang vector
// extensions so that the same code compiles to SSE2 on x86-64 and NEON on AArch64. A block
// row of eight fragments is two of them.
#pragma once

#include <cstdint>

namespace pineda {

using f32x4 = float __attribute__((vector_size(16)));
using f64x2 = double __attribute__((vector_size(16)));
using i32x4 = int32_t __attribute__((vector_size(16)));
using u32x4 = uint32_t __attribute__((vector_size(16)));
using i64x2 = int64_t __attribute__((vector_size(16)));

// Lane masks (all ones / zero per lane) of the two halves of a row to eight bits.
inline unsigned lane_bits(i32x4 lo, i32x4 hi) {
  const i32x4 b = (lo & i32x4{1, 2, 4, 8}) | (hi & i32x4{16, 32, 64, 128});
  return static_cast<unsigned>(b[0] | b[1] | b[2] | b[3]);
}

// Eight bits to lane masks of the two halves of a row.
inline void bits_to_lanes(unsigned m, i32x4& lo, i32x4& hi) {
  const i32x4 zero = {}, v = zero + static_cast<int32_t>(m);
  lo = (v & i32x4{1, 2, 4, 8}) != zero;
  hi = (v & i32x4{16, 32, 64, 128}) != zero;
}

} // namespace pineda
