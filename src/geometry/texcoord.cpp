// Per-vertex texture coordinates and fog coordinate (GL 2.1 §2.11.4, §2.11.2, §3.10).
#include "geometry/texcoord.h"

#include <cmath>

#include "fragment/fog_equation.h"

namespace pineda {

namespace {

inline float dot4(const float* a, const float* b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
}

} // namespace

void tex_vertex(const TexVertexSetup& ts, const float pos[4], const float normal[3],
                const float (*tex)[4], float fog_coord, float* attr) {
  float eye[4] = {0, 0, 0, 1};
  const float* m = ts.modelview;
  if (ts.need_eye || ts.fog_from_depth) {
    for (int r = 0; r < 4; ++r)
      eye[r] = m[r] * pos[0] + m[4 + r] * pos[1] + m[8 + r] * pos[2] + m[12 + r] * pos[3];
  }
  float n[4] = {0, 0, 1, 0}; // the fourth entries keep q (never generated from them) in bounds
  float refl[4] = {0, 0, 0, 0};
  if (ts.need_normal) {
    // §2.11.3: the eye-space normal, rescaled or normalized as for lighting.
    const float* q = ts.normal_matrix;
    for (int r = 0; r < 3; ++r)
      n[r] = (q[r] * normal[0] + q[3 + r] * normal[1] + q[6 + r] * normal[2]) * ts.rescale;
    if (ts.normalize) {
      const float len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      if (len > 0.0f)
        for (float& c : n)
          c /= len;
    }
    // §2.11.4: u is the unit vector from the origin to the vertex in eye coordinates and
    // r = u - 2 n (n . u) its reflection.
    float u[3] = {eye[0], eye[1], eye[2]};
    const float ulen = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    if (ulen > 0.0f)
      for (float& c : u)
        c /= ulen;
    const float nu = n[0] * u[0] + n[1] * u[1] + n[2] * u[2];
    for (int k = 0; k < 3; ++k)
      refl[k] = u[k] - 2.0f * n[k] * nu;
  }
  for (uint32_t bits = ts.units; bits != 0; bits &= bits - 1) {
    const int u = __builtin_ctz(bits);
    const TexVertexUnit& tu = ts.unit[u];
    float tc[4] = {tex[u][0], tex[u][1], tex[u][2], tex[u][3]};
    for (int c = 0; c < 4; ++c) {
      if (!tu.gen[c]) continue;
      switch (tu.mode[c]) {
      case GL_OBJECT_LINEAR:
        tc[c] = dot4(tu.plane[c], pos);
        break;
      case GL_EYE_LINEAR:
        tc[c] = dot4(tu.plane[c], eye);
        break;
      case GL_SPHERE_MAP: {
        // §2.11.4 eq 2.6: m = 2 sqrt(rx^2 + ry^2 + (rz + 1)^2); s = rx/m + 1/2, t = ry/m + 1/2.
        const float mm = 2.0f * std::sqrt(refl[0] * refl[0] + refl[1] * refl[1] +
                                          (refl[2] + 1.0f) * (refl[2] + 1.0f));
        tc[c] = (mm > 0.0f ? refl[c] / mm : 0.0f) + 0.5f;
        break;
      }
      case GL_REFLECTION_MAP:
        tc[c] = refl[c];
        break;
      case GL_NORMAL_MAP:
        tc[c] = n[c];
        break;
      default:
        break;
      }
    }
    float* out = attr + kAttrTex0 + 4 * u;
    if (tu.identity) {
      for (int k = 0; k < 4; ++k)
        out[k] = tc[k];
    } else {
      const float* t = tu.matrix;
      for (int r = 0; r < 4; ++r)
        out[r] = t[r] * tc[0] + t[4 + r] * tc[1] + t[8 + r] * tc[2] + t[12 + r] * tc[3];
    }
  }
  if (ts.fog) {
    // §3.10: with FOG_COORD_SRC = FRAGMENT_DEPTH the coordinate is the eye-space distance,
    // approximated (as Mesa does) by the absolute eye z.
    const float c = ts.fog_from_depth ? std::fabs(eye[2]) : fog_coord;
    // §3.10: "f need not be computed at each fragment, but may be computed at each vertex and
    // interpolated as other data are"; GL_FOG_HINT = FASTEST asks for that (§5.6).
    attr[kAttrFog] = ts.fog_per_vertex
                         ? fog_equation(ts.fog_mode, ts.fog_density, ts.fog_start, ts.fog_end, c)
                         : c;
  }
}

} // namespace pineda
