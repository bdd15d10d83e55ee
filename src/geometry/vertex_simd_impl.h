// The bodies of vertex_simd.h for N lanes (4: SSE2 or any target, vertex_simd.cpp; 8: AVX2,
// vertex_simd_avx2.cpp; 16: AVX-512, vertex_simd_avx512.cpp). Each function mirrors a scalar
// one expression by expression: the same operands, the same association, no fused
// multiply-add (the AVX2 and AVX-512 files are compiled with -ffp-contract=off), and a select
// where the scalar code branches per vertex, so every lane gets the scalar result.
//
// Everything here has internal linkage and calls no inline function of another header: the
// file is compiled for three instruction sets, and a shared inline function could be linked
// from the AVX2 or AVX-512 copy into the code that runs on any x86-64.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

#include "geometry/input_vertex.h"
#include "geometry/clip.h"
#include "geometry/light_eval.h"
#include "core/vertex.h"

#if defined(__SSE2__)
#include <immintrin.h>
#endif

namespace pineda {
namespace {

template <int N> struct Lanes;
template <> struct Lanes<4> {
  using V = float __attribute__((vector_size(16)));
  using M = int32_t __attribute__((vector_size(16)));
};
template <> struct Lanes<8> {
  using V = float __attribute__((vector_size(32)));
  using M = int32_t __attribute__((vector_size(32)));
};
template <> struct Lanes<16> {
  using V = float __attribute__((vector_size(64)));
  using M = int32_t __attribute__((vector_size(64)));
};

using F4 = Lanes<4>::V;
using F8 = Lanes<8>::V;

inline F4 load_f4(const float* p) {
  F4 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

// Rows a..d become columns: out[j] holds element j of a, b, c, d.
inline void transpose_f4(F4 a, F4 b, F4 c, F4 d, F4 out[4]) {
  const F4 t0 = __builtin_shufflevector(a, b, 0, 4, 1, 5);
  const F4 t1 = __builtin_shufflevector(a, b, 2, 6, 3, 7);
  const F4 t2 = __builtin_shufflevector(c, d, 0, 4, 1, 5);
  const F4 t3 = __builtin_shufflevector(c, d, 2, 6, 3, 7);
  out[0] = __builtin_shufflevector(t0, t2, 0, 1, 4, 5);
  out[1] = __builtin_shufflevector(t0, t2, 2, 3, 6, 7);
  out[2] = __builtin_shufflevector(t1, t3, 0, 1, 4, 5);
  out[3] = __builtin_shufflevector(t1, t3, 2, 3, 6, 7);
}

template <int N> struct Simd {
  using V = typename Lanes<N>::V;
  using M = typename Lanes<N>::M;

  static V splat(float x) { return V{} + x; }
  static M bit(uint32_t b) { return M{} + static_cast<int32_t>(b); }

  // Four floats at `offset` bytes into each of N consecutive InputVertex, as columns.
  static void gather(const InputVertex* in, size_t offset, V out[4]) {
    const auto row = [in, offset](int k) {
      return load_f4(
          reinterpret_cast<const float*>(reinterpret_cast<const uint8_t*>(in + k) + offset));
    };
    F4 lo[4];
    transpose_f4(row(0), row(1), row(2), row(3), lo);
    if constexpr (N == 4) {
      for (int j = 0; j < 4; ++j)
        out[j] = lo[j];
    } else if constexpr (N == 8) {
      F4 hi[4];
      transpose_f4(row(4), row(5), row(6), row(7), hi);
      for (int j = 0; j < 4; ++j)
        out[j] = __builtin_shufflevector(lo[j], hi[j], 0, 1, 2, 3, 4, 5, 6, 7);
    } else {
      // Four groups of four vertices, joined into halves of eight, then into sixteen.
      F4 q1[4], q2[4], q3[4];
      transpose_f4(row(4), row(5), row(6), row(7), q1);
      transpose_f4(row(8), row(9), row(10), row(11), q2);
      transpose_f4(row(12), row(13), row(14), row(15), q3);
      for (int j = 0; j < 4; ++j) {
        const F8 a = __builtin_shufflevector(lo[j], q1[j], 0, 1, 2, 3, 4, 5, 6, 7);
        const F8 b = __builtin_shufflevector(q2[j], q3[j], 0, 1, 2, 3, 4, 5, 6, 7);
        out[j] =
            __builtin_shufflevector(a, b, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
      }
    }
  }

  // Columns c[0..3] (component j of N vertices) written as four floats at `offset` bytes into
  // each of N consecutive PVertex.
  static void scatter(const V c[4], PVertex* out, size_t offset) {
    const auto store = [out, offset](int k, F4 v) {
      std::memcpy(reinterpret_cast<uint8_t*>(out + k) + offset, &v, sizeof v);
    };
    F4 rows[4];
    if constexpr (N == 4) {
      transpose_f4(c[0], c[1], c[2], c[3], rows);
      for (int k = 0; k < 4; ++k)
        store(k, rows[k]);
    } else if constexpr (N == 8) {
      for (int half = 0; half < 2; ++half) {
        F4 part[4];
        for (int j = 0; j < 4; ++j)
          part[j] = half == 0 ? __builtin_shufflevector(c[j], c[j], 0, 1, 2, 3)
                              : __builtin_shufflevector(c[j], c[j], 4, 5, 6, 7);
        transpose_f4(part[0], part[1], part[2], part[3], rows);
        for (int k = 0; k < 4; ++k)
          store(4 * half + k, rows[k]);
      }
    } else {
      for (int quarter = 0; quarter < 4; ++quarter) {
        F4 part[4];
        for (int j = 0; j < 4; ++j)
          part[j] = quarter16(c[j], quarter);
        transpose_f4(part[0], part[1], part[2], part[3], rows);
        for (int k = 0; k < 4; ++k)
          store(4 * quarter + k, rows[k]);
      }
    }
  }

  // Lanes 4q .. 4q + 3 of a sixteen-lane vector.
  static F4 quarter16(V v, int q) {
    if constexpr (N == 16) {
      switch (q) {
      case 0:
        return __builtin_shufflevector(v, v, 0, 1, 2, 3);
      case 1:
        return __builtin_shufflevector(v, v, 4, 5, 6, 7);
      case 2:
        return __builtin_shufflevector(v, v, 8, 9, 10, 11);
      default:
        return __builtin_shufflevector(v, v, 12, 13, 14, 15);
      }
    }
    return F4{};
  }

  static V vsqrt(V v) {
#if defined(__AVX512F__)
    // The zero-masking form with every lane selected: GCC 12 warns about the undefined
    // pass-through operand of _mm512_sqrt_ps (-Wmaybe-uninitialized).
    if constexpr (N == 16) return _mm512_maskz_sqrt_ps(static_cast<__mmask16>(0xffff), v);
#endif
#if defined(__AVX__)
    if constexpr (N == 8) return _mm256_sqrt_ps(v);
#endif
#if defined(__SSE2__)
    if constexpr (N == 4) return _mm_sqrt_ps(v);
#endif
    for (int k = 0; k < N; ++k)
      v[k] = __builtin_sqrtf(v[k]);
    return v;
  }

  // !(d >= 0): set for a negative distance and for NaN, as clip_code tests.
  static M outside(V d) {
    return ~(d >= 0.0f);
  }

  static V dot3(const V a[3], const V b[3]) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  }

  // normalize3 of light_eval.cpp: lanes of zero (or NaN) length stay as they are.
  static void normalize3(V v[3]) {
    const V len2 = dot3(v, v);
    const M live = len2 > 0.0f;
    const V inv = 1.0f / vsqrt(live ? len2 : splat(1.0f));
    for (int c = 0; c < 3; ++c)
      v[c] = live ? v[c] * inv : v[c];
  }

  static V clamp01(V v) {
    return v > 0.0f ? (v < 1.0f ? v : splat(1.0f)) : splat(0.0f);
  }

  // lit_pow (light_eval.h) where `mask` is set, 0 elsewhere: the same multiplications in
  // every lane for an integer exponent, else powf lane by lane.
  static V pow_lanes(M mask, V x, float y) {
    // lit_pow_by_squaring, repeated here: no inline function of another header (see above).
    if (y >= 0.0f && y <= 128.0f && static_cast<float>(static_cast<int>(y)) == y) {
      V r = splat(1.0f), b = x;
      for (auto n = static_cast<unsigned>(y); n != 0;) {
        if ((n & 1u) != 0) r *= b;
        n >>= 1;
        if (n != 0) b *= b;
      }
      return mask ? r : splat(0.0f);
    }
    V r = {};
    for (int k = 0; k < N; ++k)
      if (mask[k] != 0) r[k] = __builtin_powf(x[k], y);
    return r;
  }

  struct Terms {
    V scale, n_dot_vp, n_dot_h;
  };

  // shade_face of light_eval.cpp.
  static void shade_face(const LightSetup& s, const LitFace& m, const Terms* terms, float sign,
                         V pri[4], V sec[4]) {
    for (int c = 0; c < 3; ++c) {
      pri[c] = splat(m.base[c]);
      sec[c] = V{};
    }
    for (int i = 0; i < s.count; ++i) {
      const Terms& t = terms[i];
      const M live = t.scale != 0.0f;
      const V ndl = sign * t.n_dot_vp;
      const M lit = live & (ndl > 0.0f);
      const V dif = lit ? ndl : splat(0.0f);
      // spec_power: (n . h)^srm with n . h clamped at 0.
      const V ndh = sign * t.n_dot_h;
      const V spe = pow_lanes(lit, ndh > 0.0f ? ndh : splat(0.0f), m.shininess);
      for (int c = 0; c < 3; ++c) {
        const V amb_dif = m.amb[i][c] + dif * m.dif[i][c];
        const V spec = spe * m.spe[i][c];
        if (s.separate_specular) {
          pri[c] = live ? pri[c] + t.scale * amb_dif : pri[c];
          sec[c] = live ? sec[c] + t.scale * spec : sec[c];
        } else {
          pri[c] = live ? pri[c] + t.scale * (amb_dif + spec) : pri[c];
        }
      }
    }
    for (int c = 0; c < 3; ++c) {
      pri[c] = clamp01(pri[c]);
      sec[c] = clamp01(sec[c]);
    }
    pri[3] = splat(m.alpha);
    sec[3] = splat(1.0f);
  }

  // light_vertex_faces of light_eval.cpp for N vertices.
  static void light(const LightSetup& s, const LitFaces& faces, const InputVertex* in,
                    PVertex* out) {
    V nin[4]; // normal[0..2] and the float after it (color2[0]), which is ignored
    gather(in, offsetof(InputVertex, normal), nin);
    const float* nm = s.normal_matrix;
    V n[3];
    for (int r = 0; r < 3; ++r)
      n[r] = nm[r] * nin[0] + nm[3 + r] * nin[1] + nm[6 + r] * nin[2];
    if (s.normalize) normalize3(n);

    V v[3] = {};
    if (s.need_eye_position) {
      V p[4];
      gather(in, offsetof(InputVertex, pos), p);
      const float* m = s.modelview;
      V e[4];
      for (int r = 0; r < 4; ++r)
        e[r] = m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r] * p[3];
      const M divide = (e[3] != 1.0f) & (e[3] != 0.0f);
      const V inv_w = divide ? 1.0f / (divide ? e[3] : splat(1.0f)) : splat(1.0f);
      for (int c = 0; c < 3; ++c)
        v[c] = e[c] * inv_w;
    }
    V ve[3] = {-v[0], -v[1], -v[2]};
    if (s.local_viewer) normalize3(ve);

    Terms terms[kMaxLights];
    for (int i = 0; i < s.count; ++i) {
      const LightConstants& l = s.light[i];
      V vp[3], h[3];
      V scale = splat(1.0f);
      if (l.positional) {
        for (int c = 0; c < 3; ++c)
          vp[c] = l.position[c] - v[c];
        const V d2 = dot3(vp, vp);
        const V d = vsqrt(d2);
        const M live = d > 0.0f;
        const V inv = 1.0f / (live ? d : splat(1.0f));
        for (int c = 0; c < 3; ++c)
          vp[c] = live ? vp[c] * inv : vp[c];
        if (l.attenuated) scale = 1.0f / (l.k[0] + l.k[1] * d + l.k[2] * d2);
        if (l.spot) {
          const V sd = -(vp[0] * l.spot_direction[0] + vp[1] * l.spot_direction[1] +
                         vp[2] * l.spot_direction[2]);
          scale *= pow_lanes(sd >= l.spot_cos, sd, l.spot_exponent);
        }
      } else {
        for (int c = 0; c < 3; ++c)
          vp[c] = splat(l.direction[c]);
        scale = splat(l.spot_factor);
      }
      if (s.local_viewer) {
        for (int c = 0; c < 3; ++c)
          h[c] = vp[c] + ve[c];
        normalize3(h);
      } else if (l.positional) {
        h[0] = vp[0], h[1] = vp[1], h[2] = vp[2] + 1.0f;
        normalize3(h);
      } else {
        for (int c = 0; c < 3; ++c)
          h[c] = splat(l.half[c]);
      }
      terms[i].scale = scale;
      terms[i].n_dot_vp = dot3(n, vp);
      terms[i].n_dot_h = dot3(n, h);
    }

    constexpr size_t kAttr = offsetof(PVertex, attr);
    V pri[4], sec[4];
    shade_face(s, faces.face[0], terms, 1.0f, pri, sec);
    scatter(pri, out, kAttr + sizeof(float) * kAttrColor);
    scatter(sec, out, kAttr + sizeof(float) * kAttrColor2);
    if (s.two_side) {
      shade_face(s, faces.face[1], terms, -1.0f, pri, sec);
      scatter(pri, out, kAttr + sizeof(float) * kAttrBackColor);
      scatter(sec, out, kAttr + sizeof(float) * kAttrBackColor2);
    }
  }

  // The composite transform, clip_code (clip.cpp) and to_window (raster.h) for N vertices.
  static void transform(const float* m, const ClipSetup& cs, const Viewport& vp,
                        const InputVertex* in, PVertex* out) {
    V p[4];
    gather(in, offsetof(InputVertex, pos), p);
    V c[4];
    for (int r = 0; r < 4; ++r)
      c[r] = m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r] * p[3];
    const V x = c[0], y = c[1], z = c[2], w = c[3];

    // The frustum planes in ClipBit order, the user planes, the guard band.
    M code = (outside(x + w) & bit(kClipLeft)) | (outside(w - x) & bit(kClipRight)) |
             (outside(y + w) & bit(kClipBottom)) | (outside(w - y) & bit(kClipTop)) |
             (outside(z + w) & bit(kClipNear)) | (outside(w - z) & bit(kClipFar));
    for (int i = 0; i < 6; ++i) {
      if ((cs.user_mask & (1u << i)) == 0) continue;
      const float* q = cs.user[i];
      code |= outside(q[0] * x + q[1] * y + q[2] * z + q[3] * w) & bit(kClipUser0 << i);
    }
    const M guard = ~((w >= __FLT_MIN__) & (w <= __FLT_MAX__)) | outside(x - cs.gx0 * w) |
                    outside(cs.gx1 * w - x) | outside(y - cs.gy0 * w) | outside(cs.gy1 * w - y);
    code |= guard & bit(kClipGuard);

    // Window coordinates for the lanes with a zero code; the others' are not valid
    // (vertex.h) and get those of w = 1.
    const V inv_w = 1.0f / (code == 0 ? w : splat(1.0f));
    const V xd = x * inv_w, yd = y * inv_w, zd = z * inv_w;
    const V win[4] = {vp.x + (xd + 1.0f) * 0.5f * vp.w, vp.y + (yd + 1.0f) * 0.5f * vp.h,
                      vp.near + (zd + 1.0f) * 0.5f * (vp.far - vp.near), inv_w};
    scatter(c, out, offsetof(PVertex, clip));
    scatter(win, out, offsetof(PVertex, win));
    for (int k = 0; k < N; ++k)
      out[k].clipmask = static_cast<uint32_t>(code[k]);
  }
};

} // namespace
} // namespace pineda
