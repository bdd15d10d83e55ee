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

#include "fragment/blend.h"
#include "core/simd.h"

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

namespace pineda {

// Whether every factor of `bp` is a multiple of 1/255 of the unorm8 colours themselves (all but
// the constant-colour ones), so that blend_fixed_lanes reproduces blend_pixel exactly.
inline bool blend_params_fixed(const BlendParams& bp) {
  const auto ok = [](BlendFactor f) {
    return f != BlendFactor::ConstColor && f != BlendFactor::OneMinusConstColor &&
           f != BlendFactor::ConstAlpha && f != BlendFactor::OneMinusConstAlpha;
  };
  return ok(bp.src_rgb) && ok(bp.dst_rgb) && ok(bp.src_a) && ok(bp.dst_a);
}

// A factor of GL 2.1 table 4.2 times 255, on two pixels' lanes: s and d the colours, sa and da
// their alphas broadcast to every lane of the pixel. `alpha` selects the alpha-channel meaning
// of SRC_ALPHA_SATURATE (1); the colour factors need no such choice, since the alpha lane of s
// already holds the source alpha.
inline u16x8 factor_lanes(BlendFactor f, u16x8 s, u16x8 d, u16x8 sa, u16x8 da, bool alpha) {
  const u16x8 one = u16x8{} + 255;
  switch (f) {
  case BlendFactor::Zero:
    return u16x8{};
  case BlendFactor::One:
    return one;
  case BlendFactor::SrcColor:
    return s;
  case BlendFactor::OneMinusSrcColor:
    return one - s;
  case BlendFactor::DstColor:
    return d;
  case BlendFactor::OneMinusDstColor:
    return one - d;
  case BlendFactor::SrcAlpha:
    return sa;
  case BlendFactor::OneMinusSrcAlpha:
    return one - sa;
  case BlendFactor::DstAlpha:
    return da;
  case BlendFactor::OneMinusDstAlpha:
    return one - da;
  case BlendFactor::SrcAlphaSaturate: {
    if (alpha) return one;
    const u16x8 ida = one - da;
    return sa < ida ? sa : ida;
  }
  default:
    return one; // constant factors never come here (blend_params_fixed)
  }
}

// One equation (GL 2.1 table 4.1) on lanes, rounded as blend_pixel rounds: products of at
// most 255 * 255, their sum or difference clamped to [0, 255 * 255] (the float path clamps the
// result to [0, 1]) and divided by 255 with rounding; MIN and MAX take the colours themselves.
inline u16x8 equation_lanes(BlendEq eq, u16x8 s, u16x8 d, u16x8 fs, u16x8 fd) {
  const u16x8 ps = s * fs, pd = d * fd, cap = u16x8{} + 255 * 255;
  u16x8 n;
  switch (eq) {
  case BlendEq::Add:
    n = ps + pd;
    n = (n < ps || n > cap) ? cap : n; // a wrapped sum exceeded 65535
    break;
  case BlendEq::Subtract:
    n = ps > pd ? ps - pd : u16x8{};
    break;
  case BlendEq::ReverseSubtract:
    n = pd > ps ? pd - ps : u16x8{};
    break;
  case BlendEq::Min:
    return s < d ? s : d;
  case BlendEq::Max:
    return s > d ? s : d;
  default:
    n = ps;
    break;
  }
  return div255_round(n);
}

// Any blend blend_params_fixed accepts, on two pixels (alpha at byte offset A); `has_alpha`
// false makes destination alpha read as 1 (GL 2.1 §4.1.8).
template <int A>
inline u16x8 blend_fixed_lanes(const BlendParams& bp, bool has_alpha, u16x8 s, u16x8 d) {
  const u16x8 amask = {A == 0 ? 0xffff : 0, A == 1 ? 0xffff : 0, A == 2 ? 0xffff : 0,
                       A == 3 ? 0xffff : 0, A == 0 ? 0xffff : 0, A == 1 ? 0xffff : 0,
                       A == 2 ? 0xffff : 0, A == 3 ? 0xffff : 0};
  if (!has_alpha) d = (d & ~amask) | (amask & 255);
  const u16x8 sa = broadcast_alpha<A>(s), da = broadcast_alpha<A>(d);
  u16x8 fs = factor_lanes(bp.src_rgb, s, d, sa, da, false);
  u16x8 fd = factor_lanes(bp.dst_rgb, s, d, sa, da, false);
  if (bp.src_a != bp.src_rgb || bp.src_a == BlendFactor::SrcAlphaSaturate)
    fs = (fs & ~amask) | (factor_lanes(bp.src_a, s, d, sa, da, true) & amask);
  if (bp.dst_a != bp.dst_rgb || bp.dst_a == BlendFactor::SrcAlphaSaturate)
    fd = (fd & ~amask) | (factor_lanes(bp.dst_a, s, d, sa, da, true) & amask);
  const u16x8 out = equation_lanes(bp.eq_rgb, s, d, fs, fd);
  if (bp.eq_a == bp.eq_rgb) return out;
  return (out & ~amask) | (equation_lanes(bp.eq_a, s, d, fs, fd) & amask);
}

template <int A>
inline u32x4 blend_fixed4(const BlendParams& bp, bool has_alpha, u32x4 s, u32x4 d) {
  const u8x16 sb = reinterpret_cast<u8x16>(s), db = reinterpret_cast<u8x16>(d);
  const u16x8 lo = blend_fixed_lanes<A>(bp, has_alpha, widen_lo(sb), widen_lo(db));
  const u16x8 hi = blend_fixed_lanes<A>(bp, has_alpha, widen_hi(sb), widen_hi(db));
  return reinterpret_cast<u32x4>(narrow(lo, hi));
}

} // namespace pineda
