// Four vertices at a time (vertex_simd.h). Each function mirrors a scalar one expression by
// expression: the same operands, the same association, no fused multiply-add, and a select
// where the scalar code branches per vertex, so every lane gets the scalar result.
#include "geometry/vertex_simd.h"

#include <cmath>
#include <cstring>
#include <limits>

#include "fragment/simd.h"
#include "raster/raster.h"

namespace pineda {

namespace {

using m32x4 = i32x4; // lane masks: all ones or zero

inline f32x4 load4(const float* p) {
  f32x4 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
inline void store4(float* p, f32x4 v) {
  std::memcpy(p, &v, sizeof v);
}
inline f32x4 splat(float x) {
  return f32x4{} + x;
}
// A clip code bit in every lane.
inline m32x4 bit(uint32_t b) {
  return m32x4{} + static_cast<int32_t>(b);
}

// Rows a..d become columns: out[j] holds element j of a, b, c, d.
inline void transpose4(f32x4 a, f32x4 b, f32x4 c, f32x4 d, f32x4 out[4]) {
  const f32x4 t0 = __builtin_shufflevector(a, b, 0, 4, 1, 5);
  const f32x4 t1 = __builtin_shufflevector(a, b, 2, 6, 3, 7);
  const f32x4 t2 = __builtin_shufflevector(c, d, 0, 4, 1, 5);
  const f32x4 t3 = __builtin_shufflevector(c, d, 2, 6, 3, 7);
  out[0] = __builtin_shufflevector(t0, t2, 0, 1, 4, 5);
  out[1] = __builtin_shufflevector(t0, t2, 2, 3, 6, 7);
  out[2] = __builtin_shufflevector(t1, t3, 0, 1, 4, 5);
  out[3] = __builtin_shufflevector(t1, t3, 2, 3, 6, 7);
}

// Four floats at byte offset `field` of four consecutive InputVertex, as columns.
inline void gather4(const InputVertex* in, const float* (*field)(const InputVertex&),
                    f32x4 out[4]) {
  transpose4(load4(field(in[0])), load4(field(in[1])), load4(field(in[2])), load4(field(in[3])),
             out);
}
inline const float* pos_of(const InputVertex& v) {
  return v.pos;
}
// Reads normal[0..2] and the float after it (color2[0]), which is ignored.
inline const float* normal_of(const InputVertex& v) {
  return v.normal;
}

// Columns c[0..3] (component j of four vertices) written as four floats at dst(k).
template <typename Dst> inline void scatter4(const f32x4 c[4], Dst dst) {
  f32x4 rows[4];
  transpose4(c[0], c[1], c[2], c[3], rows);
  for (int k = 0; k < 4; ++k)
    store4(dst(k), rows[k]);
}

inline f32x4 vsqrt(f32x4 v) {
#if defined(__SSE2__)
  return _mm_sqrt_ps(v);
#else
  for (int k = 0; k < 4; ++k)
    v[k] = std::sqrt(v[k]);
  return v;
#endif
}

// !(d >= 0): set for a negative distance and for NaN, as clip_code tests.
inline m32x4 outside(f32x4 d) {
  return ~(d >= 0.0f);
}

inline f32x4 dot3(const f32x4 a[3], const f32x4 b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// normalize3 of light_eval.cpp: lanes of zero (or NaN) length stay as they are.
inline void normalize3(f32x4 v[3]) {
  const f32x4 len2 = dot3(v, v);
  const m32x4 live = len2 > 0.0f;
  const f32x4 inv = 1.0f / vsqrt(live ? len2 : splat(1.0f));
  for (int c = 0; c < 3; ++c)
    v[c] = live ? v[c] * inv : v[c];
}

inline f32x4 clamp01(f32x4 v) {
  return v > 0.0f ? (v < 1.0f ? v : splat(1.0f)) : splat(0.0f);
}

// f(x) lane by lane where `mask` is set, 0 elsewhere: pow has no vector form that matches the
// scalar library's results.
template <typename F> inline f32x4 per_lane(m32x4 mask, f32x4 x, F f) {
  f32x4 r = {};
  for (int k = 0; k < 4; ++k)
    if (mask[k] != 0) r[k] = f(x[k]);
  return r;
}

struct LightTerms4 {
  f32x4 scale, n_dot_vp, n_dot_h;
};

// shade_face of light_eval.cpp on four lanes.
void shade_face4(const LightSetup& s, const LitFace& m, const LightTerms4* terms, float sign,
                 f32x4 pri[4], f32x4 sec[4]) {
  for (int c = 0; c < 3; ++c) {
    pri[c] = splat(m.base[c]);
    sec[c] = f32x4{};
  }
  for (int i = 0; i < s.count; ++i) {
    const LightTerms4& t = terms[i];
    const m32x4 live = t.scale != 0.0f;
    const f32x4 ndl = sign * t.n_dot_vp;
    const m32x4 lit = live & (ndl > 0.0f);
    const f32x4 dif = lit ? ndl : splat(0.0f);
    const float shininess = m.shininess;
    const f32x4 spe = per_lane(lit, sign * t.n_dot_h, [shininess](float ndh) {
      return std::pow(ndh > 0.0f ? ndh : 0.0f, shininess);
    });
    for (int c = 0; c < 3; ++c) {
      const f32x4 amb_dif = m.amb[i][c] + dif * m.dif[i][c];
      const f32x4 spec = spe * m.spe[i][c];
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

void light4(const LightSetup& s, const LitFaces& faces, const InputVertex* in, PVertex* out) {
  f32x4 nin[4];
  gather4(in, normal_of, nin);
  const float* nm = s.normal_matrix;
  f32x4 n[3];
  for (int r = 0; r < 3; ++r)
    n[r] = nm[r] * nin[0] + nm[3 + r] * nin[1] + nm[6 + r] * nin[2];
  if (s.normalize) normalize3(n);

  f32x4 v[3] = {};
  if (s.need_eye_position) {
    f32x4 p[4];
    gather4(in, pos_of, p);
    const float* m = s.modelview;
    f32x4 e[4];
    for (int r = 0; r < 4; ++r)
      e[r] = m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r] * p[3];
    const m32x4 divide = (e[3] != 1.0f) & (e[3] != 0.0f);
    const f32x4 inv_w = divide ? 1.0f / (divide ? e[3] : splat(1.0f)) : splat(1.0f);
    for (int c = 0; c < 3; ++c)
      v[c] = e[c] * inv_w;
  }
  f32x4 ve[3] = {-v[0], -v[1], -v[2]};
  if (s.local_viewer) normalize3(ve);

  LightTerms4 terms[kMaxLights];
  for (int i = 0; i < s.count; ++i) {
    const LightConstants& l = s.light[i];
    f32x4 vp[3], h[3];
    f32x4 scale = splat(1.0f);
    if (l.positional) {
      for (int c = 0; c < 3; ++c)
        vp[c] = l.position[c] - v[c];
      const f32x4 d2 = dot3(vp, vp);
      const f32x4 d = vsqrt(d2);
      const m32x4 live = d > 0.0f;
      const f32x4 inv = 1.0f / (live ? d : splat(1.0f));
      for (int c = 0; c < 3; ++c)
        vp[c] = live ? vp[c] * inv : vp[c];
      if (l.attenuated) scale = 1.0f / (l.k[0] + l.k[1] * d + l.k[2] * d2);
      if (l.spot) {
        const f32x4 sd = -(vp[0] * l.spot_direction[0] + vp[1] * l.spot_direction[1] +
                           vp[2] * l.spot_direction[2]);
        const float exponent = l.spot_exponent;
        scale *=
            per_lane(sd >= l.spot_cos, sd, [exponent](float x) { return std::pow(x, exponent); });
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

  f32x4 pri[4], sec[4];
  shade_face4(s, faces.face[0], terms, 1.0f, pri, sec);
  scatter4(pri, [out](int k) { return out[k].attr + kAttrColor; });
  scatter4(sec, [out](int k) { return out[k].attr + kAttrColor2; });
  if (s.two_side) {
    shade_face4(s, faces.face[1], terms, -1.0f, pri, sec);
    scatter4(pri, [out](int k) { return out[k].attr + kAttrBackColor; });
    scatter4(sec, [out](int k) { return out[k].attr + kAttrBackColor2; });
  }
}

void transform4(const float* m, const ClipSetup& cs, const Viewport& vp, const InputVertex* in,
                PVertex* out) {
  f32x4 p[4];
  gather4(in, pos_of, p);
  f32x4 c[4];
  for (int r = 0; r < 4; ++r)
    c[r] = m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r] * p[3];
  const f32x4 x = c[0], y = c[1], z = c[2], w = c[3];

  // clip_code (clip.cpp): the frustum planes in ClipBit order, the user planes, the guard band.
  m32x4 code = (outside(x + w) & bit(kClipLeft)) | (outside(w - x) & bit(kClipRight)) |
               (outside(y + w) & bit(kClipBottom)) | (outside(w - y) & bit(kClipTop)) |
               (outside(z + w) & bit(kClipNear)) | (outside(w - z) & bit(kClipFar));
  for (int i = 0; i < 6; ++i) {
    if ((cs.user_mask & (1u << i)) == 0) continue;
    const float* q = cs.user[i];
    code |= outside(q[0] * x + q[1] * y + q[2] * z + q[3] * w) & bit(kClipUser0 << i);
  }
  const m32x4 guard =
      ~((w >= std::numeric_limits<float>::min()) & (w <= std::numeric_limits<float>::max())) |
      outside(x - cs.gx0 * w) | outside(cs.gx1 * w - x) | outside(y - cs.gy0 * w) |
      outside(cs.gy1 * w - y);
  code |= guard & bit(kClipGuard);

  // to_window (raster.h) for the lanes with a zero code; the others' window coordinates are
  // not valid (vertex.h) and get those of w = 1.
  const f32x4 inv_w = 1.0f / (code == 0 ? w : splat(1.0f));
  const f32x4 xd = x * inv_w, yd = y * inv_w, zd = z * inv_w;
  const f32x4 win[4] = {vp.x + (xd + 1.0f) * 0.5f * vp.w, vp.y + (yd + 1.0f) * 0.5f * vp.h,
                        vp.near + (zd + 1.0f) * 0.5f * (vp.far - vp.near), inv_w};
  scatter4(c, [out](int k) { return out[k].clip; });
  scatter4(win, [out](int k) { return out[k].win; });
  for (int k = 0; k < 4; ++k)
    out[k].clipmask = static_cast<uint32_t>(code[k]);
}

} // namespace

void transform_positions(const float* m, const ClipSetup& cs, const Viewport& vp,
                         const InputVertex* in, PVertex* out, size_t n) {
  size_t i = 0;
  for (; i + 4 <= n; i += 4)
    transform4(m, cs, vp, in + i, out + i);
  for (; i < n; ++i) {
    const float* pos = in[i].pos;
    PVertex& p = out[i];
    for (int r = 0; r < 4; ++r)
      p.clip[r] = m[r] * pos[0] + m[4 + r] * pos[1] + m[8 + r] * pos[2] + m[12 + r] * pos[3];
    p.clipmask = clip_code(cs, p.clip);
    if (p.clipmask == 0) to_window(p, vp);
  }
}

void light_vertices(const LightSetup& s, const LitFaces& faces, const InputVertex* in, PVertex* out,
                    size_t n) {
  size_t i = 0;
  for (; i + 4 <= n; i += 4)
    light4(s, faces, in + i, out + i);
  for (; i < n; ++i)
    light_vertex_faces(s, faces, in[i].pos, in[i].normal, out[i].attr);
}

} // namespace pineda
