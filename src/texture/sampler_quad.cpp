// Sampling of whole 2x2 quads (texture/sampler.h sample_quads): 2D colour textures whose wraps
// are CLAMP_TO_EDGE or REPEAT on power-of-two sizes, filtered LINEAR with any mipmap mode,
// four fragments at a time in vectors. The arithmetic is sampler.cpp's fixed-point path
// (llvmpipe's: coordinates with 8 fractional bits rounded to nearest even, each linear step
// v0 + floor(((v1 - v0) w + 128) / 256) on 8-bit values, the mipmap weight truncated to
// 1/256), so the results equal sample_texture's bit for bit. Since one quad shares one lambda
// (GL 2.1 §3.8.8 allows rho to be approximated; llvmpipe computes it per quad), the level
// selection is done once per quad. Whatever this path does not cover (NEAREST filters,
// coordinates too large for 32-bit fixed point, NaN) goes through sample_texture.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "fragment/simd.h"
#include "texture/sampler.h"

#if defined(__SSE2__) && defined(__x86_64__)
#include <emmintrin.h>
#define PINEDA_QUAD_SIMD 1
#endif

namespace pineda {

namespace {

constexpr float kMaxLodBias = 16.0f; // MAX_TEXTURE_LOD_BIAS, as sampler.cpp

bool is_pot(int v) {
  return v > 0 && (v & (v - 1)) == 0;
}

// The sampler's general path for the four fragments of quad q, transposed to planes.
void quad_fallback(const SamplerView& v, const float* s, const float* t, float lambda, float bias,
                   int q, float (*rgba)[64]) {
  const float lam[4] = {lambda, lambda, lambda, lambda};
  float out[4][4];
  sample_texture(v, 4, s + 4 * q, t + 4 * q, nullptr, lam, bias, out);
  for (int k = 0; k < 4; ++k)
    for (int c = 0; c < 4; ++c)
      rgba[c][4 * q + k] = out[k][c];
}

#if defined(PINEDA_QUAD_SIMD)

// One level as the vector path reads it.
struct QuadLevel {
  const uint8_t* rgba;
  float fw, fh;      // sizes without border, as floats
  int w, h;          // sizes without border
  int row;           // texels per stored row (border included)
  int bi, bj;        // border offsets
  bool rep_s, rep_t; // REPEAT (power-of-two size): wrap by mask; else CLAMP_TO_EDGE
};

// llvmpipe's linear step with a weight per lane: a + floor(((b - a) w + 128) / 256), written as
// (a (256 - w) + b w + 128) / 256 (the same value: a 256 is a multiple of 256), whose every
// term fits an unsigned 16-bit lane for a, b, w in [0, 255].
inline u16x8 lerp_w(u16x8 a, u16x8 b, u16x8 w) {
  const u16x8 k256 = u16x8{} + 256, k128 = u16x8{} + 128;
  return (a * (k256 - w) + b * w + k128) >> 8;
}

inline i32x4 round_even4(f32x4 x) {
  return reinterpret_cast<i32x4>(_mm_cvtps_epi32(x));
}

inline i32x4 select(i32x4 m, i32x4 a, i32x4 b) {
  return (m & a) | (~m & b);
}

inline i32x4 clamp4(i32x4 v, int hi) {
  const i32x4 zero = {}, top = zero + hi;
  v = select(v < zero, zero, v);
  return select(v > top, top, v);
}

inline uint32_t load_texel(const uint8_t* base, int index) {
  uint32_t x;
  std::memcpy(&x, base + static_cast<ptrdiff_t>(index) * 4, 4);
  return x;
}

// Lanes 0..3 of `v` each repeated four times: the weights of fragments 0, 1 (lo) or 2, 3 (hi)
// for their texels' four channels.
inline u16x8 spread_lo(i32x4 v) {
  const u16x8 h = reinterpret_cast<u16x8>(v);
  return __builtin_shufflevector(h, h, 0, 0, 0, 0, 2, 2, 2, 2);
}
inline u16x8 spread_hi(i32x4 v) {
  const u16x8 h = reinterpret_cast<u16x8>(v);
  return __builtin_shufflevector(h, h, 4, 4, 4, 4, 6, 6, 6, 6);
}

// The axis of four coordinates: texel indices (border offset added) and 1/256 weights, as
// sampler.cpp's axis_linear_fixed.
inline void axis4(f32x4 s, float size_f, int size, bool repeat, int border, i32x4& i0, i32x4& i1,
                  i32x4& w) {
  const i32x4 u = round_even4(s * size_f * 256.0f) - 128;
  w = u & 255;
  i0 = u >> 8;
  i1 = i0 + 1;
  if (repeat) {
    i0 &= size - 1;
    i1 &= size - 1;
  } else {
    i0 = clamp4(i0, size - 1);
    i1 = clamp4(i1, size - 1);
  }
  i0 += border;
  i1 += border;
}

// LINEAR filtering of one level at four coordinates: fragments 0 and 1 in `lo`, 2 and 3 in
// `hi` (four 16-bit channels each).
inline void bilinear4(const QuadLevel& l, f32x4 s, f32x4 t, u16x8& lo, u16x8& hi) {
  i32x4 i0, i1, ws, j0, j1, wt;
  axis4(s, l.fw, l.w, l.rep_s, l.bi, i0, i1, ws);
  axis4(t, l.fh, l.h, l.rep_t, l.bj, j0, j1, wt);
  const i32x4 r0 = j0 * l.row, r1 = j1 * l.row;
  const i32x4 o00 = r0 + i0, o10 = r0 + i1, o01 = r1 + i0, o11 = r1 + i1;
  const uint8_t* b = l.rgba;
  const u32x4 p00 = {load_texel(b, o00[0]), load_texel(b, o00[1]), load_texel(b, o00[2]),
                     load_texel(b, o00[3])};
  const u32x4 p10 = {load_texel(b, o10[0]), load_texel(b, o10[1]), load_texel(b, o10[2]),
                     load_texel(b, o10[3])};
  const u32x4 p01 = {load_texel(b, o01[0]), load_texel(b, o01[1]), load_texel(b, o01[2]),
                     load_texel(b, o01[3])};
  const u32x4 p11 = {load_texel(b, o11[0]), load_texel(b, o11[1]), load_texel(b, o11[2]),
                     load_texel(b, o11[3])};
  const auto bytes = [](u32x4 x) { return reinterpret_cast<u8x16>(x); };
  const u16x8 ws_lo = spread_lo(ws), ws_hi = spread_hi(ws);
  const u16x8 wt_lo = spread_lo(wt), wt_hi = spread_hi(wt);
  lo = lerp_w(lerp_w(widen_lo(bytes(p00)), widen_lo(bytes(p10)), ws_lo),
              lerp_w(widen_lo(bytes(p01)), widen_lo(bytes(p11)), ws_lo), wt_lo);
  hi = lerp_w(lerp_w(widen_hi(bytes(p00)), widen_hi(bytes(p10)), ws_hi),
              lerp_w(widen_hi(bytes(p01)), widen_hi(bytes(p11)), ws_hi), wt_hi);
}

// Whether every lane is a coordinate the 32-bit fixed point represents as sampler.cpp's
// 64-bit one does: |s| within the sampler's 1e6 pin and |s size 256| below 2^31; false for NaN.
inline bool coords_fit(f32x4 s, float size_f) {
  const f32x4 a = reinterpret_cast<f32x4>(reinterpret_cast<i32x4>(s) & 0x7fffffff);
  const i32x4 ok = (a <= 1.0e6f) & (a * size_f * 256.0f < 2147483520.0f);
  return _mm_movemask_ps(reinterpret_cast<__m128>(ok)) == 0xf;
}

#endif

} // namespace

bool quad_sampling_supported(const SamplerView& v) {
#if defined(PINEDA_QUAD_SIMD)
  if (v.target != GL_TEXTURE_2D || v.is_depth || v.compare) return false;
  const GLenum minf = v.min_filter;
  const bool linear_min =
      minf == GL_LINEAR || minf == GL_LINEAR_MIPMAP_NEAREST || minf == GL_LINEAR_MIPMAP_LINEAR;
  if (!linear_min) return false;
  // Level sizes halve from the base level, so a power-of-two base keeps every level one.
  const auto wrap_ok = [](GLenum wrap, int size) {
    return wrap == GL_CLAMP_TO_EDGE || (wrap == GL_REPEAT && is_pot(size));
  };
  return wrap_ok(v.wrap_s, v.width) && wrap_ok(v.wrap_t, v.height);
#else
  (void)v;
  return false;
#endif
}

void sample_quads(const SamplerView& v, int nq, const float* s, const float* t, const float* lambda,
                  float bias, float (*rgba)[64]) {
#if defined(PINEDA_QUAD_SIMD)
  if (!v.quads) {
    for (int q = 0; q < nq; ++q)
      quad_fallback(v, s, t, lambda[q], bias, q, rgba);
    return;
  }
  // §3.8.8 eq. 3.17: the biases' sum is clamped to MAX_TEXTURE_LOD_BIAS.
  const float total_bias = std::clamp(bias + v.lod_bias, -kMaxLodBias, kMaxLodBias);
  const GLenum minf = v.min_filter;
  const bool mip_linear = minf == GL_LINEAR_MIPMAP_LINEAR;
  const bool mip_nearest = minf == GL_LINEAR_MIPMAP_NEAREST;
  QuadLevel levels[kMaxTexLevels];
  unsigned ready = 0;
  const auto level = [&](int l) -> const QuadLevel& {
    if (!(ready & (1u << l))) {
      const SamplerLevel& sl = v.levels[0][l];
      QuadLevel& q = levels[l];
      q.rgba = sl.rgba;
      q.bi = q.bj = v.border;
      q.w = sl.width - 2 * v.border;
      q.h = sl.height - 2 * v.border;
      q.fw = static_cast<float>(q.w);
      q.fh = static_cast<float>(q.h);
      q.row = sl.width;
      q.rep_s = v.wrap_s == GL_REPEAT;
      q.rep_t = v.wrap_t == GL_REPEAT;
      ready |= 1u << l;
    }
    return levels[l];
  };
  for (int q = 0; q < nq; ++q) {
    // The level selection of sampler.cpp's sample_2d_fixed, once for the quad.
    float lod = lambda[q] + total_bias;
    if (!(lod == lod)) lod = 0.0f;
    lod = std::min(lod, v.max_lod);
    lod = std::max(lod, v.min_lod);
    int d0 = v.base_level, w8 = 0;
    if (lod <= v.c) {
      if (v.mag_filter != GL_LINEAR) {
        quad_fallback(v, s, t, lambda[q], bias, q, rgba);
        continue;
      }
    } else if (mip_nearest) {
      const int d = v.base_level + static_cast<int>(std::floor(std::min(lod, 64.0f) + 0.5f));
      d0 = std::clamp(d, v.base_level, v.max_level);
    } else if (mip_linear) {
      const float lc = std::min(lod, 64.0f);
      const float fl = std::floor(lc);
      d0 = v.base_level + static_cast<int>(fl);
      float w = lc - fl;
      if (d0 >= v.max_level) {
        d0 = v.max_level;
        w = 0.0f;
      }
      w8 = static_cast<int>(w * 256.0f);
    }
    f32x4 sq, tq;
    std::memcpy(&sq, s + 4 * q, sizeof(sq));
    std::memcpy(&tq, t + 4 * q, sizeof(tq));
    const QuadLevel& l0 = level(d0);
    // The coarser level is the smaller one: coordinates that fit the finer level fit it.
    if (!coords_fit(sq, l0.fw) || !coords_fit(tq, l0.fh)) {
      quad_fallback(v, s, t, lambda[q], bias, q, rgba);
      continue;
    }
    u16x8 lo, hi;
    bilinear4(l0, sq, tq, lo, hi);
    if (w8 > 0) {
      u16x8 lo1, hi1;
      bilinear4(level(d0 + 1), sq, tq, lo1, hi1);
      const u16x8 wm = u16x8{} + static_cast<uint16_t>(w8);
      lo = lerp_w(lo, lo1, wm);
      hi = lerp_w(hi, hi1, wm);
    }
    // Fragments' channels to planes: lane k of plane c is channel c of fragment k.
    const i16x8 a = reinterpret_cast<i16x8>(lo), b = reinterpret_cast<i16x8>(hi);
    const i16x8 rg = __builtin_shufflevector(a, b, 0, 4, 8, 12, 1, 5, 9, 13);
    const i16x8 ba = __builtin_shufflevector(a, b, 2, 6, 10, 14, 3, 7, 11, 15);
    const i16x8 z = {};
    const auto plane = [&](i16x8 x, bool high) {
      const i32x4 wide =
          high ? reinterpret_cast<i32x4>(__builtin_shufflevector(x, z, 4, 8, 5, 8, 6, 8, 7, 8))
               : reinterpret_cast<i32x4>(__builtin_shufflevector(x, z, 0, 8, 1, 8, 2, 8, 3, 8));
      return __builtin_convertvector(wide, f32x4) * (1.0f / 255.0f);
    };
    const f32x4 planes[4] = {plane(rg, false), plane(rg, true), plane(ba, false), plane(ba, true)};
    for (int c = 0; c < 4; ++c)
      std::memcpy(&rgba[c][4 * q], &planes[c], sizeof(f32x4));
  }
#else
  for (int q = 0; q < nq; ++q)
    quad_fallback(v, s, t, lambda[q], bias, q, rgba);
#endif
}

} // namespace pineda
