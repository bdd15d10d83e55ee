// Four-lane vectors for the rasterizer and fragment loops, written with the GCC/Clang vector
// extensions so that the same code compiles to SSE2 on x86-64 and NEON on AArch64. A block
// row of eight fragments is two of them.
#pragma once

#include <cstdint>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace pineda {

using f32x4 = float __attribute__((vector_size(16)));
using f64x2 = double __attribute__((vector_size(16)));
using f64x4 = double __attribute__((vector_size(32)));
using i32x4 = int32_t __attribute__((vector_size(16)));
using u32x4 = uint32_t __attribute__((vector_size(16)));
using i64x2 = int64_t __attribute__((vector_size(16)));
using u16x8 = uint16_t __attribute__((vector_size(16)));
using i16x8 = int16_t __attribute__((vector_size(16)));
using u8x16 = uint8_t __attribute__((vector_size(16)));

// Lane masks (all ones / zero per lane) of the two halves of a row to eight bits.
inline unsigned lane_bits(i32x4 lo, i32x4 hi) {
#if defined(__SSE2__)
  // The lanes' sign bits, which for masks are the lanes.
  const int l = _mm_movemask_ps(_mm_castsi128_ps(reinterpret_cast<__m128i>(lo)));
  const int h = _mm_movemask_ps(_mm_castsi128_ps(reinterpret_cast<__m128i>(hi)));
  return static_cast<unsigned>(l | (h << 4));
#else
  const i32x4 b = (lo & i32x4{1, 2, 4, 8}) | (hi & i32x4{16, 32, 64, 128});
  return static_cast<unsigned>(b[0] | b[1] | b[2] | b[3]);
#endif
}

// Eight bits to lane masks of the two halves of a row.
inline void bits_to_lanes(unsigned m, i32x4& lo, i32x4& hi) {
  const i32x4 zero = {}, v = zero + static_cast<int32_t>(m);
  lo = (v & i32x4{1, 2, 4, 8}) != zero;
  hi = (v & i32x4{16, 32, 64, 128}) != zero;
}

// a > b ? a : b and a < b ? a : b, lane by lane (b where a lane is NaN). These are exactly
// the SSE2 max/min instructions, which GCC does not pick for the vector forms by itself.
inline f32x4 vmax(f32x4 a, f32x4 b) {
#if defined(__SSE2__)
  return _mm_max_ps(a, b);
#else
  return a > b ? a : b;
#endif
}
inline f32x4 vmin(f32x4 a, f32x4 b) {
#if defined(__SSE2__)
  return _mm_min_ps(a, b);
#else
  return a < b ? a : b;
#endif
}
inline f64x2 vmax(f64x2 a, f64x2 b) {
#if defined(__SSE2__)
  return _mm_max_pd(a, b);
#else
  return a > b ? a : b;
#endif
}
inline f64x2 vmin(f64x2 a, f64x2 b) {
#if defined(__SSE2__)
  return _mm_min_pd(a, b);
#else
  return a < b ? a : b;
#endif
}

// The low and high eight bytes of `v` widened to 16-bit lanes (two 4-byte pixels each).
inline u16x8 widen_lo(u8x16 v) {
  const u8x16 z = {};
  return reinterpret_cast<u16x8>(
      __builtin_shufflevector(v, z, 0, 16, 1, 17, 2, 18, 3, 19, 4, 20, 5, 21, 6, 22, 7, 23));
}
inline u16x8 widen_hi(u8x16 v) {
  const u8x16 z = {};
  return reinterpret_cast<u16x8>(
      __builtin_shufflevector(v, z, 8, 24, 9, 25, 10, 26, 11, 27, 12, 28, 13, 29, 14, 30, 15, 31));
}

// The inverse of widen_lo/widen_hi for lanes holding values in [0, 255].
inline u8x16 narrow(u16x8 lo, u16x8 hi) {
#if defined(__SSE2__)
  // Saturation never applies to such lanes.
  return reinterpret_cast<u8x16>(
      _mm_packus_epi16(reinterpret_cast<__m128i>(lo), reinterpret_cast<__m128i>(hi)));
#else
  return __builtin_shufflevector(reinterpret_cast<u8x16>(lo), reinterpret_cast<u8x16>(hi), 0, 2, 4,
                                 6, 8, 10, 12, 14, 16, 18, 20, 22, 24, 26, 28, 30);
#endif
}

// llvmpipe's 8-bit linear step a + floor(((b - a) w + 128) / 256) (texture/sampler.cpp lerp8) on
// lanes holding values in [0, 255], with w in [0, 255]. (b - a) w does not fit 16 bits, so
// w = 2h + e is split: with x = (b - a) h and y = (b - a) e, floor((2x + y + 128) / 256) equals
// (x + ((y + 128) >> 1)) >> 7, because an odd 2K + 1 never reaches the next multiple of 256
// past 2K. Every intermediate value fits 16 bits.
inline i16x8 lerp8_lanes(i16x8 a, i16x8 b, int w) {
  const i16x8 d = b - a;
  const i16x8 x = d * static_cast<int16_t>(w >> 1);
  const i16x8 y = d & static_cast<int16_t>(-(w & 1));
  return a + ((x + ((y + 128) >> 1)) >> 7);
}

// Four vectors of lanes in [0, 255] (one 4-byte pixel each) packed to the sixteen bytes of four
// pixels, lane k of vector p going to byte 4p + k.
inline u32x4 pack_pixels(i32x4 p0, i32x4 p1, i32x4 p2, i32x4 p3) {
#if defined(__SSE2__)
  const __m128i a = _mm_packs_epi32(reinterpret_cast<__m128i>(p0), reinterpret_cast<__m128i>(p1));
  const __m128i b = _mm_packs_epi32(reinterpret_cast<__m128i>(p2), reinterpret_cast<__m128i>(p3));
  return reinterpret_cast<u32x4>(_mm_packus_epi16(a, b));
#else
  const u16x8 a = __builtin_shufflevector(reinterpret_cast<u16x8>(p0), reinterpret_cast<u16x8>(p1),
                                          0, 2, 4, 6, 8, 10, 12, 14);
  const u16x8 b = __builtin_shufflevector(reinterpret_cast<u16x8>(p2), reinterpret_cast<u16x8>(p3),
                                          0, 2, 4, 6, 8, 10, 12, 14);
  return reinterpret_cast<u32x4>(narrow(a, b));
#endif
}

} // namespace pineda
