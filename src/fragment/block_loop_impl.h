// The specialized block loops of the per-fragment operations (GL 2.1 §4.1), written once for
// three instruction sets. fragment_ops.cpp includes this file for the baseline build (SSE2 on
// x86-64, NEON on AArch64), fragment_ops_avx2.cpp includes it again with PINEDA_BLOCK_AVX2
// set, inside a region compiled for AVX2, and fragment_ops_avx512.cpp with PINEDA_BLOCK_AVX2
// and PINEDA_BLOCK_AVX512 set, inside a region compiled for AVX-512. Everything here lives in
// an unnamed namespace, so each translation unit has its own instances and they never meet at
// link time.
//
// One block loop handles up to 8x8 fragments of one primitive, row by row: depth test and
// depth write for the covered fragments of the row (GL 2.1 §4.1.6), then colour
// (perspective-correct or constant), blending (§4.1.8) and the masked store (§4.2.2) for the
// fragments that survived. Every choice that depends on state is a template parameter; what
// is left at run time are values (blend factors, generic depth function, colour keep mask).
// The scissor test (§4.1.2) costs nothing here: it narrows the clip rectangle the
// rasterizers already respect. The alpha test (§4.1.4), the stencil test (§4.1.5) and the
// logical operation (§4.1.10) live in a second set of instances (template parameter X),
// chosen only when one of them is on, with a per-row branch for each.
//
// A block row of eight pixels is one Row: two 4-lane vectors in the baseline build, one
// 8-lane (256-bit) vector with AVX2. The code below is written on Row's parts and works for
// both; only the few functions whose instructions differ (lane masks, depth conversion,
// smooth colour packing, the 16-bit blend) have a version per instruction set, each doing
// exactly the same arithmetic per lane, so both builds give the same bytes. The AVX-512
// instances are the AVX2 ones with a few functions replaced (PINEDA_BLOCK_AVX512): coverage and
// depth-test results in opmask registers (masked moves, and masked loads and stores for the
// last block of a row, instead of lane masks, blends and loops over fragments), and 512-bit
// vectors where a row's work fits one (eight depth values as doubles, the colours of four
// pixels, a row's pixels widened to 16 bits for blending).
//
// Included only by those three files; it has no include guard on purpose.

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <utility>

#include "fragment/blend_simd.h"
#include "fragment/fragment_ops.h"
#include "fragment/shade.h"
#include "core/simd.h"

#ifndef PINEDA_BLOCK_AVX512
#define PINEDA_BLOCK_AVX512 0
#endif

#if PINEDA_BLOCK_AVX2
#include <immintrin.h>
#endif

