// The texture sampler (GL 2.1 §3.8.8-§3.8.10, §3.8.14): level of detail, level selection,
// wrap modes, borders, NEAREST/LINEAR filtering, mipmap interpolation, cube face selection and
// depth comparison, on the plain SamplerView the texture objects' completeness check makes
// (state/texture_view.cpp); and the mipmap filter of GENERATE_MIPMAP.
//
// Where the spec leaves room Pineda does what Mesa llvmpipe does:
//  - the minification/magnification switch-over point c is 0 for every filter combination
//    (GL 3.1 and later allow this; llvmpipe does it): lambda > 0 minifies;
//  - NEAREST_MIPMAP_* picks level base + round-half-up(lambda);
//  - 8-bit textures with REPEAT or CLAMP_TO_EDGE wraps on every axis are filtered the way
//    llvmpipe's fixed-point path does it: coordinates with 8 fractional bits (rounded), weights
//    of 1/256, each linear step v0 + floor((v1 - v0) * w / 256) on 8-bit values, and a mipmap
//    weight truncated to 1/256. Every other case interpolates in float.
#include "texture/sampler.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

#if defined(__SSE2__) && defined(__x86_64__)
#include <emmintrin.h>
#endif

#include "core/simd.h"

namespace pineda {

namespace {

// The two texels and weight of one axis for LINEAR, or the texel for NEAREST (i0), after the
// wrap mode (GL 2.1 §3.8.8 eq. 3.20-3.26). Indices lie in [-1, size]; those outside
// [0, size-1] address the border.
struct Axis {
  int i0, i1;
  float w; // weight of i1 (float path)
  int w8;  // weight of i1 in 1/256 (fixed-point path)
};

inline float frac(float x) {
  return x - std::floor(x);
}

// MIRRORED_REPEAT (§3.8.8): the coordinate mirrored into [0,1].
inline float mirror(float s) {
  const float fl = std::floor(s);
  const float f = s - fl;
  return (static_cast<int64_t>(fl) & 1) != 0 ? 1.0f - f : f;
}

inline int clampi(int v, int lo, int hi) {
  return v < lo ? lo : (v > hi ? hi : v);
}

// Float coordinates that cannot be converted to int safely are pinned first.
inline float sane(float s) {
  if (!(s == s)) return 0.0f;
  return std::clamp(s, -1.0e6f, 1.0e6f);
}

Axis axis_nearest(float s, int size, GLenum wrap) {
  s = sane(s);
  int i;
  switch (wrap) {
  case GL_REPEAT:
    if ((size & (size - 1)) == 0) {
      i = static_cast<int>(std::floor(s * float(size))) & (size - 1);
    } else {
      i = std::min(static_cast<int>(frac(s) * float(size)), size - 1);
    }
    break;
  case GL_MIRRORED_REPEAT:
    i = std::min(static_cast<int>(std::floor(mirror(s) * float(size))), size - 1);
    break;
  case GL_CLAMP_TO_BORDER: {
    // §3.8.8: s clamped to [-1/2N, 1 + 1/2N], so the border is reached.
    i = static_cast<int>(std::floor(s * float(size)));
    i = clampi(i, -1, size);
    break;
  }
  default: // CLAMP, CLAMP_TO_EDGE: nearest never reaches the border
    i = clampi(static_cast<int>(std::floor(s * float(size))), 0, size - 1);
    break;
  }
  return Axis{i, i, 0.0f, 0};
}

Axis axis_linear(float s, int size, GLenum wrap) {
  s = sane(s);
  float u;
  switch (wrap) {
  case GL_REPEAT:
    u = frac(s) * float(size) - 0.5f;
    break;
  case GL_MIRRORED_REPEAT:
    u = mirror(s) * float(size) - 0.5f;
    break;
  case GL_CLAMP:
    u = std::clamp(s, 0.0f, 1.0f) * float(size) - 0.5f;
    break;
  case GL_CLAMP_TO_EDGE:
    u = std::clamp(s * float(size), 0.5f, float(size) - 0.5f) - 0.5f;
    break;
  default: // CLAMP_TO_BORDER
    u = std::clamp(s * float(size), -0.5f, float(size) + 0.5f) - 0.5f;
    break;
  }
  const float fl = std::floor(u);
  Axis a;
  a.i0 = static_cast<int>(fl);
  a.i1 = a.i0 + 1;
  a.w = u - fl;
  a.w8 = 0;
  switch (wrap) {
  case GL_REPEAT:
    a.i0 = a.i0 < 0 ? a.i0 + size : (a.i0 >= size ? a.i0 - size : a.i0);
    a.i1 = a.i1 >= size ? a.i1 - size : a.i1;
    break;
  case GL_MIRRORED_REPEAT:
  case GL_CLAMP_TO_EDGE:
    a.i0 = clampi(a.i0, 0, size - 1);
    a.i1 = clampi(a.i1, 0, size - 1);
    break;
  default: // CLAMP, CLAMP_TO_BORDER: the border is reached
    a.i0 = clampi(a.i0, -1, size);
    a.i1 = clampi(a.i1, -1, size);
    break;
  }
  return a;
}

// x rounded to the nearest integer, ties to even (the default rounding mode), as nearbyint;
// on x86-64 one conversion instruction instead of nearbyint's sequence.
inline int64_t round_even(float x) {
#if defined(__SSE2__) && defined(__x86_64__)
  return _mm_cvtss_si64(_mm_set_ss(x));
#else
  return static_cast<int64_t>(std::nearbyint(x));
#endif
}

// The fixed-point variant of axis_linear for REPEAT and CLAMP_TO_EDGE (see the file comment).
// Coordinates are in 1/256 texel, rounded to nearest (even on ties, as the SIMD conversion).
inline Axis axis_linear_fixed(float s, int size, GLenum wrap) {
  s = sane(s);
  Axis a;
  const bool repeat = wrap == GL_REPEAT;
  const bool pot = (size & (size - 1)) == 0;
  const float scaled = (repeat && !pot ? frac(s) : s) * float(size) * 256.0f;
  const int64_t u = round_even(scaled) - 128;
  a.w8 = static_cast<int>(u & 255);
  const int64_t i0 = u >> 8;
  if (repeat && pot) {
    a.i0 = static_cast<int>(i0 & (size - 1));
    a.i1 = static_cast<int>((i0 + 1) & (size - 1));
  } else if (repeat) {
    a.i0 = i0 < 0 ? size - 1 : static_cast<int>(std::min<int64_t>(i0, size - 1));
    a.i1 = a.i0 == size - 1 ? 0 : a.i0 + 1;
  } else {
    a.i0 = static_cast<int>(std::clamp<int64_t>(i0, 0, size - 1));
    a.i1 = static_cast<int>(std::clamp<int64_t>(i0 + 1, 0, size - 1));
  }
  a.w = float(a.w8) * (1.0f / 256.0f);
  return a;
}

// llvmpipe's 8-bit linear step (a rounding high multiply, pmulhrsw):
// v0 + floor(((v1 - v0) * w + 128) / 256).
inline int lerp8(int v0, int v1, int w) {
  return v0 + (((v1 - v0) * w + 128) >> 8);
}

// One filtered level sample.
struct LevelCtx {
  const SamplerView* v;
  const SamplerLevel* lv;
  int w, h, d;    // sizes without border
  int bi, bj, bk; // border width along each axis (0 along axes the target lacks)
};

// The texel at (i, j, k) (border-relative indices in [-1, size]) as floats; the border
// colour when outside the image and its border.
inline size_t texel_index(const LevelCtx& c, int i, int j, int k) {
  return (size_t(k + c.bk) * size_t(c.lv->height) + size_t(j + c.bj)) * size_t(c.lv->width) +
         size_t(i + c.bi);
}

inline void fetch(const LevelCtx& c, int i, int j, int k, float* out) {
  if (i < -c.bi || i >= c.w + c.bi || j < -c.bj || j >= c.h + c.bj || k < -c.bk ||
      k >= c.d + c.bk) {
    for (int q = 0; q < 4; ++q)
      out[q] = c.v->border_color[q];
    return;
  }
  const size_t idx = texel_index(c, i, j, k);
  if (c.v->is_depth) {
    const float z = c.lv->z != nullptr ? float(double(c.lv->z[idx]) / c.lv->z_max) : 0.0f;
    out[0] = out[1] = out[2] = out[3] = z;
    return;
  }
  const uint8_t* t = c.lv->rgba + idx * 4;
  constexpr float k255 = 1.0f / 255.0f;
  if (c.v->srgb) {
    // §3.8.15: decoded before filtering.
    const float* lin = srgb_decode_table();
    out[0] = lin[t[0]], out[1] = lin[t[1]], out[2] = lin[t[2]], out[3] = t[3] * k255;
    return;
  }
  out[0] = t[0] * k255, out[1] = t[1] * k255, out[2] = t[2] * k255, out[3] = t[3] * k255;
}

inline const uint8_t* fetch8(const LevelCtx& c, int i, int j, int k) {
  return c.lv->rgba + texel_index(c, i, j, k) * 4;
}

// §3.8.14: the comparison result for texel value `z` and reference `ref`.
inline float compare(GLenum func, float ref, float z) {
  bool pass;
  switch (func) {
  case GL_LEQUAL:
    pass = ref <= z;
    break;
  case GL_GEQUAL:
    pass = ref >= z;
    break;
  case GL_LESS:
    pass = ref < z;
    break;
  case GL_GREATER:
    pass = ref > z;
    break;
  case GL_EQUAL:
    pass = ref == z;
    break;
  case GL_NOTEQUAL:
    pass = ref != z;
    break;
  case GL_ALWAYS:
    pass = true;
    break;
  default:
    pass = false;
    break; // NEVER
  }
  return pass ? 1.0f : 0.0f;
}

// Samples one level with `filter` (NEAREST or LINEAR) at (s, t, r); `ref` is the depth
// comparison reference. Writes RGBA (for depth textures the (compared) depth in all four).
LevelCtx level_ctx(const SamplerView& v, int face, int level, int dims) {
  LevelCtx c;
  c.v = &v;
  c.lv = &v.levels[face][level];
  c.bi = v.border;
  c.bj = dims >= 2 ? v.border : 0;
  c.bk = dims >= 3 ? v.border : 0;
  c.w = c.lv->width - 2 * c.bi;
  c.h = c.lv->height - 2 * c.bj;
  c.d = c.lv->depth - 2 * c.bk;
  return c;
}

void sample_level(const LevelCtx& c, int dims, GLenum filter, bool fixed, float s, float t, float r,
                  float ref, float* out) {
  const SamplerView& v = *c.v;
  if (filter == GL_NEAREST) {
    const Axis as = axis_nearest(s, c.w, v.wrap_s);
    const Axis at = dims >= 2 ? axis_nearest(t, c.h, v.wrap_t) : Axis{0, 0, 0.0f, 0};
    const Axis ar = dims >= 3 ? axis_nearest(r, c.d, v.wrap_r) : Axis{0, 0, 0.0f, 0};
    fetch(c, as.i0, at.i0, ar.i0, out);
    if (v.compare) out[0] = out[1] = out[2] = out[3] = compare(v.compare_func, ref, out[0]);
    return;
  }
  if (fixed) {
    const Axis as = axis_linear_fixed(s, c.w, v.wrap_s);
    const Axis at = dims >= 2 ? axis_linear_fixed(t, c.h, v.wrap_t) : Axis{0, 0, 0.0f, 0};
    const Axis ar = dims >= 3 ? axis_linear_fixed(r, c.d, v.wrap_r) : Axis{0, 0, 0.0f, 0};
    int res[2][4];
    const int nk = dims >= 3 ? 2 : 1;
    for (int kk = 0; kk < nk; ++kk) {
      const int k = kk == 0 ? ar.i0 : ar.i1;
      const uint8_t* t00 = fetch8(c, as.i0, at.i0, k);
      const uint8_t* t10 = fetch8(c, as.i1, at.i0, k);
      if (dims == 1) {
        for (int q = 0; q < 4; ++q)
          res[kk][q] = lerp8(t00[q], t10[q], as.w8);
      } else {
        const uint8_t* t01 = fetch8(c, as.i0, at.i1, k);
        const uint8_t* t11 = fetch8(c, as.i1, at.i1, k);
        for (int q = 0; q < 4; ++q)
          res[kk][q] = lerp8(lerp8(t00[q], t10[q], as.w8), lerp8(t01[q], t11[q], as.w8), at.w8);
      }
    }
    for (int q = 0; q < 4; ++q) {
      const int val = nk == 2 ? lerp8(res[0][q], res[1][q], ar.w8) : res[0][q];
      out[q] = float(val) * (1.0f / 255.0f);
    }
    return;
  }
  const Axis as = axis_linear(s, c.w, v.wrap_s);
  const Axis at = dims >= 2 ? axis_linear(t, c.h, v.wrap_t) : Axis{0, 0, 0.0f, 0};
  const Axis ar = dims >= 3 ? axis_linear(r, c.d, v.wrap_r) : Axis{0, 0, 0.0f, 0};
  const int nj = dims >= 2 ? 2 : 1, nk = dims >= 3 ? 2 : 1;
  float acc[4] = {0, 0, 0, 0};
  for (int kk = 0; kk < nk; ++kk) {
    const float wk = nk == 1 ? 1.0f : (kk == 0 ? 1.0f - ar.w : ar.w);
    for (int jj = 0; jj < nj; ++jj) {
      const float wj = nj == 1 ? 1.0f : (jj == 0 ? 1.0f - at.w : at.w);
      for (int ii = 0; ii < 2; ++ii) {
        const float wi = ii == 0 ? 1.0f - as.w : as.w;
        const float wt = wi * wj * wk;
        float texel[4];
        fetch(c, ii == 0 ? as.i0 : as.i1, jj == 0 ? at.i0 : at.i1, kk == 0 ? ar.i0 : ar.i1, texel);
        if (v.compare)
          texel[0] = texel[1] = texel[2] = texel[3] = compare(v.compare_func, ref, texel[0]);
        for (int q = 0; q < 4; ++q)
          acc[q] += wt * texel[q];
      }
    }
  }
  for (int q = 0; q < 4; ++q)
    out[q] = acc[q];
}

// GL 2.1 §3.8.6 Table 3.21: the face and the face's (s, t) for direction (rx, ry, rz).
// Ties go to z over x and y, and to y over x (llvmpipe's order).
inline int cube_face(float rx, float ry, float rz, float& s, float& t) {
  const float ax = std::fabs(rx), ay = std::fabs(ry), az = std::fabs(rz);
  float sc, tc, ma;
  int face;
  if (az >= ax && az >= ay) {
    face = rz >= 0.0f ? 4 : 5;
    sc = rz >= 0.0f ? rx : -rx;
    tc = -ry;
    ma = az;
  } else if (ax > ay) {
    face = rx >= 0.0f ? 0 : 1;
    sc = rx >= 0.0f ? -rz : rz;
    tc = -ry;
    ma = ax;
  } else {
    face = ry >= 0.0f ? 2 : 3;
    sc = rx;
    tc = ry >= 0.0f ? rz : -rz;
    ma = ay;
  }
  if (ma == 0.0f || !(ma == ma)) {
    s = t = 0.5f;
    return face;
  }
  s = 0.5f * (sc / ma + 1.0f);
  t = 0.5f * (tc / ma + 1.0f);
  return face;
}

inline void expand_depth(TexBase base, float d, float* out) {
  switch (base) {
  case TexBase::Alpha:
    out[0] = out[1] = out[2] = 0.0f, out[3] = d;
    break;
  case TexBase::Intensity:
    out[0] = out[1] = out[2] = out[3] = d;
    break;
  default:
    out[0] = out[1] = out[2] = d, out[3] = 1.0f;
    break;
  }
}

// The common case of a 2D colour texture sampled on its base level only (no mipmap filter and
// one filter for minification and magnification, so lambda does not matter) with REPEAT or
// CLAMP_TO_EDGE: the level set-up is hoisted out of the fragment loop.
void sample_2d_base(const SamplerView& v, int n, const float* s, const float* t, GLenum filter,
                    float (*rgba)[4]) {
  LevelCtx c;
  c.v = &v;
  c.lv = &v.levels[0][v.base_level];
  c.bi = c.bj = v.border;
  c.bk = 0;
  c.w = c.lv->width - 2 * c.bi;
  c.h = c.lv->height - 2 * c.bj;
  c.d = 1;
  constexpr float k = 1.0f / 255.0f;
  if (filter == GL_NEAREST) {
    for (int i = 0; i < n; ++i) {
      const int x = axis_nearest(s[i], c.w, v.wrap_s).i0;
      const int y = axis_nearest(t != nullptr ? t[i] : 0.0f, c.h, v.wrap_t).i0;
      const uint8_t* p = fetch8(c, x, y, 0);
      rgba[i][0] = p[0] * k, rgba[i][1] = p[1] * k, rgba[i][2] = p[2] * k, rgba[i][3] = p[3] * k;
    }
    return;
  }
  for (int i = 0; i < n; ++i) {
    const Axis as = axis_linear_fixed(s[i], c.w, v.wrap_s);
    const Axis at = axis_linear_fixed(t != nullptr ? t[i] : 0.0f, c.h, v.wrap_t);
    const uint8_t* t00 = fetch8(c, as.i0, at.i0, 0);
    const uint8_t* t10 = fetch8(c, as.i1, at.i0, 0);
    const uint8_t* t01 = fetch8(c, as.i0, at.i1, 0);
    const uint8_t* t11 = fetch8(c, as.i1, at.i1, 0);
    for (int q = 0; q < 4; ++q)
      rgba[i][q] =
          float(lerp8(lerp8(t00[q], t10[q], as.w8), lerp8(t01[q], t11[q], as.w8), at.w8)) * k;
  }
}

// The texel at a fetch8 address widened to the low four 16-bit lanes.
inline i16x8 texel_lanes(const uint8_t* p) {
  u32x4 v = {};
  std::memcpy(&v, p, 4);
  return reinterpret_cast<i16x8>(widen_lo(reinterpret_cast<u8x16>(v)));
}

// One level of a 2D colour texture with REPEAT or CLAMP_TO_EDGE on both axes, as 8-bit values in
// lanes 0..3: the texel for NEAREST, llvmpipe's fixed-point bilinear filter for LINEAR (the same
// arithmetic as sample_level's fixed path, both rows' horizontal steps in one vector).
inline i16x8 sample_level8(const LevelCtx& c, GLenum filter, float s, float t) {
  const SamplerView& v = *c.v;
  if (filter == GL_NEAREST)
    return texel_lanes(
        fetch8(c, axis_nearest(s, c.w, v.wrap_s).i0, axis_nearest(t, c.h, v.wrap_t).i0, 0));
  const Axis as = axis_linear_fixed(s, c.w, v.wrap_s);
  const Axis at = axis_linear_fixed(t, c.h, v.wrap_t);
  uint32_t p[4];
  std::memcpy(&p[0], fetch8(c, as.i0, at.i0, 0), 4);
  std::memcpy(&p[1], fetch8(c, as.i0, at.i1, 0), 4);
  std::memcpy(&p[2], fetch8(c, as.i1, at.i0, 0), 4);
  std::memcpy(&p[3], fetch8(c, as.i1, at.i1, 0), 4);
  // Lanes 0..3 the row at.i0, lanes 4..7 the row at.i1.
  const u32x4 left = {p[0], p[1], 0, 0}, right = {p[2], p[3], 0, 0};
  const i16x8 rows =
      lerp8_lanes(reinterpret_cast<i16x8>(widen_lo(reinterpret_cast<u8x16>(left))),
                  reinterpret_cast<i16x8>(widen_lo(reinterpret_cast<u8x16>(right))), as.w8);
  return lerp8_lanes(rows, __builtin_shufflevector(rows, rows, 4, 5, 6, 7, 4, 5, 6, 7), at.w8);
}

// 2D colour textures with REPEAT or CLAMP_TO_EDGE wraps, every filter: the level selection of
// sample_texture with the texels kept as 8-bit integers until the end, which gives the same
// results as the general loop (whose float values are exactly these integers / 255).
void sample_2d_fixed(const SamplerView& v, int n, const float* s, const float* t,
                     const float* lambda, float total_bias, GLenum min_img, bool mip_linear,
                     bool mip_nearest, float (*rgba)[4]) {
  LevelCtx levels[kMaxTexLevels];
  for (int l = v.base_level; l <= v.max_level; ++l)
    levels[l] = level_ctx(v, 0, l, 2);
  for (int i = 0; i < n; ++i) {
    const float ss = s[i];
    const float tt = t != nullptr ? t[i] : 0.0f;
    float lod = lambda[i] + total_bias;
    if (!(lod == lod)) lod = 0.0f;
    lod = std::min(lod, v.max_lod);
    lod = std::max(lod, v.min_lod);
    i16x8 out;
    if (lod <= v.c || !(mip_linear || mip_nearest)) {
      out = sample_level8(levels[v.base_level], lod <= v.c ? v.mag_filter : min_img, ss, tt);
    } else if (mip_nearest) {
      const int d = v.base_level + static_cast<int>(std::floor(std::min(lod, 64.0f) + 0.5f));
      out = sample_level8(levels[clampi(d, v.base_level, v.max_level)], min_img, ss, tt);
    } else {
      const float lc = std::min(lod, 64.0f);
      const float fl = std::floor(lc);
      int d0 = v.base_level + static_cast<int>(fl);
      float w = lc - fl;
      if (d0 >= v.max_level) {
        d0 = v.max_level;
        w = 0.0f;
      }
      out = sample_level8(levels[d0], min_img, ss, tt);
      const int w8 = static_cast<int>(w * 256.0f);
      if (w8 > 0) out = lerp8_lanes(out, sample_level8(levels[d0 + 1], min_img, ss, tt), w8);
    }
    const f32x4 f = __builtin_convertvector(__builtin_shufflevector(out, out, 0, 1, 2, 3), f32x4) *
                    (1.0f / 255.0f);
    std::memcpy(rgba[i], &f, sizeof(f));
  }
}

} // namespace

const float* srgb_decode_table() {
  static const auto table = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i) {
      const double c = i / 255.0;
      t[i] = static_cast<float>(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
    }
    return t;
  }();
  return table.data();
}

