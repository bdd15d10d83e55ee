// Sampling of whole 2x2 quads (texture/sampler.h sample_quads): 2D colour textures whose wraps
// are CLAMP_TO_EDGE or REPEAT on power-of-two sizes, filtered LINEAR with any mipmap mode,
// four fragments at a time in vectors. The arithmetic is sampler.cpp's fixed-point path
// (llvmpipe's: coordinates with 8 fractional bits rounded to nearest even, each linear step
// v0 + floor(((v1 - v0) w + 128) / 256) on 8-bit values, the mipmap weight truncated to
// 1/256), so the results equal sample_texture's bit for bit. Since one quad shares one lambda
// (GL 2.1 §3.8.8 allows rho to be approximated; llvmpipe computes it per quad), the level
// selection is done once per quad. Whatever this path does not cover (NEAREST filters,
// coordinates too large for 32-bit fixed point, NaN) goes through sample_texture. sRGB
// textures are decoded and filtered in float instead (srgb_quads), as sample_texture does.
//
// The vector path is SSE2; where the CPU has AVX2 (texture/cpu_dispatch.h) a second copy runs,
// which filters the two levels of a LINEAR_MIPMAP_LINEAR sample side by side in 256-bit vectors.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "texture/cpu_dispatch.h"
#include "texture/sampler.h"

#if defined(__SSE2__) && defined(__x86_64__)
#include <immintrin.h>
#define PINEDA_QUAD_SIMD 1
#endif

