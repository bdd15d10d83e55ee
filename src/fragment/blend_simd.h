// Blending (GL 2.1 §4.1.8) of four packed 4-byte pixels at a time in 16-bit fixed point, for the
// factor and equation combinations whose float result (blend.h blend_pixel) is exactly the
// rounded rational one, so that these paths give the same bytes as the float path.
//
// With unorm8 colours and factors f = F/255 (F an integer in [0, 255]), the float path computes
// round((S*Fs +- D*Fd) / 255) up to float error. The numerator N is an integer and 255 is odd,
// so N/255 is never closer than 1/510 to a half-integer, far beyond the float error: rounding
// the exact quotient gives the same byte. round(N / 255) for 0 <= N <= 255*255 is
// (n + (n >> 8)) >> 8 with n = N + 128, which never leaves 16 bits.
#pragma once

#include <cstdint>

#include "fragment/simd.h"

namespace pineda {

// round(x / 255) on lanes x in [0, 255 * 255]. With n = x + 128, (n + (n >> 8)) >> 8 equals
// floor(n * 257 / 65536): the two differ by floor((A + f) / 256) against floor(A / 256) for an
// integer A and 0 <= f < 1, which are equal. The second is one high multiply on SSE2.
inline u16x8 div255_round(u16x8 x) {
  const u16x8 n = x + 128;
#if defined(__SSE2__)
  const u16x8 k257 = u16x8{} + 257;
  return reinterpret_cast<u16x8>(
      _mm_mulhi_epu16(reinterpret_cast<__m128i>(n), reinterpret_cast<__m128i>(k257)));
#else
  return (n + (n >> 8)) >> 8;
#endif
}

// The alpha lane of each of the two pixels of `v` (alpha at byte offset A) in all its lanes.
template <int A> inline u16x8 broadcast_alpha(u16x8 v) {
  return __builtin_shufflevector(v, v, A, A, A, A, 4 + A, 4 + A, 4 + A, 4 + A);
}

// SRC_ALPHA, ONE_MINUS_SRC_ALPHA, FUNC_ADD on every channel (alpha included):
// round((s a + d (255 - a)) / 255), as blend.h blend_over_channel.
template <int A> inline u16x8 blend_over_lanes(u16x8 s, u16x8 d) {
  const u16x8 a = broadcast_alpha<A>(s);
  return div255_round(s * a + d * (255 - a));
}

// Four pixels: s over d, alpha at byte offset A of each pixel.
template <int A> inline u32x4 blend_over4(u32x4 s, u32x4 d) {
  const u8x16 sb = reinterpret_cast<u8x16>(s), db = reinterpret_cast<u8x16>(d);
  const u16x8 lo = blend_over_lanes<A>(widen_lo(sb), widen_lo(db));
  const u16x8 hi = blend_over_lanes<A>(widen_hi(sb), widen_hi(db));
  return reinterpret_cast<u32x4>(narrow(lo, hi));
}

} // namespace pineda
