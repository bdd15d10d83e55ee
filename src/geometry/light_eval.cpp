// The GL 2.1 §2.14.1 lighting equation, evaluated in float per vertex as llvmpipe's
// fixed-function vertex program does, with everything that does not depend on the vertex
// computed once per draw by the lighting area (state/lighting.cpp, setup_lighting).
#include "geometry/light_eval.h"

#include <cmath>

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "core/vertex.h"

namespace pineda {

namespace {

inline float clamp01(float v) {
  return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;
}

// The geometric terms of one light at one vertex, shared by both faces.
struct LightTerms {
  float scale;    // att_i * spot_i
  float n_dot_vp; // n . VPpli, unclamped (the back face uses its negation)
  float n_dot_h;  // n . h_i (unit h), unclamped
};

// (n . h)^srm for a clamped n . h, with 0^0 = 1 as pow gives.
inline float spec_power(float n_dot_h, float shininess) {
  return lit_pow(n_dot_h > 0.0f ? n_dot_h : 0.0f, shininess);
}

// c_pri and c_sec of one face: `sign` is +1 for the front (n) and -1 for the back (-n).
[[gnu::always_inline]] inline void shade_face(const LightSetup& s, const LitFace& m,
                                              const LightTerms* terms, float sign, float* pri,
                                              float* sec) {
  for (int c = 0; c < 3; ++c) {
    pri[c] = m.base[c];
    sec[c] = 0.0f;
  }
  for (int i = 0; i < s.count; ++i) {
    const LightTerms& t = terms[i];
    if (t.scale == 0.0f) continue;
    const float ndl = sign * t.n_dot_vp;
    float dif = 0.0f, spe = 0.0f;
    if (ndl > 0.0f) { // f_i = 1 exactly when n . VPpli is positive (eq. 2.2)
      dif = ndl;
      spe = spec_power(sign * t.n_dot_h, m.shininess);
    }
    for (int c = 0; c < 3; ++c) {
      const float amb_dif = m.amb[i][c] + dif * m.dif[i][c];
      const float spec = spe * m.spe[i][c];
      if (s.separate_specular) {
        pri[c] += t.scale * amb_dif;
        sec[c] += t.scale * spec;
      } else {
        pri[c] += t.scale * (amb_dif + spec);
      }
    }
  }
  // §2.14.6 clamps both colours; the secondary alpha is 1.
  for (int c = 0; c < 3; ++c) {
    pri[c] = clamp01(pri[c]);
    sec[c] = clamp01(sec[c]);
  }
  pri[3] = m.alpha;
  sec[3] = 1.0f;
}

} // namespace

void prepare_lit_faces(const LightSetup& s, const Material* mat, const float color[4],
                       LitFaces& out) {
  const int faces = s.two_side ? 2 : 1;
  for (int f = 0; f < faces; ++f) {
    Material m = mat[f];
    if (s.track[f]) {
      for (int c = 0; c < 4; ++c) {
        if (s.track_ambient) m.ambient[c] = color[c];
        if (s.track_diffuse) m.diffuse[c] = color[c];
        if (s.track_specular) m.specular[c] = color[c];
        if (s.track_emission) m.emission[c] = color[c];
      }
    }
    LitFace& o = out.face[f];
    for (int c = 0; c < 3; ++c)
      o.base[c] = m.emission[c] + m.ambient[c] * s.scene_ambient[c];
    for (int i = 0; i < s.count; ++i) {
      const LightConstants& l = s.light[i];
      for (int c = 0; c < 3; ++c) {
        o.amb[i][c] = m.ambient[c] * l.ambient[c];
        o.dif[i][c] = m.diffuse[c] * l.diffuse[c];
        o.spe[i][c] = m.specular[c] * l.specular[c];
      }
    }
    o.shininess = m.shininess;
    // §2.14.1: A is the alpha of d_cm.
    o.alpha = clamp01(m.diffuse[3]);
  }
}

void light_vertex_faces(const LightSetup& s, const LitFaces& faces, const float pos[4],
                        const float normal[3], float* attr) {
  // Eye-space normal.
  const float* nm = s.normal_matrix;
  float n[3];
  for (int r = 0; r < 3; ++r)
    n[r] = nm[r] * normal[0] + nm[3 + r] * normal[1] + nm[6 + r] * normal[2];
  if (s.normalize) light_normalize3(n);

  // Eye-space position, needed for positional lights and the local viewer.
  float v[3] = {0.0f, 0.0f, 0.0f};
  if (s.need_eye_position) {
    const float* m = s.modelview;
    float e[4];
    for (int r = 0; r < 4; ++r)
      e[r] = m[r] * pos[0] + m[4 + r] * pos[1] + m[8 + r] * pos[2] + m[12 + r] * pos[3];
    const float inv_w = e[3] != 1.0f && e[3] != 0.0f ? 1.0f / e[3] : 1.0f;
    for (int c = 0; c < 3; ++c)
      v[c] = e[c] * inv_w;
  }
  // VPe: the unit vector from the vertex to the eye at the origin (local viewer).
  float ve[3] = {-v[0], -v[1], -v[2]};
  if (s.local_viewer) light_normalize3(ve);

  LightTerms terms[kMaxLights];
  for (int i = 0; i < s.count; ++i) {
    const LightConstants& l = s.light[i];
    LightTerms& t = terms[i];
    float vp[3], h[3];
    float scale = 1.0f;
    if (l.positional) {
      for (int c = 0; c < 3; ++c)
        vp[c] = l.position[c] - v[c];
      const float d2 = light_dot3(vp, vp);
      const float d = std::sqrt(d2);
      if (d > 0.0f) {
        const float inv = 1.0f / d;
        vp[0] *= inv, vp[1] *= inv, vp[2] *= inv;
      }
      if (l.attenuated) scale = 1.0f / (l.k[0] + l.k[1] * d + l.k[2] * d2);
      if (l.spot) {
        const float sd = -light_dot3(vp, l.spot_direction);
        scale *= sd >= l.spot_cos ? lit_pow(sd, l.spot_exponent) : 0.0f;
      }
    } else {
      for (int c = 0; c < 3; ++c)
        vp[c] = l.direction[c];
      scale = l.spot_factor;
    }
    if (s.local_viewer) {
      for (int c = 0; c < 3; ++c)
        h[c] = vp[c] + ve[c];
      light_normalize3(h);
    } else if (l.positional) {
      h[0] = vp[0], h[1] = vp[1], h[2] = vp[2] + 1.0f;
      light_normalize3(h);
    } else {
      h[0] = l.half[0], h[1] = l.half[1], h[2] = l.half[2];
    }
    t.scale = scale;
    t.n_dot_vp = light_dot3(n, vp);
    t.n_dot_h = light_dot3(n, h);
  }

  shade_face(s, faces.face[0], terms, 1.0f, attr + kAttrColor, attr + kAttrColor2);
  if (s.two_side)
    shade_face(s, faces.face[1], terms, -1.0f, attr + kAttrBackColor, attr + kAttrBackColor2);
}

void light_vertex(const LightSetup& s, const Material* mat, const float pos[4],
                  const float normal[3], const float color[4], float* attr) {
  LitFaces faces;
  prepare_lit_faces(s, mat, color, faces);
  light_vertex_faces(s, faces, pos, normal, attr);
}

} // namespace pineda