namespace pineda {
namespace {

constexpr int N = kBlockSize;

#if PINEDA_BLOCK_AVX2
using u32x8 = uint32_t __attribute__((vector_size(32)));
using i32x8 = int32_t __attribute__((vector_size(32)));
using f32x8 = float __attribute__((vector_size(32)));
using u16x16 = uint16_t __attribute__((vector_size(32)));
#if PINEDA_BLOCK_AVX512
using f32x16 = float __attribute__((vector_size(64)));
using i32x16 = int32_t __attribute__((vector_size(64)));
using u32x16 = uint32_t __attribute__((vector_size(64)));
using f64x8 = double __attribute__((vector_size(64)));
using u16x32 = uint16_t __attribute__((vector_size(64)));
#endif
using LaneU = u32x8;
using LaneI = i32x8;
using LaneF = f32x8;
#else
using LaneU = u32x4;
using LaneI = i32x4;
using LaneF = f32x4;
#endif
constexpr int kLanes = static_cast<int>(sizeof(LaneU) / sizeof(uint32_t));
constexpr int kParts = N / kLanes;

// Eight packed pixels (or depth values) of one block row, in memory order.
struct Row {
  LaneU v[kParts];
};
// Lane masks (all ones / zero) of one block row.
struct RowMask {
  LaneI v[kParts];
};

// Rows move to and from memory part by part: GCC copies a whole Row (a struct) through the
// stack, which stalls the 256-bit loads that follow two 128-bit stores.
inline Row row_load(const void* p) {
  Row r;
  for (int h = 0; h < kParts; ++h)
    std::memcpy(&r.v[h], static_cast<const char*>(p) + sizeof(LaneU) * h, sizeof(LaneU));
  return r;
}
inline void row_store(void* p, const Row& r) {
  for (int h = 0; h < kParts; ++h)
    std::memcpy(static_cast<char*>(p) + sizeof(LaneU) * h, &r.v[h], sizeof(LaneU));
}

inline uint32_t row_lane(const Row& r, int i) {
  return r.v[i / kLanes][i % kLanes];
}

inline Row row_splat(uint32_t x) {
  Row r;
  for (int h = 0; h < kParts; ++h)
    r.v[h] = LaneU{} + x;
  return r;
}

using pineda::vmax;
using pineda::vmin;

#if PINEDA_BLOCK_AVX2

// Eight bits to lane masks, and back (the lanes' sign bits).
inline RowMask row_mask(unsigned m) {
  const i32x8 bit = {1, 2, 4, 8, 16, 32, 64, 128};
  return RowMask{{((i32x8{} + static_cast<int32_t>(m)) & bit) != 0}};
}
inline unsigned mask_bits(const RowMask& m) {
  return static_cast<unsigned>(
      _mm256_movemask_ps(_mm256_castsi256_ps(reinterpret_cast<__m256i>(m.v[0]))));
}

// The SSE max/min semantics of simd.h vmax/vmin (b where a lane is NaN), eight lanes.
inline f32x8 vmax(f32x8 a, f32x8 b) {
  return _mm256_max_ps(a, b);
}
inline f32x8 vmin(f32x8 a, f32x8 b) {
  return _mm256_min_ps(a, b);
}
inline f64x4 vmax(f64x4 a, f64x4 b) {
  return _mm256_max_pd(a, b);
}
inline f64x4 vmin(f64x4 a, f64x4 b) {
  return _mm256_min_pd(a, b);
}
#if PINEDA_BLOCK_AVX512
// The AVX-512 intrinsics below are the zero-masking forms with every lane selected (the same
// instructions): GCC 12 warns about the undefined pass-through operand of the plain forms
// (-Wmaybe-uninitialized).
inline f32x16 vmax(f32x16 a, f32x16 b) {
  return _mm512_maskz_max_ps(0xffff, a, b);
}
inline f32x16 vmin(f32x16 a, f32x16 b) {
  return _mm512_maskz_min_ps(0xffff, a, b);
}
inline f64x8 vmax(f64x8 a, f64x8 b) {
  return _mm512_maskz_max_pd(0xff, a, b);
}
inline f64x8 vmin(f64x8 a, f64x8 b) {
  return _mm512_maskz_min_pd(0xff, a, b);
}
#endif

#else

inline RowMask row_mask(unsigned m) {
  RowMask r;
  bits_to_lanes(m, r.v[0], r.v[1]);
  return r;
}
inline unsigned mask_bits(const RowMask& m) {
  return lane_bits(m.v[0], m.v[1]);
}

#endif

// Byte offsets of R, G, B, A inside one stored pixel (framebuffer.h ColorFormat).
template <ColorFormat F> struct Layout;
template <> struct Layout<ColorFormat::RGBA8> {
  static constexpr int r = 0, g = 1, b = 2, a = 3, bpp = 4;
};
template <> struct Layout<ColorFormat::BGRA8> {
  static constexpr int r = 2, g = 1, b = 0, a = 3, bpp = 4;
};
template <> struct Layout<ColorFormat::ARGB8> {
  static constexpr int r = 1, g = 2, b = 3, a = 0, bpp = 4;
};
template <> struct Layout<ColorFormat::RGB8> {
  static constexpr int r = 0, g = 1, b = 2, a = -1, bpp = 3;
};

// Shift of the byte at memory offset `off` within a 4-byte pixel read with memcpy.
constexpr int byte_shift(int off) {
  return std::endian::native == std::endian::little ? 8 * off : 8 * (3 - off);
}

template <ColorFormat F> uint32_t pack_pixel(uint32_t r, uint32_t g, uint32_t b, uint32_t a) {
  using L = Layout<F>;
  return r << byte_shift(L::r) | g << byte_shift(L::g) | b << byte_shift(L::b) |
         a << byte_shift(L::a);
}

template <ColorFormat F> LaneU pack_lanes(LaneI r, LaneI g, LaneI b, LaneI a) {
  using L = Layout<F>;
  return reinterpret_cast<LaneU>(r) << byte_shift(L::r) |
         reinterpret_cast<LaneU>(g) << byte_shift(L::g) |
         reinterpret_cast<LaneU>(b) << byte_shift(L::b) |
         reinterpret_cast<LaneU>(a) << byte_shift(L::a);
}

// Clamp to [0,1] and round to 8 bits (GL 2.1 §2.14.9); NaN from a degenerate 1/w gives 0.
inline LaneI to_unorm8(LaneF v) {
  const LaneF zero = {}, one = zero + 1.0f;
  v = vmin(vmax(v, zero), one);
  return __builtin_convertvector(v * 255.0f + 0.5f, LaneI);
}
#if PINEDA_BLOCK_AVX512
// The same on sixteen lanes (the four channels of four pixels).
inline i32x16 to_unorm8(f32x16 v) {
  const f32x16 zero = {}, one = zero + 1.0f;
  v = vmin(vmax(v, zero), one);
  return __builtin_convertvector(v * 255.0f + 0.5f, i32x16);
}
#endif

// One block row of the colours shade_block computed (ShadePath::PerFragment).
template <ColorFormat P> void per_fragment_row(const float (*sc)[64], int j, Row& out) {
#if PINEDA_BLOCK_AVX512
  // Two channels per register (R and G, B and A, eight pixels each), each half shifted to its
  // byte and the halves merged.
  using L = Layout<P>;
  const auto pair = [&](int c0, int c1) {
    __m256 lo, hi;
    std::memcpy(&lo, &sc[c0][8 * j], sizeof lo);
    std::memcpy(&hi, &sc[c1][8 * j], sizeof hi);
    return f32x16(
        _mm512_mask_broadcast_f32x8(_mm512_maskz_broadcast_f32x8(0x00ff, lo), 0xff00, hi));
  };
  constexpr int sr = byte_shift(L::r), sg = byte_shift(L::g), sb = byte_shift(L::b),
                sa = byte_shift(L::a);
  const u32x16 shift_rg = {sr, sr, sr, sr, sr, sr, sr, sr, sg, sg, sg, sg, sg, sg, sg, sg};
  const u32x16 shift_ba = {sb, sb, sb, sb, sb, sb, sb, sb, sa, sa, sa, sa, sa, sa, sa, sa};
  const u32x16 t = (reinterpret_cast<u32x16>(to_unorm8(pair(0, 1))) << shift_rg) |
                   (reinterpret_cast<u32x16>(to_unorm8(pair(2, 3))) << shift_ba);
  out.v[0] = __builtin_shufflevector(t, t, 0, 1, 2, 3, 4, 5, 6, 7) |
             __builtin_shufflevector(t, t, 8, 9, 10, 11, 12, 13, 14, 15);
#else
  for (int h = 0; h < kParts; ++h) {
    LaneF ch[4];
    for (int c = 0; c < 4; ++c)
      std::memcpy(&ch[c], &sc[c][8 * j + kLanes * h], sizeof(LaneF));
    out.v[h] =
        pack_lanes<P>(to_unorm8(ch[0]), to_unorm8(ch[1]), to_unorm8(ch[2]), to_unorm8(ch[3]));
  }
#endif
}

#if PINEDA_BLOCK_AVX512
// The channel (0 R, 1 G, 2 B, 3 A) stored at byte k of a pixel of layout L.
template <class L> constexpr int channel_at(int k) {
  return L::r == k ? 0 : L::g == k ? 1 : L::b == k ? 2 : 3;
}
#endif

// The colour planes of a smoothly shaded primitive with lane k holding the channel stored at
// byte k of a pixel in the packed format P, and each pixel's offset i * dx from its row's start:
// set up once per block, so that a row is computed pixel by pixel with the four channels in
// one vector and packed with a few instructions.
template <ColorFormat P> struct SmoothPlanes {
  f32x4 v0 = {}, dx = {}, dy = {};
#if PINEDA_BLOCK_AVX512
  f32x16 step[2] = {}; // pixels 4k .. 4k + 3 of a row: i * dx for i = 4k + q in lanes 4q ..
#elif PINEDA_BLOCK_AVX2
  f32x8 step[N / 2] = {}; // pixels k and k + 4 of a row: i * dx for i = k (low), k + 4 (high)
#else
  f32x4 step[N] = {};
#endif
  // 1/w is exactly 1 everywhere (no perspective, w = 1): then every w below is exactly 1 and
  // dividing and multiplying by it change nothing, so both are skipped.
  bool unit_w = true;

  void init(const FragInputs& in) {
    using L = Layout<P>;
#if PINEDA_BLOCK_AVX512
    // The channels put in place by a constant shuffle: with AVX-512, GCC 12 turns the stores
    // to variable lanes of the loop below into scatters, which are slow and stall the loads
    // that follow.
    constexpr int at[4] = {channel_at<L>(0), channel_at<L>(1), channel_at<L>(2), channel_at<L>(3)};
    const PlaneF* cw = in.color_w;
    const f32x4 rv = {cw[0].v0, cw[1].v0, cw[2].v0, cw[3].v0};
    const f32x4 rx = {cw[0].dx, cw[1].dx, cw[2].dx, cw[3].dx};
    const f32x4 ry = {cw[0].dy, cw[1].dy, cw[2].dy, cw[3].dy};
    v0 = __builtin_shufflevector(rv, rv, at[0], at[1], at[2], at[3]);
    dx = __builtin_shufflevector(rx, rx, at[0], at[1], at[2], at[3]);
    dy = __builtin_shufflevector(ry, ry, at[0], at[1], at[2], at[3]);
#else
    const int offs[4] = {L::r, L::g, L::b, L::a};
    for (int c = 0; c < 4; ++c) {
      v0[offs[c]] = in.color_w[c].v0;
      dx[offs[c]] = in.color_w[c].dx;
      dy[offs[c]] = in.color_w[c].dy;
    }
#endif
#if PINEDA_BLOCK_AVX512
    const f32x16 dx4 = _mm512_maskz_broadcast_f32x4(0xffff, dx);
    for (int k = 0; k < 2; ++k) {
      const auto p0 = static_cast<float>(4 * k), p1 = p0 + 1.0f, p2 = p0 + 2.0f, p3 = p0 + 3.0f;
      step[k] = f32x16{p0, p0, p0, p0, p1, p1, p1, p1, p2, p2, p2, p2, p3, p3, p3, p3} * dx4;
    }
#elif PINEDA_BLOCK_AVX2
    const f32x8 dx2 = __builtin_shufflevector(dx, dx, 0, 1, 2, 3, 0, 1, 2, 3);
    for (int k = 0; k < N / 2; ++k) {
      const auto lo = static_cast<float>(k), hi = static_cast<float>(k + 4);
      step[k] = f32x8{lo, lo, lo, lo, hi, hi, hi, hi} * dx2;
    }
#else
    for (int i = 0; i < N; ++i)
      step[i] = static_cast<float>(i) * dx;
#endif
    unit_w = in.inv_w.v0 == 1.0f && in.inv_w.dx == 0.0f && in.inv_w.dy == 0.0f;
  }
};

// Perspective-correct colour of one block row (GL 2.1 §3.5.1 eq 3.9): c = (c/w) / (1/w), each
// channel of the pixel at (ox + di + i, oy + dj) computed as ((v0 + di dx + dj dy) + i dx) w.
template <ColorFormat P>
[[gnu::always_inline]] inline void shade_row(const SmoothPlanes<P>& sp, const FragInputs& in,
                                             int di, int dj, Row& out) {
  const float fi = static_cast<float>(di), fj = static_cast<float>(dj);
  const f32x4 cr = sp.v0 + fi * sp.dx + fj * sp.dy;
#if PINEDA_BLOCK_AVX512
  // Four pixels' channels in one vector, in memory order: converting each lane to a byte
  // (vpmovdb) leaves four packed pixels, two conversions the row.
  // Broadcasts and lane permutes by intrinsic: GCC 12 widens a 128- or 256-bit vector with
  // __builtin_shufflevector through the stack, and the 512-bit reload stalls on forwarding.
  const f32x16 cr4 = _mm512_maskz_broadcast_f32x4(0xffff, cr);
  i32x16 px[2];
  if (sp.unit_w) {
    for (int k = 0; k < 2; ++k)
      px[k] = to_unorm8(cr4 + sp.step[k]);
  } else {
    const PlaneF iw = in.inv_w;
    const float iwr = iw.v0 + fi * iw.dx + fj * iw.dy;
    const f32x8 lane = {0, 1, 2, 3, 4, 5, 6, 7};
    const f32x8 w = 1.0f / (iwr + lane * iw.dx);
    const __m512 w16 = _mm512_maskz_broadcast_f32x8(0xffff, w);
    const f32x16 wk[2] = {
        _mm512_maskz_permutexvar_ps(
            0xffff, _mm512_setr_epi32(0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3), w16),
        _mm512_maskz_permutexvar_ps(
            0xffff, _mm512_setr_epi32(4, 4, 4, 4, 5, 5, 5, 5, 6, 6, 6, 6, 7, 7, 7, 7), w16),
    };
    for (int k = 0; k < 2; ++k)
      px[k] = to_unorm8((cr4 + sp.step[k]) * wk[k]);
  }
  out.v[0] = reinterpret_cast<u32x8>(
      _mm256_set_m128i(_mm512_maskz_cvtepi32_epi8(0xffff, reinterpret_cast<__m512i>(px[1])),
                       _mm512_maskz_cvtepi32_epi8(0xffff, reinterpret_cast<__m512i>(px[0]))));
#elif PINEDA_BLOCK_AVX2
  // Pixels k (low half) and k + 4 (high half) in one vector: the in-lane packs below then
  // leave the eight pixels in order.
  const f32x8 cr2 = __builtin_shufflevector(cr, cr, 0, 1, 2, 3, 0, 1, 2, 3);
  i32x8 px[N / 2];
  if (sp.unit_w) {
    for (int k = 0; k < N / 2; ++k)
      px[k] = to_unorm8(cr2 + sp.step[k]);
  } else {
    const PlaneF iw = in.inv_w;
    const float iwr = iw.v0 + fi * iw.dx + fj * iw.dy;
    const f32x8 lane = {0, 1, 2, 3, 4, 5, 6, 7};
    const f32x8 w = 1.0f / (iwr + lane * iw.dx);
    const f32x8 wk[N / 2] = {
        __builtin_shufflevector(w, w, 0, 0, 0, 0, 4, 4, 4, 4),
        __builtin_shufflevector(w, w, 1, 1, 1, 1, 5, 5, 5, 5),
        __builtin_shufflevector(w, w, 2, 2, 2, 2, 6, 6, 6, 6),
        __builtin_shufflevector(w, w, 3, 3, 3, 3, 7, 7, 7, 7),
    };
    for (int k = 0; k < N / 2; ++k)
      px[k] = to_unorm8((cr2 + sp.step[k]) * wk[k]);
  }
  const __m256i a = _mm256_packs_epi32(reinterpret_cast<__m256i>(px[0]),
                                       reinterpret_cast<__m256i>(px[1])); // 0 1 | 4 5
  const __m256i b = _mm256_packs_epi32(reinterpret_cast<__m256i>(px[2]),
                                       reinterpret_cast<__m256i>(px[3])); // 2 3 | 6 7
  out.v[0] = reinterpret_cast<u32x8>(_mm256_packus_epi16(a, b));
#else
  constexpr f32x4 kLaneLo = {0, 1, 2, 3};
  constexpr f32x4 kLaneHi = {4, 5, 6, 7};
  i32x4 px[N];
  if (sp.unit_w) {
    for (int i = 0; i < N; ++i)
      px[i] = to_unorm8(cr + sp.step[i]);
  } else {
    const PlaneF iw = in.inv_w;
    const float iwr = iw.v0 + fi * iw.dx + fj * iw.dy;
    const f32x4 w[2] = {1.0f / (iwr + kLaneLo * iw.dx), 1.0f / (iwr + kLaneHi * iw.dx)};
    for (int i = 0; i < N; ++i)
      px[i] = to_unorm8((cr + sp.step[i]) * w[i >> 2][i & 3]);
  }
  out.v[0] = pack_pixels(px[0], px[1], px[2], px[3]);
  out.v[1] = pack_pixels(px[4], px[5], px[6], px[7]);
#endif
}

#if PINEDA_BLOCK_AVX512
// Eight pixels: s over d, alpha at byte offset A (blend_simd.h blend_over_lanes), the row's 32
// channels widened to 16-bit lanes of one vector and narrowed back with vpmovwb.
template <int A> inline u32x8 blend_over8(u32x8 s, u32x8 d) {
  const u16x32 sv = reinterpret_cast<u16x32>(_mm512_cvtepu8_epi16(reinterpret_cast<__m256i>(s)));
  const u16x32 dv = reinterpret_cast<u16x32>(_mm512_cvtepu8_epi16(reinterpret_cast<__m256i>(d)));
  const u16x32 a = __builtin_shufflevector(
      sv, sv, A, A, A, A, 4 + A, 4 + A, 4 + A, 4 + A, 8 + A, 8 + A, 8 + A, 8 + A, 12 + A, 12 + A,
      12 + A, 12 + A, 16 + A, 16 + A, 16 + A, 16 + A, 20 + A, 20 + A, 20 + A, 20 + A, 24 + A,
      24 + A, 24 + A, 24 + A, 28 + A, 28 + A, 28 + A, 28 + A);
  const u16x32 n = sv * a + dv * (255 - a) + 128;
  const u16x32 k257 = u16x32{} + 257;
  return reinterpret_cast<u32x8>(
      _mm512_maskz_cvtepi16_epi8(0xffffffffu, _mm512_mulhi_epu16(reinterpret_cast<__m512i>(n),
                                                                 reinterpret_cast<__m512i>(k257))));
}
#elif PINEDA_BLOCK_AVX2
// blend_simd.h blend_over_lanes on sixteen 16-bit lanes (four pixels, two per 128-bit half).
template <int A> inline u16x16 blend_over_lanes16(u16x16 s, u16x16 d) {
  const u16x16 a = __builtin_shufflevector(s, s, A, A, A, A, 4 + A, 4 + A, 4 + A, 4 + A, 8 + A,
                                           8 + A, 8 + A, 8 + A, 12 + A, 12 + A, 12 + A, 12 + A);
  const u16x16 n = s * a + d * (255 - a) + 128;
  const u16x16 k257 = u16x16{} + 257;
  return reinterpret_cast<u16x16>(
      _mm256_mulhi_epu16(reinterpret_cast<__m256i>(n), reinterpret_cast<__m256i>(k257)));
}

// Eight pixels: s over d, alpha at byte offset A. The in-lane unpacks take pixels 0 1 | 4 5
// and 2 3 | 6 7, which the in-lane pack puts back in order.
template <int A> inline u32x8 blend_over8(u32x8 s, u32x8 d) {
  const __m256i z = _mm256_setzero_si256();
  const __m256i sv = reinterpret_cast<__m256i>(s), dv = reinterpret_cast<__m256i>(d);
  const u16x16 lo = blend_over_lanes16<A>(reinterpret_cast<u16x16>(_mm256_unpacklo_epi8(sv, z)),
                                          reinterpret_cast<u16x16>(_mm256_unpacklo_epi8(dv, z)));
  const u16x16 hi = blend_over_lanes16<A>(reinterpret_cast<u16x16>(_mm256_unpackhi_epi8(sv, z)),
                                          reinterpret_cast<u16x16>(_mm256_unpackhi_epi8(dv, z)));
  return reinterpret_cast<u32x8>(
      _mm256_packus_epi16(reinterpret_cast<__m256i>(lo), reinterpret_cast<__m256i>(hi)));
}
#endif

// SRC_ALPHA, ONE_MINUS_SRC_ALPHA, FUNC_ADD in exact unorm8 (blend.h blend_over_channel) in
// 16-bit lanes (blend_simd.h).
template <ColorFormat F> inline void blend_over_row(Row& s, const Row& d) {
#if PINEDA_BLOCK_AVX2
  s.v[0] = blend_over8<Layout<F>::a>(s.v[0], d.v[0]);
#else
  for (int h = 0; h < 2; ++h)
    s.v[h] = blend_over4<Layout<F>::a>(s.v[h], d.v[h]);
#endif
}

template <ColorFormat F> void unpack_pixel(uint32_t px, bool has_alpha, uint8_t c[4]) {
  using L = Layout<F>;
  c[0] = static_cast<uint8_t>(px >> byte_shift(L::r));
  c[1] = static_cast<uint8_t>(px >> byte_shift(L::g));
  c[2] = static_cast<uint8_t>(px >> byte_shift(L::b));
  // Without alpha bits, destination alpha reads as 1 (GL 2.1 §4.1.8).
  c[3] = has_alpha ? static_cast<uint8_t>(px >> byte_shift(L::a)) : 255;
}

// Any other blend: factors without the constant colour in 16-bit lanes (blend_simd.h, the
// same bytes as blend_pixel), four pixels at a time; the others one fragment at a time through
// blend_pixel (float).
template <ColorFormat F>
void blend_generic_row(const FragCtx& ctx, unsigned m, Row& s, const Row& d) {
  alignas(32) uint32_t sp[N], dp[N];
  row_store(sp, s);
  row_store(dp, d);
  if (ctx.blend_fixed) {
    for (int h = 0; h < 2; ++h) {
      u32x4 sv, dv;
      std::memcpy(&sv, sp + 4 * h, sizeof(sv));
      std::memcpy(&dv, dp + 4 * h, sizeof(dv));
      sv = blend_fixed4<Layout<F>::a>(ctx.blend, ctx.key.has_alpha, sv, dv);
      std::memcpy(sp + 4 * h, &sv, sizeof(sv));
    }
  } else {
    for (int i = 0; i < N; ++i) {
      if (((m >> i) & 1u) == 0) continue;
      uint8_t sc[4], dc[4], oc[4];
      unpack_pixel<F>(sp[i], true, sc);
      unpack_pixel<F>(dp[i], ctx.key.has_alpha, dc);
      blend_pixel(ctx.blend, sc, dc, oc);
      sp[i] = pack_pixel<F>(oc[0], oc[1], oc[2], oc[3]);
    }
  }
  s = row_load(sp);
}

// The plane's z at the eight pixels (ox + di + i, oy + dj) in depth-buffer units, clamped to
// [0, 2^bits - 1] (window z clamped to [0,1], GL 2.1 §2.11.1) and rounded to the nearest
// representable value. The values are non-negative, so truncation is the floor. Below 2^31 the
// conversion is the packed one; 32-bit buffers convert lane by lane.
[[gnu::always_inline]] inline Row depth_values(const FragCtx& ctx, const PlaneD& zp, int di,
                                               int dj) {
  const double zr = zp.v0 + di * zp.dx + dj * zp.dy;
  Row zv;
#if PINEDA_BLOCK_AVX512
  // The row in one vector of doubles; the unsigned conversion covers 32-bit buffers too (the
  // values lie in [0.5, 2^32 - 0.5], where truncating to uint32 is what the int32 or int64
  // conversions of the other builds give).
  const f64x8 zero = {}, zmax = zero + ctx.depth_max;
  const f64x8 lane = {0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0};
  const f64x8 z = zr + lane * zp.dx;
  const f64x8 zc = vmin(vmax(z, zero), zmax) + 0.5;
  zv.v[0] = reinterpret_cast<u32x8>(_mm512_maskz_cvttpd_epu32(0xff, reinterpret_cast<__m512d>(zc)));
#elif PINEDA_BLOCK_AVX2
  const f64x4 zero = {}, zmax = zero + ctx.depth_max;
  f64x4 zc[2];
  for (int h = 0; h < 2; ++h) {
    const f64x4 lane = {4.0 * h, 4.0 * h + 1.0, 4.0 * h + 2.0, 4.0 * h + 3.0};
    const f64x4 z = zr + lane * zp.dx;
    zc[h] = vmin(vmax(z, zero), zmax) + 0.5;
  }
  if (ctx.depth_max < 2147483648.0) {
    const i32x4 lo = __builtin_convertvector(zc[0], i32x4);
    const i32x4 hi = __builtin_convertvector(zc[1], i32x4);
    zv.v[0] = reinterpret_cast<u32x8>(__builtin_shufflevector(lo, hi, 0, 1, 2, 3, 4, 5, 6, 7));
  } else {
    for (int l = 0; l < N; ++l)
      zv.v[0][l] = static_cast<uint32_t>(static_cast<int64_t>(zc[l >> 2][l & 3]));
  }
#else
  const f64x2 zero = {}, zmax = zero + ctx.depth_max;
  f64x2 zc[N / 2];
  for (int h = 0; h < N / 2; ++h) {
    const f64x2 lane = {2.0 * h, 2.0 * h + 1.0};
    const f64x2 z = zr + lane * zp.dx;
    zc[h] = vmin(vmax(z, zero), zmax) + 0.5;
  }
  if (ctx.depth_max < 2147483648.0) {
    for (int k = 0; k < 2; ++k)
      zv.v[k] = reinterpret_cast<u32x4>(__builtin_convertvector(
          __builtin_shufflevector(zc[2 * k], zc[2 * k + 1], 0, 1, 2, 3), i32x4));
  } else {
    for (int k = 0; k < 2; ++k)
      for (int l = 0; l < 4; ++l)
        zv.v[k][l] = static_cast<uint32_t>(static_cast<int64_t>(zc[2 * k + l / 2][l & 1]));
  }
#endif
  return zv;
}

// Depth test and write of one row of a block (GL 2.1 §4.1.6). Returns the fragments of `m`
// that passed. `zrow`, when set, holds the row's depth values as the fragment shader wrote them
// (gl_FragDepth, §3.11.2) in place of the primitive's.
template <DepthPath D>
[[gnu::always_inline]] inline unsigned depth_row(const FragCtx& ctx, const FragInputs& in, int bx,
                                                 int y, int di, int dj, unsigned m,
                                                 const uint32_t* zrow = nullptr) {
  uint32_t* const d = ctx.depth + static_cast<ptrdiff_t>(y) * ctx.depth_stride + bx;
  const Row zv = zrow != nullptr ? row_load(zrow) : depth_values(ctx, in.z, di, dj);
  const bool write = D != DepthPath::Generic || ctx.depth_write;
#if PINEDA_BLOCK_AVX512
  // Coverage and result as opmasks, the stored values kept by a masked move. Rows inside the
  // buffer are loaded and stored whole, as in the AVX2 instances (masked stores there measured
  // no faster on Zen 4: one thread, blend_heavy 29.1 against 29.3 ms, tiny_tris 25.2 against
  // 24.5 ms). The last block of a row whose width is not a multiple of 8 uses masked loads and
  // stores (masked-off lanes do not fault) instead of a loop over its fragments.
  const __m256i z = reinterpret_cast<__m256i>(zv.v[0]);
  const auto k = static_cast<__mmask8>(m);
  const bool whole = bx + N <= ctx.fb_width;
  __m256i old;
  if (whole)
    std::memcpy(&old, d, sizeof old);
  else
    old = _mm256_maskz_loadu_epi32(k, d);
  unsigned bits;
  if constexpr (D == DepthPath::LessWrite) {
    bits = _mm256_mask_cmplt_epu32_mask(k, z, old);
  } else if constexpr (D == DepthPath::LequalWrite) {
    bits = _mm256_mask_cmple_epu32_mask(k, z, old);
  } else {
    const unsigned f = ctx.depth_func;
    bits = (_mm256_mask_cmplt_epu32_mask(k, z, old) & (0u - (f & 1u))) |
           (_mm256_mask_cmpeq_epu32_mask(k, z, old) & (0u - ((f >> 1) & 1u))) |
           (_mm256_mask_cmpgt_epu32_mask(k, z, old) & (0u - ((f >> 2) & 1u)));
  }
  if (write && bits != 0) {
    if (whole) {
      const __m256i merged = _mm256_mask_mov_epi32(old, static_cast<__mmask8>(bits), z);
      std::memcpy(d, &merged, sizeof merged);
    } else {
      _mm256_mask_storeu_epi32(d, static_cast<__mmask8>(bits), z);
    }
  }
  return bits;
#else
  if (bx + N <= ctx.fb_width) {
    // The whole row lies in the buffer: test all eight lanes and keep the covered ones.
    Row old = row_load(d);
    RowMask pass = row_mask(m);
    for (int h = 0; h < kParts; ++h) {
      if constexpr (D == DepthPath::LessWrite) {
        pass.v[h] &= zv.v[h] < old.v[h];
      } else if constexpr (D == DepthPath::LequalWrite) {
        pass.v[h] &= zv.v[h] <= old.v[h];
      } else {
        const LaneI f = {}, lt = f - static_cast<int32_t>(ctx.depth_func & 1u);
        const LaneI eq = f - static_cast<int32_t>((ctx.depth_func >> 1) & 1u);
        const LaneI gt = f - static_cast<int32_t>((ctx.depth_func >> 2) & 1u);
        pass.v[h] &= ((zv.v[h] < old.v[h]) & lt) | ((zv.v[h] == old.v[h]) & eq) |
                     ((zv.v[h] > old.v[h]) & gt);
      }
    }
    const unsigned bits = mask_bits(pass);
    if (write && bits != 0) {
      for (int h = 0; h < kParts; ++h)
        old.v[h] = pass.v[h] ? zv.v[h] : old.v[h];
      row_store(d, old);
    }
    return bits;
  }
  // The last block of a row whose width is not a multiple of 8: fragment by fragment.
  unsigned bits = 0;
  for (int i = 0; i < N; ++i) {
    if (((m >> i) & 1u) == 0) continue;
    const uint32_t z = row_lane(zv, i);
    bool pass;
    if constexpr (D == DepthPath::LessWrite) {
      pass = z < d[i];
    } else if constexpr (D == DepthPath::LequalWrite) {
      pass = z <= d[i];
    } else {
      const unsigned rel = z < d[i] ? 1u : (z == d[i] ? 2u : 4u);
      pass = (ctx.depth_func & rel) != 0;
    }
    if (pass) {
      bits |= 1u << i;
      if (write) d[i] = z;
    }
  }
  return bits;
#endif
}

// The depth test (GL 2.1 §4.1.6) of a fully covered block at once: true when no fragment of
// the block at (bx, by) can pass, so that the block loop can drop the block before any other
// work. It reads the depth buffer itself and keeps no state, so every other writer of the
// buffer (clears, DrawPixels, CopyPixels, other draws) is seen as it is.
//
// Each fragment's stored-format z is q(z) = trunc(clamp(z, 0, max) + 0.5) of the plane value
// z computed in depth_values, and q is non-decreasing. Over the block the plane's exact values
// lie between its values at two corners; the computed ones differ from the exact ones by a few
// rounding errors of the terms' magnitudes (at most 2^-49 of their sum here), which the margin
// covers. So every fragment's value is at least q(lo) and at most q(hi): with LESS all fail
// when no stored value exceeds q(lo), with LEQUAL when all are below it, and GREATER and
// GEQUAL mirror that with q(hi). Other functions (and non-finite planes) never skip.
template <DepthPath D>
inline bool block_fails_depth(const FragCtx& ctx, const FragInputs& in, int bx, int by) {
  const unsigned func = D == DepthPath::LessWrite     ? 1u
                        : D == DepthPath::LequalWrite ? 3u
                                                      : ctx.depth_func;
  const bool below = func == 1u || func == 3u; // LESS, LEQUAL
  if (!below && func != 4u && func != 6u) return false;
  const PlaneD zp = in.z;
  const double a = zp.v0, b = (bx - in.ox) * zp.dx, c = (by - in.oy) * zp.dy;
  const double ex = (N - 1) * zp.dx, ey = (N - 1) * zp.dy;
  const double size = std::fabs(a) + std::fabs(b) + std::fabs(c) + std::fabs(ex) + std::fabs(ey);
  if (!(size < 1e300)) return false;
  const double margin = size * 0x1p-40;
  const double z = below ? a + b + c + std::min(ex, 0.0) + std::min(ey, 0.0) - margin
                         : a + b + c + std::max(ex, 0.0) + std::max(ey, 0.0) + margin;
  const double zc = std::min(std::max(z, 0.0), ctx.depth_max) + 0.5;
  const uint32_t q = ctx.depth_max < 2147483648.0 ? static_cast<uint32_t>(static_cast<int32_t>(zc))
                                                  : static_cast<uint32_t>(static_cast<int64_t>(zc));
  // The largest (LESS, LEQUAL) or smallest (GREATER, GEQUAL) stored value of the block.
  const uint32_t* d = ctx.depth + static_cast<ptrdiff_t>(by) * ctx.depth_stride + bx;
  Row acc = row_load(d);
  for (int j = 1; j < N; ++j) {
    const Row r = row_load(d + j * ctx.depth_stride);
    for (int h = 0; h < kParts; ++h)
      acc.v[h] =
          below ? (acc.v[h] > r.v[h] ? acc.v[h] : r.v[h]) : (acc.v[h] < r.v[h] ? acc.v[h] : r.v[h]);
  }
  const LaneU qv = LaneU{} + q;
  RowMask pass;
  for (int h = 0; h < kParts; ++h) {
    switch (func) {
    case 1u:
      pass.v[h] = acc.v[h] > qv;
      break;
    case 3u:
      pass.v[h] = acc.v[h] >= qv;
      break;
    case 4u:
      pass.v[h] = acc.v[h] < qv;
      break;
    default:
      pass.v[h] = acc.v[h] <= qv;
      break;
    }
  }
  return mask_bits(pass) == 0;
}

// Alpha test of one row (GL 2.1 §4.1.4): the fragment alpha as the 8-bit value it would be
// stored as, against the reference converted the same way, which is what llvmpipe compares
// (a float comparison gives different results for alphas within half a step of the
// reference). Returns the fragments of `m` that pass.
template <ColorFormat P> unsigned alpha_row(const FragCtx& ctx, const Row& s, unsigned m) {
  const LaneI f = {}, ref = f + static_cast<int32_t>(ctx.alpha_ref);
  const LaneI lt = f - static_cast<int32_t>(ctx.alpha_func & 1u);
  const LaneI eq = f - static_cast<int32_t>((ctx.alpha_func >> 1) & 1u);
  const LaneI gt = f - static_cast<int32_t>((ctx.alpha_func >> 2) & 1u);
  RowMask pass;
  for (int h = 0; h < kParts; ++h) {
    const LaneI a = reinterpret_cast<LaneI>((s.v[h] >> byte_shift(Layout<P>::a)) & 0xffu);
    pass.v[h] = ((a < ref) & lt) | ((a == ref) & eq) | ((a > ref) & gt);
  }
  return m & mask_bits(pass);
}

// Stencil test of one row (GL 2.1 §4.1.5), the depth test of the survivors (§4.1.6), and the
// stencil update chosen by the outcome of both: sfail where the stencil test failed, dpfail
// where the depth test failed, dppass where both passed (or the depth test is off, which
// counts as passing). Returns the fragments that passed both tests.
template <DepthPath D>
unsigned stencil_depth_row(const FragCtx& ctx, const FragInputs& in, int bx, int y, int di, int dj,
                           unsigned m, const uint32_t* zrow) {
  uint8_t* const st = ctx.stencil + static_cast<ptrdiff_t>(y) * ctx.stencil_stride + bx;
  // Whole rows inside the buffer are loaded and stored as eight bytes; the last block of a
  // row whose width is not a multiple of 8 touches only its fragments.
  const bool whole = bx + N <= ctx.fb_width;
  uint8_t old[N] = {};
  if (whole) {
    std::memcpy(old, st, N);
  } else {
    for (int i = 0; i < N; ++i)
      if ((m >> i) & 1u) old[i] = st[i];
  }
  const StencilSide& side = ctx.stencil_side[in.back_facing];
  const i32x4 v[2] = {{old[0], old[1], old[2], old[3]}, {old[4], old[5], old[6], old[7]}};
  const i32x4 zero = {}, vm = zero + side.value_mask, ref = zero + side.ref;
  const i32x4 masked_ref = ref & vm;
  const i32x4 lt = zero - static_cast<int32_t>(side.func & 1u);
  const i32x4 eq = zero - static_cast<int32_t>((side.func >> 1) & 1u);
  const i32x4 gt = zero - static_cast<int32_t>((side.func >> 2) & 1u);
  i32x4 pass[2];
  for (int h = 0; h < 2; ++h) {
    const i32x4 sv = v[h] & vm;
    pass[h] = ((masked_ref < sv) & lt) | ((masked_ref == sv) & eq) | ((masked_ref > sv) & gt);
  }
  const unsigned spass = m & lane_bits(pass[0], pass[1]);
  unsigned zpass = spass;
  if constexpr (D != DepthPath::Off)
    zpass = spass != 0 ? depth_row<D>(ctx, in, bx, y, di, dj, spass, zrow) : 0;
  if (side.write_mask == 0) return zpass;
  const i32x4 wm = zero + side.write_mask;
  i32x4 sfail[2], dpfail[2], dppass[2];
  bits_to_lanes(m & ~spass, sfail[0], sfail[1]);
  bits_to_lanes(spass & ~zpass, dpfail[0], dpfail[1]);
  bits_to_lanes(zpass, dppass[0], dppass[1]);
  uint8_t out[N];
  for (int h = 0; h < 2; ++h) {
    const i32x4 keep = ~(sfail[h] | dpfail[h] | dppass[h]);
    const i32x4 nv = (stencil_op_lanes(side.ops[0], v[h], ref) & sfail[h]) |
                     (stencil_op_lanes(side.ops[1], v[h], ref) & dpfail[h]) |
                     (stencil_op_lanes(side.ops[2], v[h], ref) & dppass[h]) | (v[h] & keep);
    const i32x4 w = (v[h] & ~wm) | (nv & wm);
    for (int k = 0; k < 4; ++k)
      out[4 * h + k] = static_cast<uint8_t>(w[k]);
  }
  if (whole) {
    std::memcpy(st, out, N);
  } else {
    for (int i = 0; i < N; ++i)
      if ((m >> i) & 1u) st[i] = out[i];
  }
  return zpass;
}

// Blend or logical operation, then colour mask, of source row `s` against destination `dst`
// (GL 2.1 §4.1.8, §4.1.10, §4.2.2); the result is left in `s`.
template <ColorFormat F, ColorPath C, BlendPath B>
[[gnu::always_inline]] inline void combine_row4(const FragCtx& ctx, unsigned m, bool logic, Row& s,
                                                const Row& dst) {
  if constexpr (B == BlendPath::Over)
    blend_over_row<F>(s, dst);
  else if constexpr (B == BlendPath::Generic)
    blend_generic_row<F>(ctx, m, s, dst);
  if (logic) {
    // per_fragment.h apply_logic, written out on the row's lanes.
    const LogicMasks& lm = ctx.logic;
    for (int h = 0; h < kParts; ++h) {
      const LaneU a = s.v[h], b = dst.v[h];
      s.v[h] = (a & b & lm.sd) | (a & ~b & lm.s_nd) | (~a & b & lm.ns_d) | (~a & ~b & lm.ns_nd);
    }
  }
  if constexpr (C == ColorPath::Partial) {
    const LaneU keep = LaneU{} + ctx.color_keep;
    for (int h = 0; h < kParts; ++h)
      s.v[h] = (dst.v[h] & keep) | (s.v[h] & ~keep);
  }
}

// Blend, colour mask and store of one row of a 4-byte format (GL 2.1 §4.1.8, §4.2.2). Full
// rows load and store the eight pixels whole; others touch only their fragments.
template <ColorFormat F, ColorPath C, BlendPath B, bool X>
[[gnu::always_inline]] inline void write_row4(const FragCtx& ctx, uint8_t* row, unsigned m,
                                              bool in_buffer, Row& s) {
  constexpr bool kReadsDst = B != BlendPath::Off || C == ColorPath::Partial;
  // GL 2.1 §4.1.10: the logical operation takes blending's place (the key has blend off).
  const bool logic = X && ctx.key.logic_op;
  const bool reads_dst = kReadsDst || logic;
  if (m == 0xffu && !reads_dst) {
    row_store(row, s);
    return;
  }
#if PINEDA_BLOCK_AVX512
  // The coverage as an opmask, the covered pixels kept by a masked move. Rows inside the
  // buffer are loaded and stored whole (see depth_row); the last block of a row uses masked
  // loads and stores.
  const auto k = static_cast<__mmask8>(m);
  if (in_buffer) {
    Row dst = row_load(row);
    combine_row4<F, C, B>(ctx, m, logic, s, dst);
    const __m256i out = _mm256_mask_mov_epi32(reinterpret_cast<__m256i>(dst.v[0]), k,
                                              reinterpret_cast<__m256i>(s.v[0]));
    std::memcpy(row, &out, sizeof out);
    return;
  }
  if (reads_dst) {
    Row dst;
    dst.v[0] = reinterpret_cast<u32x8>(_mm256_maskz_loadu_epi32(k, row));
    combine_row4<F, C, B>(ctx, m, logic, s, dst);
  }
  _mm256_mask_storeu_epi32(row, k, reinterpret_cast<__m256i>(s.v[0]));
#else
  if (in_buffer) {
    // The whole row lies in the buffer: compute all eight lanes and select the covered ones.
    Row dst = row_load(row);
    combine_row4<F, C, B>(ctx, m, logic, s, dst);
    if (m == 0xffu) {
      row_store(row, s);
      return;
    }
    const RowMask lanes = row_mask(m);
    for (int h = 0; h < kParts; ++h)
      dst.v[h] = lanes.v[h] ? s.v[h] : dst.v[h];
    row_store(row, dst);
    return;
  }
  // The last block of a row whose width is not a multiple of 8: fragment by fragment.
  alignas(32) uint32_t tmp[N] = {};
  if (reads_dst) {
    for (int i = 0; i < N; ++i)
      if ((m >> i) & 1u) std::memcpy(&tmp[i], row + 4 * i, 4);
  }
  const Row dst = row_load(tmp);
  combine_row4<F, C, B>(ctx, m, logic, s, dst);
  row_store(tmp, s);
  for (int i = 0; i < N; ++i)
    if ((m >> i) & 1u) std::memcpy(row + 4 * i, &tmp[i], 4);
#endif
}

// The same for 3-byte RGB8 pixels, one fragment at a time; `s` is packed as RGBA8.
template <ColorPath C, BlendPath B, bool X>
void write_row3(const FragCtx& ctx, uint8_t* row, unsigned m, const Row& s) {
  alignas(32) uint32_t sp[N];
  row_store(sp, s);
  uint8_t keep[4];
  std::memcpy(keep, &ctx.color_keep, 4);
  for (int i = 0; i < N; ++i) {
    if (((m >> i) & 1u) == 0) continue;
    uint8_t* p = row + 3 * i;
    uint8_t c[4];
    unpack_pixel<ColorFormat::RGBA8>(sp[i], true, c);
    if constexpr (B != BlendPath::Off) {
      const uint8_t d[4] = {p[0], p[1], p[2], 255}; // no alpha: destination alpha is 1
      if constexpr (B == BlendPath::Over) {
        for (int k = 0; k < 3; ++k)
          c[k] = blend_over_channel(c[k], d[k], c[3]);
      } else {
        uint8_t o[4];
        blend_pixel(ctx.blend, c, d, o);
        std::memcpy(c, o, 4);
      }
    }
    if (X && ctx.key.logic_op) {
      const uint32_t src = c[0] | (c[1] << 8) | (c[2] << 16);
      const uint32_t dst = p[0] | (p[1] << 8) | (p[2] << 16);
      const uint32_t out = apply_logic(ctx.logic, src, dst);
      for (int k = 0; k < 3; ++k)
        c[k] = static_cast<uint8_t>(out >> (8 * k));
    }
    for (int k = 0; k < 3; ++k)
      p[k] = C == ColorPath::Partial ? static_cast<uint8_t>((p[k] & keep[k]) | (c[k] & ~keep[k]))
                                     : c[k];
  }
}

// The further draw buffers of a fragment shader's draw (FragCtx::more, §4.2.1): the fragments
// of `passed` (those that passed every test in the primary buffer's block loop), each buffer
// with the colour of its output, from the shader run the block loop just made.
[[gnu::noinline]] inline void write_more_buffers(const FragCtx& ctx, int bx, int by,
                                                 uint64_t passed, const float (*shaded)[64]) {
  if (passed == 0) return;
  const bool per_output = ctx.shade->program->frag_data;
  alignas(32) float colors[4][64];
  for (int i = 0; i < ctx.more_count; ++i) {
    const FragCtx& o = *ctx.more[i];
    if (per_output) shade_program_colors(ctx, o.color_output, colors);
    o.write_color(o, bx, by, passed, per_output ? colors : shaded);
  }
}

// A further draw buffer's writer (ColorWriteFn): blending or logical operation (X), colour
// mask and store of the given colours, row by row.
template <ColorFormat F, ColorPath C, BlendPath B, bool X>
void write_colors(const FragCtx& ctx, int bx, int by, uint64_t mask, const float (*colors)[64]) {
  using L = Layout<F>;
  constexpr ColorFormat P = L::bpp == 4 ? F : ColorFormat::RGBA8;
  const bool in_buffer = bx + N <= ctx.fb_width;
  while (mask != 0) {
    const int j = std::countr_zero(mask) >> 3;
    const unsigned m = static_cast<unsigned>(mask >> (8 * j)) & 0xffu;
    mask &= ~(0xffull << (8 * j));
    uint8_t* const row = ctx.color + static_cast<ptrdiff_t>(by + j) * ctx.color_stride +
                         static_cast<ptrdiff_t>(bx) * L::bpp;
    Row s;
    per_fragment_row<P>(colors, j, s);
    if constexpr (L::bpp == 4)
      write_row4<F, C, B, X>(ctx, row, m, in_buffer, s);
    else
      write_row3<C, B, X>(ctx, row, m, s);
  }
}

// X selects the extended instances: alpha test (§4.1.4) before the stencil and depth tests
// (§4.1.5, §4.1.6), and the logical operation (§4.1.10) in place of blending, each behind a
// per-row branch on the key. Without X none of that code exists in the instance.
template <DepthPath D, ColorFormat F, ColorPath C, BlendPath B, ShadePath S, bool X>
void block_loop(const FragCtx& ctx, const FragInputs& in, int bx, int by, uint64_t mask) {
  using L = Layout<F>;
  // Pixels travel packed in the format's byte order; RGB8 rows are packed as RGBA8.
  constexpr ColorFormat P = L::bpp == 4 ? F : ColorFormat::RGBA8;
  // A fully covered block that the depth test rejects whole (hidden surfaces drawn after what
  // hides them) costs one pass over its stored depths. The stencil test must still see its
  // fragments (depth-fail updates); the alpha test and sample counting need not.
  // A shader that writes gl_FragDepth decides the depth itself: no rejection before it ran.
  if constexpr (D != DepthPath::Off) {
    if (mask == ~uint64_t{0} && (!X || !ctx.key.stencil_test) &&
        (S != ShadePath::PerFragment || !ctx.shader_depth) && block_fails_depth<D>(ctx, in, bx, by))
      return;
  }
  [[maybe_unused]] Row const_row{};
  [[maybe_unused]] SmoothPlanes<P> smooth;
  if constexpr (S == ShadePath::Smooth) smooth.init(in);
  if constexpr (S == ShadePath::Const)
    const_row = row_splat(
        pack_pixel<P>(in.const_color[0], in.const_color[1], in.const_color[2], in.const_color[3]));
  // Texturing and fog: the whole block's colours first (fragment/shade.cpp), which writes every
  // row that holds a fragment of `mask`, the only rows read below.
  [[maybe_unused]] alignas(32) float shaded_block[4][64];
  // gl_FragDepth of the block's fragments in depth-buffer units (ctx.shader_depth).
  [[maybe_unused]] alignas(32) uint32_t shaded_z[64];
  if constexpr (S == ShadePath::PerFragment && !X && D != DepthPath::Off && C != ColorPath::None) {
    // Early depth test: without the alpha test (only in the X instances) nothing the depth
    // test decides depends on texturing or fog (§4.1.6 needs the window z alone), so every row
    // is tested first and only the fragments that pass are textured. The depth buffer is
    // written before any colour, which changes nothing: each pixel is tested and written once.
    // A fragment shader that may discard decides first (§3.11.2), on the path below.
    if (!ctx.late_depth) {
      uint64_t live = 0;
      for (uint64_t rest = mask; rest != 0;) {
        const int j = std::countr_zero(rest) >> 3;
        const unsigned m = static_cast<unsigned>(rest >> (8 * j)) & 0xffu;
        rest &= ~(0xffull << (8 * j));
        const int y = by + j;
        live |= static_cast<uint64_t>(depth_row<D>(ctx, in, bx, y, bx - in.ox, y - in.oy, m))
                << (8 * j);
      }
      if (live == 0) return;
      live = shade_block(ctx, in, bx, by, live, shaded_block);
      const uint64_t written = live;
      const bool in_buffer = bx + N <= ctx.fb_width;
      while (live != 0) {
        const int j = std::countr_zero(live) >> 3;
        const unsigned m = static_cast<unsigned>(live >> (8 * j)) & 0xffu;
        live &= ~(0xffull << (8 * j));
        uint8_t* const row = ctx.color + static_cast<ptrdiff_t>(by + j) * ctx.color_stride +
                             static_cast<ptrdiff_t>(bx) * L::bpp;
        Row s;
        per_fragment_row<P>(shaded_block, j, s);
        if constexpr (L::bpp == 4)
          write_row4<F, C, B, X>(ctx, row, m, in_buffer, s);
        else
          write_row3<C, B, X>(ctx, row, m, s);
      }
      if (ctx.more_count > 0) write_more_buffers(ctx, bx, by, written, shaded_block);
      return;
    }
  }
  if constexpr (S == ShadePath::PerFragment) {
    mask = shade_block(ctx, in, bx, by, mask, shaded_block,
                       D != DepthPath::Off && ctx.shader_depth ? shaded_z : nullptr);
    if (mask == 0) return;
  }
  // The fragments stored, for the further draw buffers (FragCtx::more).
  [[maybe_unused]] uint64_t passed = 0;
  // One row: the tests, then colour and store for the survivors of `m`. `in_buffer`: the whole
  // row lies inside the buffer (bx + 8 <= width).
  const auto run_row = [&](int j, unsigned m, bool in_buffer) __attribute__((always_inline)) {
    const int y = by + j;
    const int di = bx - in.ox, dj = y - in.oy;
    Row s;
    bool shaded = false;
    // Only the PerFragment instances can meet a shader's depth; the others pass a constant null.
    const uint32_t* zrow = nullptr;
    if constexpr (S == ShadePath::PerFragment && D != DepthPath::Off)
      if (ctx.shader_depth) zrow = shaded_z + 8 * j;
    if constexpr (X) {
      if (ctx.key.alpha_test) {
        if constexpr (S == ShadePath::Const)
          s = const_row;
        else if constexpr (S == ShadePath::PerFragment)
          per_fragment_row<P>(shaded_block, j, s);
        else
          shade_row<P>(smooth, in, di, dj, s);
        shaded = true;
        m = alpha_row<P>(ctx, s, m);
        if (m == 0) return;
      }
      if (ctx.key.stencil_test) {
        m = stencil_depth_row<D>(ctx, in, bx, y, di, dj, m, zrow);
        if (m == 0) return;
      } else if constexpr (D != DepthPath::Off) {
        m = depth_row<D>(ctx, in, bx, y, di, dj, m, zrow);
        if (m == 0) return;
      }
    } else if constexpr (D != DepthPath::Off) {
      m = depth_row<D>(ctx, in, bx, y, di, dj, m, zrow);
      if (m == 0) return;
    }
    // §4.1.7: SAMPLES_PASSED counts what survived the stencil and depth tests.
    if constexpr (X)
      if (ctx.key.count_samples) ctx.samples_passed += static_cast<unsigned>(std::popcount(m));
    if constexpr (C != ColorPath::None) {
      uint8_t* const row = ctx.color + static_cast<ptrdiff_t>(y) * ctx.color_stride +
                           static_cast<ptrdiff_t>(bx) * L::bpp;
      if (!shaded) {
        if constexpr (S == ShadePath::Const)
          s = const_row;
        else if constexpr (S == ShadePath::PerFragment)
          per_fragment_row<P>(shaded_block, j, s);
        else
          shade_row<P>(smooth, in, di, dj, s);
      }
      if constexpr (L::bpp == 4)
        write_row4<F, C, B, X>(ctx, row, m, in_buffer, s);
      else
        write_row3<C, B, X>(ctx, row, m, s);
      if constexpr (S == ShadePath::PerFragment) passed |= static_cast<uint64_t>(m) << (8 * j);
    }
  };
  // A fully covered block (inside the buffer by construction): its rows in order, each with
  // all eight fragments live, without the mask bookkeeping. The extended instances keep one
  // copy of the row code.
  if constexpr (!X) {
    if (mask == ~uint64_t{0}) {
      for (int j = 0; j < N; ++j)
        run_row(j, 0xffu, true);
      mask = 0;
    }
  }
  while (mask != 0) {
    const int j = std::countr_zero(mask) >> 3;
    const unsigned m = static_cast<unsigned>(mask >> (8 * j)) & 0xffu;
    mask &= ~(0xffull << (8 * j));
    run_row(j, m, bx + N <= ctx.fb_width);
  }
  if constexpr (S == ShadePath::PerFragment && C != ColorPath::None)
    if (ctx.more_count > 0) write_more_buffers(ctx, bx, by, passed, shaded_block);
}

void noop_block(const FragCtx&, const FragInputs&, int, int, uint64_t) {}

// Table of colour-writing instances, index
//   (((depth * formats + format) * 2 + (partial ? 1 : 0)) * blends + blend) * shades + shade.
constexpr int kColorInstances =
    kDepthPathCount * kColorFormatCount * 2 * kBlendPathCount * kShadePathCount;

constexpr int color_index(DepthPath d, ColorFormat f, ColorPath c, BlendPath b, ShadePath s) {
  return (((static_cast<int>(d) * kColorFormatCount + static_cast<int>(f)) * 2 +
           (c == ColorPath::Partial ? 1 : 0)) *
              kBlendPathCount +
          static_cast<int>(b)) *
             kShadePathCount +
         static_cast<int>(s);
}

template <int I, bool X> constexpr BlockFn color_entry() {
  constexpr auto s = static_cast<ShadePath>(I % kShadePathCount);
  constexpr auto b = static_cast<BlendPath>((I / kShadePathCount) % kBlendPathCount);
  constexpr int rest = I / (kShadePathCount * kBlendPathCount);
  constexpr auto c = (rest % 2) ? ColorPath::Partial : ColorPath::All;
  constexpr auto f = static_cast<ColorFormat>((rest / 2) % kColorFormatCount);
  constexpr auto d = static_cast<DepthPath>(rest / (2 * kColorFormatCount));
  static_assert(color_index(d, f, c, b, s) == I);
  // The extended instances run every depth function through the generic path, which keeps
  // their number down: all depth rows but Off name the one Generic instance.
  constexpr DepthPath dx = (X && d != DepthPath::Off) ? DepthPath::Generic : d;
  return &block_loop<dx, f, c, b, s, X>;
}

template <bool X, size_t... I>
constexpr std::array<BlockFn, sizeof...(I)> make_color_table(std::index_sequence<I...>) {
  return {color_entry<static_cast<int>(I), X>()...};
}

constexpr std::array<BlockFn, kColorInstances> kColorTable =
    make_color_table<false>(std::make_index_sequence<kColorInstances>{});

constexpr std::array<BlockFn, kColorInstances> kExtColorTable =
    make_color_table<true>(std::make_index_sequence<kColorInstances>{});

// Depth-only instances of the extended loop: the shade path matters for the alpha test.
constexpr std::array<BlockFn, 2 * kShadePathCount> kExtDepthOnlyTable = {
    &block_loop<DepthPath::Off, ColorFormat::RGBA8, ColorPath::None, BlendPath::Off,
                ShadePath::Const, true>,
    &block_loop<DepthPath::Off, ColorFormat::RGBA8, ColorPath::None, BlendPath::Off,
                ShadePath::Smooth, true>,
    &block_loop<DepthPath::Off, ColorFormat::RGBA8, ColorPath::None, BlendPath::Off,
                ShadePath::PerFragment, true>,
    &block_loop<DepthPath::Generic, ColorFormat::RGBA8, ColorPath::None, BlendPath::Off,
                ShadePath::Const, true>,
    &block_loop<DepthPath::Generic, ColorFormat::RGBA8, ColorPath::None, BlendPath::Off,
                ShadePath::Smooth, true>,
    &block_loop<DepthPath::Generic, ColorFormat::RGBA8, ColorPath::None, BlendPath::Off,
                ShadePath::PerFragment, true>,
};

// Depth-only instances (colour mask all false or no colour buffer); the other template
// parameters do not matter there.
constexpr std::array<BlockFn, kDepthPathCount> kDepthOnlyTable = {
    &noop_block,
    &block_loop<DepthPath::LessWrite, ColorFormat::RGBA8, ColorPath::None, BlendPath::Off,
                ShadePath::Const, false>,
    &block_loop<DepthPath::LequalWrite, ColorFormat::RGBA8, ColorPath::None, BlendPath::Off,
                ShadePath::Const, false>,
    &block_loop<DepthPath::Generic, ColorFormat::RGBA8, ColorPath::None, BlendPath::Off,
                ShadePath::Const, false>,
};

// Depth-only instances that run the fragment shader first: one that discards or writes
// gl_FragDepth decides what the depth test sees (§3.11.2). Without a depth test nothing is
// written.
constexpr std::array<BlockFn, kDepthPathCount> kDepthOnlyShadeTable = {
    &noop_block,
    &block_loop<DepthPath::LessWrite, ColorFormat::RGBA8, ColorPath::None, BlendPath::Off,
                ShadePath::PerFragment, false>,
    &block_loop<DepthPath::LequalWrite, ColorFormat::RGBA8, ColorPath::None, BlendPath::Off,
                ShadePath::PerFragment, false>,
    &block_loop<DepthPath::Generic, ColorFormat::RGBA8, ColorPath::None, BlendPath::Off,
                ShadePath::PerFragment, false>,
};

// The instance for a key and shade path from this translation unit's tables.
BlockFn select_from_tables(const StateKey& key, ShadePath shade) {
  const ColorPath c = key.color_path();
  if (key.ext()) {
    const DepthPath d = key.depth_test ? DepthPath::Generic : DepthPath::Off;
    if (c == ColorPath::None)
      return kExtDepthOnlyTable[(d == DepthPath::Generic ? kShadePathCount : 0) +
                                static_cast<int>(shade)];
    return kExtColorTable[color_index(d, key.format, c, key.blend_path(), shade)];
  }
  if (c == ColorPath::None)
    return (shade == ShadePath::PerFragment ? kDepthOnlyShadeTable
                                            : kDepthOnlyTable)[static_cast<int>(key.depth_path())];
  return kColorTable[color_index(key.depth_path(), key.format, c, key.blend_path(), shade)];
}

} // namespace
} // namespace pineda