namespace pineda {

namespace {

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
  float fw, fh;           // sizes without border, as floats
  __m128i last_s, last_t; // size - 1 (REPEAT: the wrap mask; CLAMP_TO_EDGE: the last index)
  __m128i border;         // border offset of both axes
  __m128i row;            // texels per stored row (border included), for pmaddwd
};

// llvmpipe's linear step with a weight per lane: a + floor(((b - a) w + 128) / 256), written as
// (a (256 - w) + b w + 128) / 256 (the same value: a 256 is a multiple of 256), whose every
// term fits an unsigned 16-bit lane for a, b, w in [0, 255]. `iw` is 256 - w.
[[gnu::always_inline]] inline __m128i lerp_w(__m128i a, __m128i b, __m128i w, __m128i iw) {
  const __m128i sum = _mm_add_epi16(_mm_mullo_epi16(a, iw), _mm_mullo_epi16(b, w));
  return _mm_srli_epi16(_mm_add_epi16(sum, _mm_set1_epi16(128)), 8);
}

[[gnu::always_inline]] inline __m128i clamp4(__m128i v, __m128i last) {
  v = _mm_andnot_si128(_mm_srai_epi32(v, 31), v); // negative -> 0
  const __m128i over = _mm_cmpgt_epi32(v, last);
  return _mm_or_si128(_mm_and_si128(over, last), _mm_andnot_si128(over, v));
}

// The axis of four coordinates: texel indices (border offset added) and 1/256 weights, as
// sampler.cpp's axis_linear_fixed (the conversion rounds to nearest even, as there).
[[gnu::always_inline]] inline void axis4(__m128 s, float size_f, __m128i last, bool repeat,
                                         __m128i border, __m128i& i0, __m128i& i1, __m128i& w) {
  const __m128 scaled = _mm_mul_ps(_mm_mul_ps(s, _mm_set1_ps(size_f)), _mm_set1_ps(256.0f));
  const __m128i u = _mm_sub_epi32(_mm_cvtps_epi32(scaled), _mm_set1_epi32(128));
  w = _mm_and_si128(u, _mm_set1_epi32(255));
  i0 = _mm_srai_epi32(u, 8);
  i1 = _mm_add_epi32(i0, _mm_set1_epi32(1));
  if (repeat) {
    i0 = _mm_and_si128(i0, last);
    i1 = _mm_and_si128(i1, last);
  } else {
    i0 = clamp4(i0, last);
    i1 = clamp4(i1, last);
  }
  i0 = _mm_add_epi32(i0, border);
  i1 = _mm_add_epi32(i1, border);
}

// Weights of lanes 0, 1 (lo) or 2, 3 (hi) of `w`, each repeated for a texel's four channels.
[[gnu::always_inline]] inline __m128i spread_lo(__m128i w) {
  const __m128i d = _mm_or_si128(w, _mm_slli_epi32(w, 16));
  return _mm_unpacklo_epi32(d, d);
}
[[gnu::always_inline]] inline __m128i spread_hi(__m128i w) {
  const __m128i d = _mm_or_si128(w, _mm_slli_epi32(w, 16));
  return _mm_unpackhi_epi32(d, d);
}

[[gnu::always_inline]] inline __m128i texel(const uint8_t* base, int index) {
  int32_t x;
  std::memcpy(&x, base + static_cast<ptrdiff_t>(index) * 4, 4);
  return _mm_cvtsi32_si128(x);
}
[[gnu::always_inline]] inline __m128i texel_pair(const uint8_t* base, int index) {
  return _mm_loadl_epi64(
      reinterpret_cast<const __m128i*>(base + static_cast<ptrdiff_t>(index) * 4));
}

// The texels at columns i0 and i1 of one row (texel offsets o0 = row + i0, o1 = row + i1) of
// four fragments, widened: a_lo, b_lo the i0 and i1 texels of fragments 0 and 1, a_hi, b_hi of
// fragments 2 and 3.
[[gnu::always_inline]] inline void row_texels(const uint8_t* base, __m128i o0, __m128i o1,
                                              bool pairs, __m128i& a_lo, __m128i& b_lo,
                                              __m128i& a_hi, __m128i& b_hi) {
  alignas(16) int32_t off0[4], off1[4];
  _mm_store_si128(reinterpret_cast<__m128i*>(off0), o0);
  const __m128i zero = _mm_setzero_si128();
  __m128i x01, x23;
  if (pairs) {
    // i1 = i0 + 1 in every lane: one 8-byte load per fragment gives both texels.
    x01 = _mm_unpacklo_epi64(texel_pair(base, off0[0]), texel_pair(base, off0[1]));
    x23 = _mm_unpacklo_epi64(texel_pair(base, off0[2]), texel_pair(base, off0[3]));
    x01 = _mm_shuffle_epi32(x01, _MM_SHUFFLE(3, 1, 2, 0));
    x23 = _mm_shuffle_epi32(x23, _MM_SHUFFLE(3, 1, 2, 0));
  } else {
    _mm_store_si128(reinterpret_cast<__m128i*>(off1), o1);
    x01 = _mm_unpacklo_epi64(_mm_unpacklo_epi32(texel(base, off0[0]), texel(base, off0[1])),
                             _mm_unpacklo_epi32(texel(base, off1[0]), texel(base, off1[1])));
    x23 = _mm_unpacklo_epi64(_mm_unpacklo_epi32(texel(base, off0[2]), texel(base, off0[3])),
                             _mm_unpacklo_epi32(texel(base, off1[2]), texel(base, off1[3])));
  }
  a_lo = _mm_unpacklo_epi8(x01, zero);
  b_lo = _mm_unpackhi_epi8(x01, zero);
  a_hi = _mm_unpacklo_epi8(x23, zero);
  b_hi = _mm_unpackhi_epi8(x23, zero);
}

// LINEAR filtering of one level at four coordinates: fragments 0 and 1 in `lo`, 2 and 3 in
// `hi` (four 16-bit channels each).
[[gnu::always_inline]] inline void bilinear4(const QuadLevel& l, bool rep_s, bool rep_t, __m128 s,
                                             __m128 t, __m128i& lo, __m128i& hi) {
  __m128i i0, i1, ws, j0, j1, wt;
  axis4(s, l.fw, l.last_s, rep_s, l.border, i0, i1, ws);
  axis4(t, l.fh, l.last_t, rep_t, l.border, j0, j1, wt);
  // Indices and the row length are below 2^15: one pmaddwd multiplies.
  const __m128i r0 = _mm_madd_epi16(j0, l.row), r1 = _mm_madd_epi16(j1, l.row);
  const bool pairs =
      _mm_movemask_epi8(_mm_cmpeq_epi32(i1, _mm_add_epi32(i0, _mm_set1_epi32(1)))) == 0xffff;
  __m128i a0l, b0l, a0h, b0h, a1l, b1l, a1h, b1h;
  row_texels(l.rgba, _mm_add_epi32(r0, i0), _mm_add_epi32(r0, i1), pairs, a0l, b0l, a0h, b0h);
  row_texels(l.rgba, _mm_add_epi32(r1, i0), _mm_add_epi32(r1, i1), pairs, a1l, b1l, a1h, b1h);
  const __m128i k256 = _mm_set1_epi16(256);
  const __m128i wsl = spread_lo(ws), wsh = spread_hi(ws), wtl = spread_lo(wt), wth = spread_hi(wt);
  const __m128i iwsl = _mm_sub_epi16(k256, wsl), iwsh = _mm_sub_epi16(k256, wsh);
  const __m128i iwtl = _mm_sub_epi16(k256, wtl), iwth = _mm_sub_epi16(k256, wth);
  lo = lerp_w(lerp_w(a0l, b0l, wsl, iwsl), lerp_w(a1l, b1l, wsl, iwsl), wtl, iwtl);
  hi = lerp_w(lerp_w(a0h, b0h, wsh, iwsh), lerp_w(a1h, b1h, wsh, iwsh), wth, iwth);
}

// AVX2: both levels of a trilinear sample at once, level l0 in the low 128 bits of every vector
// and level l1 in the high ones, with bilinear4's arithmetic in each half. Returns the two
// levels' results for fragments 0, 1 (lo) and 2, 3 (hi) in the halves.
[[gnu::target("avx2"), gnu::always_inline]] inline __m256i both(__m128i a, __m128i b) {
  return _mm256_inserti128_si256(_mm256_castsi128_si256(a), b, 1);
}

[[gnu::target("avx2"), gnu::always_inline]] inline void axis8(__m256 s, __m256 size_f, __m256i last,
                                                              bool repeat, __m256i border,
                                                              __m256i& i0, __m256i& i1,
                                                              __m256i& w) {
  const __m256 scaled = _mm256_mul_ps(_mm256_mul_ps(s, size_f), _mm256_set1_ps(256.0f));
  const __m256i u = _mm256_sub_epi32(_mm256_cvtps_epi32(scaled), _mm256_set1_epi32(128));
  w = _mm256_and_si256(u, _mm256_set1_epi32(255));
  i0 = _mm256_srai_epi32(u, 8);
  i1 = _mm256_add_epi32(i0, _mm256_set1_epi32(1));
  if (repeat) {
    i0 = _mm256_and_si256(i0, last);
    i1 = _mm256_and_si256(i1, last);
  } else {
    const __m256i zero = _mm256_setzero_si256();
    i0 = _mm256_min_epi32(_mm256_max_epi32(i0, zero), last);
    i1 = _mm256_min_epi32(_mm256_max_epi32(i1, zero), last);
  }
  i0 = _mm256_add_epi32(i0, border);
  i1 = _mm256_add_epi32(i1, border);
}

[[gnu::target("avx2"), gnu::always_inline]] inline __m256i lerp_w8(__m256i a, __m256i b, __m256i w,
                                                                   __m256i iw) {
  const __m256i sum = _mm256_add_epi16(_mm256_mullo_epi16(a, iw), _mm256_mullo_epi16(b, w));
  return _mm256_srli_epi16(_mm256_add_epi16(sum, _mm256_set1_epi16(128)), 8);
}

// One row of texels of both levels (offsets o0, o1: lanes 0..3 level l0, 4..7 level l1).
[[gnu::target("avx2"), gnu::always_inline]] inline void
row_texels8(const uint8_t* b0, const uint8_t* b1, __m256i o0, __m256i o1, bool pairs, __m256i& a_lo,
            __m256i& b_lo, __m256i& a_hi, __m256i& b_hi) {
  alignas(32) int32_t off0[8], off1[8];
  _mm256_store_si256(reinterpret_cast<__m256i*>(off0), o0);
  __m256i x01, x23;
  if (pairs) {
    x01 = both(_mm_unpacklo_epi64(texel_pair(b0, off0[0]), texel_pair(b0, off0[1])),
               _mm_unpacklo_epi64(texel_pair(b1, off0[4]), texel_pair(b1, off0[5])));
    x23 = both(_mm_unpacklo_epi64(texel_pair(b0, off0[2]), texel_pair(b0, off0[3])),
               _mm_unpacklo_epi64(texel_pair(b1, off0[6]), texel_pair(b1, off0[7])));
    x01 = _mm256_shuffle_epi32(x01, _MM_SHUFFLE(3, 1, 2, 0));
    x23 = _mm256_shuffle_epi32(x23, _MM_SHUFFLE(3, 1, 2, 0));
  } else {
    _mm256_store_si256(reinterpret_cast<__m256i*>(off1), o1);
    const auto four = [](const uint8_t* b, const int32_t* p0, const int32_t* p1, int k) {
      return _mm_unpacklo_epi64(_mm_unpacklo_epi32(texel(b, p0[k]), texel(b, p0[k + 1])),
                                _mm_unpacklo_epi32(texel(b, p1[k]), texel(b, p1[k + 1])));
    };
    x01 = both(four(b0, off0, off1, 0), four(b1, off0, off1, 4));
    x23 = both(four(b0, off0, off1, 2), four(b1, off0, off1, 6));
  }
  const __m256i zero = _mm256_setzero_si256();
  a_lo = _mm256_unpacklo_epi8(x01, zero);
  b_lo = _mm256_unpackhi_epi8(x01, zero);
  a_hi = _mm256_unpacklo_epi8(x23, zero);
  b_hi = _mm256_unpackhi_epi8(x23, zero);
}

[[gnu::target("avx2")]] void trilinear8(const QuadLevel& l0, const QuadLevel& l1, bool rep_s,
                                        bool rep_t, __m128 s, __m128 t, int w8, __m128i& lo_out,
                                        __m128i& hi_out) {
  const __m256 s8 = _mm256_insertf128_ps(_mm256_castps128_ps256(s), s, 1);
  const __m256 t8 = _mm256_insertf128_ps(_mm256_castps128_ps256(t), t, 1);
  const __m256 fw = _mm256_insertf128_ps(_mm256_set1_ps(l0.fw), _mm_set1_ps(l1.fw), 1);
  const __m256 fh = _mm256_insertf128_ps(_mm256_set1_ps(l0.fh), _mm_set1_ps(l1.fh), 1);
  const __m256i border = both(l0.border, l1.border);
  __m256i i0, i1, ws, j0, j1, wt;
  axis8(s8, fw, both(l0.last_s, l1.last_s), rep_s, border, i0, i1, ws);
  axis8(t8, fh, both(l0.last_t, l1.last_t), rep_t, border, j0, j1, wt);
  const __m256i row = both(l0.row, l1.row);
  const __m256i r0 = _mm256_madd_epi16(j0, row), r1 = _mm256_madd_epi16(j1, row);
  const bool pairs = _mm256_movemask_epi8(
                         _mm256_cmpeq_epi32(i1, _mm256_add_epi32(i0, _mm256_set1_epi32(1)))) == -1;
  __m256i a0l, b0l, a0h, b0h, a1l, b1l, a1h, b1h;
  row_texels8(l0.rgba, l1.rgba, _mm256_add_epi32(r0, i0), _mm256_add_epi32(r0, i1), pairs, a0l, b0l,
              a0h, b0h);
  row_texels8(l0.rgba, l1.rgba, _mm256_add_epi32(r1, i0), _mm256_add_epi32(r1, i1), pairs, a1l, b1l,
              a1h, b1h);
  const __m256i k256 = _mm256_set1_epi16(256);
  const __m256i ds = _mm256_or_si256(ws, _mm256_slli_epi32(ws, 16));
  const __m256i dt = _mm256_or_si256(wt, _mm256_slli_epi32(wt, 16));
  const __m256i wsl = _mm256_unpacklo_epi32(ds, ds), wsh = _mm256_unpackhi_epi32(ds, ds);
  const __m256i wtl = _mm256_unpacklo_epi32(dt, dt), wth = _mm256_unpackhi_epi32(dt, dt);
  const __m256i iwsl = _mm256_sub_epi16(k256, wsl), iwsh = _mm256_sub_epi16(k256, wsh);
  const __m256i iwtl = _mm256_sub_epi16(k256, wtl), iwth = _mm256_sub_epi16(k256, wth);
  const __m256i lo = lerp_w8(lerp_w8(a0l, b0l, wsl, iwsl), lerp_w8(a1l, b1l, wsl, iwsl), wtl, iwtl);
  const __m256i hi = lerp_w8(lerp_w8(a0h, b0h, wsh, iwsh), lerp_w8(a1h, b1h, wsh, iwsh), wth, iwth);
  // The mipmap step between the halves (§3.8.10 LINEAR_MIPMAP_LINEAR).
  const __m128i wm = _mm_set1_epi16(static_cast<int16_t>(w8));
  const __m128i iwm = _mm_set1_epi16(static_cast<int16_t>(256 - w8));
  lo_out = lerp_w(_mm256_castsi256_si128(lo), _mm256_extracti128_si256(lo, 1), wm, iwm);
  hi_out = lerp_w(_mm256_castsi256_si128(hi), _mm256_extracti128_si256(hi, 1), wm, iwm);
}

// Whether every lane is a coordinate the 32-bit fixed point represents as sampler.cpp's
// 64-bit one does: |s| within the sampler's 1e6 pin and |s size 256| below 2^31; false for NaN.
[[gnu::always_inline]] inline bool coords_fit(__m128 s, float size_f) {
  const __m128 a = _mm_and_ps(s, _mm_castsi128_ps(_mm_set1_epi32(0x7fffffff)));
  const __m128 scaled = _mm_mul_ps(_mm_mul_ps(a, _mm_set1_ps(size_f)), _mm_set1_ps(256.0f));
  const __m128 ok = _mm_and_ps(_mm_cmple_ps(a, _mm_set1_ps(1.0e6f)),
                               _mm_cmplt_ps(scaled, _mm_set1_ps(2147483520.0f)));
  return _mm_movemask_ps(ok) == 0xf;
}

// The vector path of sample_quads. Compiled twice: for the default target (SSE2) and, chosen at
// run time, for AVX2, where the same instructions get the three-operand VEX forms (fewer register
// copies); the arithmetic is the same (no FMA), so are the results.
// Fragments' channels to planes: lane k of plane c is channel c of fragment k of quad q.
[[gnu::always_inline]] inline void store_planes(__m128i lo, __m128i hi, int q, float (*rgba)[64]) {
  const __m128i t0 = _mm_unpacklo_epi16(lo, hi), t1 = _mm_unpackhi_epi16(lo, hi);
  const __m128i rg = _mm_unpacklo_epi16(t0, t1), ba = _mm_unpackhi_epi16(t0, t1);
  const __m128i zero = _mm_setzero_si128();
  const __m128 k = _mm_set1_ps(1.0f / 255.0f);
  const __m128i planes[4] = {_mm_unpacklo_epi16(rg, zero), _mm_unpackhi_epi16(rg, zero),
                             _mm_unpacklo_epi16(ba, zero), _mm_unpackhi_epi16(ba, zero)};
  for (int c = 0; c < 4; ++c)
    _mm_storeu_ps(&rgba[c][4 * q], _mm_mul_ps(_mm_cvtepi32_ps(planes[c]), k));
}

template <bool kAvx2>
[[gnu::always_inline]] inline void quads_body(const SamplerView& v, int nq, const float* s,
                                              const float* t, const float* lambda, float bias,
                                              float (*rgba)[64]) {
  // §3.8.8 eq. 3.17: the biases' sum is clamped to MAX_TEXTURE_LOD_BIAS.
  const float total_bias = std::clamp(bias + v.lod_bias, -kMaxLodBias, kMaxLodBias);
  const GLenum minf = v.min_filter;
  const bool mip_linear = minf == GL_LINEAR_MIPMAP_LINEAR;
  const bool mip_nearest = minf == GL_LINEAR_MIPMAP_NEAREST;
  const bool rep_s = v.wrap_s == GL_REPEAT, rep_t = v.wrap_t == GL_REPEAT;
  QuadLevel levels[kMaxTexLevels];
  unsigned ready = 0;
  const auto level = [&](int l) __attribute__((always_inline))->const QuadLevel& {
    if (!(ready & (1u << l))) {
      const SamplerLevel& sl = v.levels[0][l];
      QuadLevel& q = levels[l];
      q.rgba = sl.rgba;
      const int w = sl.width - 2 * v.border, h = sl.height - 2 * v.border;
      q.fw = static_cast<float>(w);
      q.fh = static_cast<float>(h);
      q.last_s = _mm_set1_epi32(w - 1);
      q.last_t = _mm_set1_epi32(h - 1);
      q.border = _mm_set1_epi32(v.border);
      q.row = _mm_set1_epi32(sl.width);
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
    const __m128 sq = _mm_loadu_ps(s + 4 * q), tq = _mm_loadu_ps(t + 4 * q);
    const QuadLevel& l0 = level(d0);
    // The coarser level is the smaller one: coordinates that fit the finer level fit it.
    if (!coords_fit(sq, l0.fw) || !coords_fit(tq, l0.fh)) {
      quad_fallback(v, s, t, lambda[q], bias, q, rgba);
      continue;
    }
    __m128i lo, hi;
    if constexpr (kAvx2) {
      if (w8 > 0) {
        trilinear8(l0, level(d0 + 1), rep_s, rep_t, sq, tq, w8, lo, hi);
        store_planes(lo, hi, q, rgba);
        continue;
      }
    }
    bilinear4(l0, rep_s, rep_t, sq, tq, lo, hi);
    if (w8 > 0) {
      __m128i lo1, hi1;
      bilinear4(level(d0 + 1), rep_s, rep_t, sq, tq, lo1, hi1);
      const __m128i wm = _mm_set1_epi16(static_cast<int16_t>(w8));
      const __m128i iwm = _mm_set1_epi16(static_cast<int16_t>(256 - w8));
      lo = lerp_w(lo, lo1, wm, iwm);
      hi = lerp_w(hi, hi1, wm, iwm);
    }
    store_planes(lo, hi, q, rgba);
  }
}

// ---- sRGB textures ----
//
// GL 2.1 §3.8.15: the texels are decoded to linear before filtering, which then needs more
// than 8 bits: sampler.cpp filters them in float (its general path, as llvmpipe does), and
// this is that path's arithmetic four fragments at a time, one channel per vector, so the
// results are the same bit for bit (no FMA: each product is rounded as there).

// floor for |x| < 2^31 with SSE2 only.
[[gnu::always_inline]] inline __m128 floor4(__m128 x) {
  const __m128 t = _mm_cvtepi32_ps(_mm_cvttps_epi32(x));
  return _mm_sub_ps(t, _mm_and_ps(_mm_cmpgt_ps(t, x), _mm_set1_ps(1.0f)));
}

// sampler.cpp's axis_linear for REPEAT on a power-of-two size or CLAMP_TO_EDGE: texel
// indices (border offset added) and the weight of i1.
[[gnu::always_inline]] inline void srgb_axis4(__m128 s, int size, bool repeat, int border,
                                              __m128i& i0, __m128i& i1, __m128& w) {
  const __m128 fsize = _mm_set1_ps(static_cast<float>(size));
  __m128 u;
  if (repeat) {
    u = _mm_sub_ps(_mm_mul_ps(_mm_sub_ps(s, floor4(s)), fsize), _mm_set1_ps(0.5f));
  } else {
    const __m128 c = _mm_min_ps(_mm_max_ps(_mm_mul_ps(s, fsize), _mm_set1_ps(0.5f)),
                                _mm_set1_ps(static_cast<float>(size) - 0.5f));
    u = _mm_sub_ps(c, _mm_set1_ps(0.5f));
  }
  const __m128 fl = floor4(u);
  w = _mm_sub_ps(u, fl);
  i0 = _mm_cvttps_epi32(fl);
  i1 = _mm_add_epi32(i0, _mm_set1_epi32(1));
  const __m128i last = _mm_set1_epi32(size - 1);
  if (repeat) {
    i0 = _mm_and_si128(i0, last);
    i1 = _mm_and_si128(i1, last);
  } else {
    i0 = clamp4(i0, last);
    i1 = clamp4(i1, last);
  }
  i0 = _mm_add_epi32(i0, _mm_set1_epi32(border));
  i1 = _mm_add_epi32(i1, _mm_set1_epi32(border));
}

struct Planes4 {
  __m128 c[4]; // R, G, B, A of four fragments
};

// The texels at texel offsets `idx` of `base`, decoded: R, G, B through the sRGB table, alpha
// c / 255.
[[gnu::always_inline]] inline Planes4 srgb_texels(const uint8_t* base, __m128i idx) {
  alignas(16) int32_t o[4];
  _mm_store_si128(reinterpret_cast<__m128i*>(o), idx);
  const float* lin = srgb_decode_table();
  alignas(16) float ch[4][4];
  for (int k = 0; k < 4; ++k) {
    const uint8_t* p = base + static_cast<ptrdiff_t>(o[k]) * 4;
    ch[0][k] = lin[p[0]], ch[1][k] = lin[p[1]], ch[2][k] = lin[p[2]];
    ch[3][k] = static_cast<float>(p[3]);
  }
  Planes4 out;
  for (int c = 0; c < 3; ++c)
    out.c[c] = _mm_load_ps(ch[c]);
  out.c[3] = _mm_mul_ps(_mm_load_ps(ch[3]), _mm_set1_ps(1.0f / 255.0f));
  return out;
}

// Bilinear filtering of level `l` at four coordinates, in sampler.cpp's order: the texels
// (i0, j0), (i1, j0), (i0, j1), (i1, j1), each weighted by wi wj.
[[gnu::always_inline]] inline Planes4 srgb_bilinear4(const SamplerView& v, int l, __m128 s,
                                                     __m128 t) {
  const SamplerLevel& sl = v.levels[0][l];
  const int w = sl.width - 2 * v.border, h = sl.height - 2 * v.border;
  __m128i i0, i1, j0, j1;
  __m128 ws, wt;
  srgb_axis4(s, w, v.wrap_s == GL_REPEAT, v.border, i0, i1, ws);
  srgb_axis4(t, h, v.wrap_t == GL_REPEAT, v.border, j0, j1, wt);
  const __m128i row = _mm_set1_epi32(sl.width);
  const __m128i r0 = _mm_madd_epi16(j0, row), r1 = _mm_madd_epi16(j1, row);
  const __m128 one = _mm_set1_ps(1.0f);
  const __m128 wi[2] = {_mm_sub_ps(one, ws), ws}, wj[2] = {_mm_sub_ps(one, wt), wt};
  const __m128i rows[2] = {r0, r1}, cols[2] = {i0, i1};
  Planes4 acc;
  for (int jj = 0; jj < 2; ++jj)
    for (int ii = 0; ii < 2; ++ii) {
      const __m128 wgt = _mm_mul_ps(wi[ii], wj[jj]);
      const Planes4 tx = srgb_texels(sl.rgba, _mm_add_epi32(rows[jj], cols[ii]));
      for (int c = 0; c < 4; ++c) {
        const __m128 term = _mm_mul_ps(wgt, tx.c[c]);
        acc.c[c] = (jj == 0 && ii == 0) ? term : _mm_add_ps(acc.c[c], term);
      }
    }
  return acc;
}

// sample_quads for an sRGB view: the level selection of sample_texture's general path once
// per quad.
void srgb_quads(const SamplerView& v, int nq, const float* s, const float* t, const float* lambda,
                float bias, float (*rgba)[64]) {
  const float total_bias = std::clamp(bias + v.lod_bias, -kMaxLodBias, kMaxLodBias);
  const GLenum minf = v.min_filter;
  const bool mip_linear = minf == GL_LINEAR_MIPMAP_LINEAR;
  const bool mip_nearest = minf == GL_LINEAR_MIPMAP_NEAREST;
  for (int q = 0; q < nq; ++q) {
    float lod = lambda[q] + total_bias;
    if (!(lod == lod)) lod = 0.0f;
    lod = std::min(lod, v.max_lod);
    lod = std::max(lod, v.min_lod);
    int d0 = v.base_level;
    float w = 0.0f;
    if (lod <= v.c || !(mip_linear || mip_nearest)) {
      if (lod <= v.c && v.mag_filter != GL_LINEAR) {
        quad_fallback(v, s, t, lambda[q], bias, q, rgba);
        continue;
      }
    } else if (mip_nearest) {
      const int d = v.base_level + static_cast<int>(std::floor(std::min(lod, 64.0f) + 0.5f));
      d0 = std::clamp(d, v.base_level, v.max_level);
    } else {
      const float lc = std::min(lod, 64.0f);
      const float fl = std::floor(lc);
      d0 = v.base_level + static_cast<int>(fl);
      w = lc - fl;
      if (d0 >= v.max_level) {
        d0 = v.max_level;
        w = 0.0f;
      }
    }
    const __m128 sq = _mm_loadu_ps(s + 4 * q), tq = _mm_loadu_ps(t + 4 * q);
    const SamplerLevel& sl = v.levels[0][d0];
    if (!coords_fit(sq, static_cast<float>(sl.width)) ||
        !coords_fit(tq, static_cast<float>(sl.height))) {
      quad_fallback(v, s, t, lambda[q], bias, q, rgba);
      continue;
    }
    Planes4 out = srgb_bilinear4(v, d0, sq, tq);
    if (w > 0.0f) {
      const Planes4 o1 = srgb_bilinear4(v, d0 + 1, sq, tq);
      const __m128 wv = _mm_set1_ps(w);
      for (int c = 0; c < 4; ++c)
        out.c[c] = _mm_add_ps(out.c[c], _mm_mul_ps(wv, _mm_sub_ps(o1.c[c], out.c[c])));
    }
    for (int c = 0; c < 4; ++c)
      _mm_storeu_ps(&rgba[c][4 * q], out.c[c]);
  }
}

void sample_quads_sse2(const SamplerView& v, int nq, const float* s, const float* t,
                       const float* lambda, float bias, float (*rgba)[64]) {
  quads_body<false>(v, nq, s, t, lambda, bias, rgba);
}

[[gnu::target("avx2")]] void sample_quads_avx2(const SamplerView& v, int nq, const float* s,
                                               const float* t, const float* lambda, float bias,
                                               float (*rgba)[64]) {
  quads_body<true>(v, nq, s, t, lambda, bias, rgba);
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
  if (v.srgb) return srgb_quads(v, nq, s, t, lambda, bias, rgba);
  if (use_avx2())
    sample_quads_avx2(v, nq, s, t, lambda, bias, rgba);
  else
    sample_quads_sse2(v, nq, s, t, lambda, bias, rgba);
#else
  for (int q = 0; q < nq; ++q)
    quad_fallback(v, s, t, lambda[q], bias, q, rgba);
#endif
}

} // namespace pineda