void sample_texture(const SamplerView& v, int n, const float* s, const float* t, const float* r,
                    const float* lambda, float bias, float (*rgba)[4]) {
  const int dims = texture_dims(v.target);
  const bool cube = v.target == GL_TEXTURE_CUBE_MAP;
  const bool simple_s = v.wrap_s == GL_REPEAT || v.wrap_s == GL_CLAMP_TO_EDGE;
  const bool simple_t = dims < 2 || v.wrap_t == GL_REPEAT || v.wrap_t == GL_CLAMP_TO_EDGE;
  const bool simple_r = dims < 3 || v.wrap_r == GL_REPEAT || v.wrap_r == GL_CLAMP_TO_EDGE;
  // sRGB textures are filtered in float after decoding (linear values need more than 8
  // bits), as llvmpipe filters them.
  const bool fixed = !v.is_depth && !v.srgb && !cube && simple_s && simple_t && simple_r;
  // §3.8.8 eq. 3.17: the biases' sum is clamped to MAX_TEXTURE_LOD_BIAS.
  const float total_bias = std::clamp(bias + v.lod_bias, -kMaxLodBias, kMaxLodBias);
  const GLenum minf = v.min_filter;
  const bool mip_linear = minf == GL_NEAREST_MIPMAP_LINEAR || minf == GL_LINEAR_MIPMAP_LINEAR;
  const bool mip_nearest = minf == GL_NEAREST_MIPMAP_NEAREST || minf == GL_LINEAR_MIPMAP_NEAREST;
  const GLenum min_img =
      (minf == GL_NEAREST || minf == GL_NEAREST_MIPMAP_NEAREST || minf == GL_NEAREST_MIPMAP_LINEAR)
          ? GL_NEAREST
          : GL_LINEAR;
  if (fixed && dims == 2 && !mip_linear && !mip_nearest && min_img == v.mag_filter)
    return sample_2d_base(v, n, s, t, min_img, rgba);
  if (fixed && dims == 2)
    return sample_2d_fixed(v, n, s, t, lambda, total_bias, min_img, mip_linear, mip_nearest, rgba);
  // The levels' set-up, once per call.
  LevelCtx levels[6][kMaxTexLevels];
  for (int f = 0; f < v.faces; ++f)
    for (int l = v.base_level; l <= v.max_level; ++l)
      levels[f][l] = level_ctx(v, f, l, dims);
  for (int i = 0; i < n; ++i) {
    float ss = s[i];
    float tt = t != nullptr ? t[i] : 0.0f;
    float rr = r != nullptr ? r[i] : 0.0f;
    int face = 0;
    // §3.8.14: the comparison reference is r clamped to [0,1] (for cube maps none exists in
    // GL 2.1; depth cube maps cannot be specified).
    const float ref = std::clamp(rr, 0.0f, 1.0f);
    if (cube) face = cube_face(ss, tt, rr, ss, tt);
    float lod = lambda[i] + total_bias;
    if (!(lod == lod)) lod = 0.0f;
    lod = std::min(lod, v.max_lod);
    lod = std::max(lod, v.min_lod);
    float out[4];
    if (lod <= v.c || !(mip_linear || mip_nearest)) {
      // Magnification, or minification without mipmaps: the base level only.
      const GLenum f = lod <= v.c ? v.mag_filter : min_img;
      sample_level(levels[face][v.base_level], dims, f, fixed, ss, tt, rr, ref, out);
    } else if (mip_nearest) {
      const int d = v.base_level + static_cast<int>(std::floor(std::min(lod, 64.0f) + 0.5f));
      sample_level(levels[face][clampi(d, v.base_level, v.max_level)], dims, min_img, fixed, ss, tt,
                   rr, ref, out);
    } else {
      const float lc = std::min(lod, 64.0f);
      const float fl = std::floor(lc);
      int d0 = v.base_level + static_cast<int>(fl);
      float w = lc - fl;
      if (d0 >= v.max_level) {
        d0 = v.max_level;
        w = 0.0f;
      }
      sample_level(levels[face][d0], dims, min_img, fixed, ss, tt, rr, ref, out);
      if (fixed) {
        const int w8 = static_cast<int>(w * 256.0f);
        if (w8 > 0) {
          float o1[4];
          sample_level(levels[face][d0 + 1], dims, min_img, fixed, ss, tt, rr, ref, o1);
          for (int q = 0; q < 4; ++q) {
            const int a = static_cast<int>(std::lround(out[q] * 255.0f));
            const int b = static_cast<int>(std::lround(o1[q] * 255.0f));
            out[q] = float(lerp8(a, b, w8)) * (1.0f / 255.0f);
          }
        }
      } else if (w > 0.0f) {
        float o1[4];
        sample_level(levels[face][d0 + 1], dims, min_img, fixed, ss, tt, rr, ref, o1);
        for (int q = 0; q < 4; ++q)
          out[q] += w * (o1[q] - out[q]);
      }
    }
    if (v.is_depth) {
      expand_depth(v.base, out[0], rgba[i]);
    } else {
      for (int q = 0; q < 4; ++q)
        rgba[i][q] = out[q];
    }
  }
}

void downsample_texels(const TexelImage& src, const TexelImage& dst, int dims) {
  const int b = src.border;
  const int bj = dims >= 2 ? b : 0, bk = dims >= 3 ? b : 0;
  const int sw = src.width - 2 * b, sh = src.height - 2 * bj, sd = src.depth - 2 * bk;
  const int dw = dst.width - 2 * b, dh = dst.height - 2 * bj, dd = dst.depth - 2 * bk;
  auto src_index = [&](int i, int j, int k) {
    return (size_t(k + bk) * size_t(src.height) + size_t(j + bj)) * size_t(src.width) +
           size_t(i + b);
  };
  // Border texels (index -1 or size) map to the source border; others to the sample centre.
  auto axis = [](int i, int dsize, int ssize) {
    if (i < 0) return Axis{-1, -1, 0.0f, 0};
    if (i >= dsize) return Axis{ssize, ssize, 0.0f, 0};
    return axis_linear_fixed((float(i) + 0.5f) / float(dsize), ssize, GL_CLAMP_TO_EDGE);
  };
  size_t o = 0;
  for (int k = -bk; k < dd + bk; ++k) {
    const Axis ak = dims >= 3 ? axis(k, dd, sd) : Axis{0, 0, 0.0f, 0};
    for (int j = -bj; j < dh + bj; ++j) {
      const Axis aj = dims >= 2 ? axis(j, dh, sh) : Axis{0, 0, 0.0f, 0};
      for (int i = -b; i < dw + b; ++i, ++o) {
        const Axis ai = axis(i, dw, sw);
        if (src.is_depth) {
          float acc = 0.0f;
          for (int kk = 0; kk < (dims >= 3 ? 2 : 1); ++kk)
            for (int jj = 0; jj < (dims >= 2 ? 2 : 1); ++jj)
              for (int ii = 0; ii < 2; ++ii) {
                const float wi = ii ? ai.w : 1.0f - ai.w;
                const float wj = dims >= 2 ? (jj ? aj.w : 1.0f - aj.w) : 1.0f;
                const float wk = dims >= 3 ? (kk ? ak.w : 1.0f - ak.w) : 1.0f;
                acc += wi * wj * wk *
                       float(double(src.z[src_index(ii ? ai.i1 : ai.i0, jj ? aj.i1 : aj.i0,
                                                    kk ? ak.i1 : ak.i0)]) /
                             src.z_max);
              }
          dst.z_out[o] = uint32_t(std::nearbyint(std::clamp(double(acc), 0.0, 1.0) * src.z_max));
          continue;
        }
        int res[2][4] = {};
        for (int kk = 0; kk < (dims >= 3 ? 2 : 1); ++kk) {
          const int kz = kk ? ak.i1 : ak.i0;
          const uint8_t* t00 = &src.rgba[src_index(ai.i0, aj.i0, kz) * 4];
          const uint8_t* t10 = &src.rgba[src_index(ai.i1, aj.i0, kz) * 4];
          const uint8_t* t01 = &src.rgba[src_index(ai.i0, aj.i1, kz) * 4];
          const uint8_t* t11 = &src.rgba[src_index(ai.i1, aj.i1, kz) * 4];
          for (int q = 0; q < 4; ++q) {
            const int r0 = lerp8(t00[q], t10[q], ai.w8);
            res[kk][q] = dims >= 2 ? lerp8(r0, lerp8(t01[q], t11[q], ai.w8), aj.w8) : r0;
          }
        }
        for (int q = 0; q < 4; ++q)
          dst.rgba_out[o * 4 + q] =
              static_cast<uint8_t>(dims >= 3 ? lerp8(res[0][q], res[1][q], ak.w8) : res[0][q]);
      }
    }
  }
}

} // namespace pineda
