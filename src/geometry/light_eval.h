// Per-vertex fixed-function lighting (GL 2.1 §2.14.1): the materials and the per-draw constants
// the lighting area derives from its state (state/lighting.cpp), then the lighting equation for
// each vertex in eye coordinates.
#pragma once

#include <cmath>
#include <cstddef>

#include <glm/mat4x4.hpp>

#include "core/limits.h"

namespace pineda {

// Material parameters of one face (GL 2.1 Table 2.10).
struct Material {
  float ambient[4] = {0.2f, 0.2f, 0.2f, 1.0f};
  float diffuse[4] = {0.8f, 0.8f, 0.8f, 1.0f};
  float specular[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  float emission[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  float shininess = 0.0f;
  float color_indexes[3] = {0.0f, 1.0f, 1.0f}; // am, dm, sm: stored for queries only
};

// A Material call between Begin and End (GL 2.1 §2.14.2): from vertex `vertex` of the
// primitive on, both faces' materials are `material`.
struct MaterialChange {
  size_t vertex = 0;
  Material material[2];
};

// Per-draw constants of one enabled light, in eye coordinates.
struct LightConstants {
  float ambient[3] = {}, diffuse[3] = {}, specular[3] = {};
  bool positional = false;
  float position[3] = {};       // positional: the light's eye position
  float direction[3] = {};      // directional: VPpli, the unit vector towards the light
  float half[3] = {};           // directional with an infinite viewer: the unit half vector
  bool spot = false;            // cutoff != 180
  float spot_direction[3] = {}; // unit spot direction
  float spot_cos = 0.0f;        // cos(cutoff)
  float spot_exponent = 0.0f;
  float spot_factor = 1.0f; // directional spot lights: the spot term is constant
  bool attenuated = false;  // positional with attenuation other than (1, 0, 0)
  float k[3] = {1.0f, 0.0f, 0.0f};
};

// Everything the per-vertex evaluation reads, derived once per draw.
struct LightSetup {
  int count = 0;
  LightConstants light[kMaxLights];
  float scene_ambient[4] = {};
  bool local_viewer = false;
  bool two_side = false;
  bool separate_specular = false;
  // COLOR_MATERIAL: which properties of which faces take the vertex colour.
  bool track[2] = {false, false}; // front, back
  bool track_ambient = false, track_diffuse = false, track_specular = false, track_emission = false;
  // Normal transformation (GL 2.1 §2.11.3): inverse transpose of the model-view's upper 3x3,
  // column-major, with the rescale factor folded in.
  float normal_matrix[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  bool normalize = false;
  float modelview[16] = {}; // column-major, for eye-space vertex positions
  bool need_eye_position = false;
};

// x^y for the lighting equation's powers (the specular exponent, eq. 2.1, and the spot
// exponent, eq. 2.5), x >= 0 or NaN. An integer exponent up to 128 (the usual case) is
// computed by repeated squaring, a few multiplications instead of a library pow; each
// squaring doubles the relative error, so the result is within about y units in the last
// place (below 1e-5 relative, far below the 8-bit colour step). vertex_simd_impl.h does the
// same multiplications in its lanes, so every vertex gets the same colour whichever path
// lights it.
inline bool lit_pow_by_squaring(float y) {
  return y >= 0.0f && y <= 128.0f && static_cast<float>(static_cast<int>(y)) == y;
}
inline float lit_pow(float x, float y) {
  if (!lit_pow_by_squaring(y)) return std::pow(x, y);
  float r = 1.0f, b = x;
  for (auto n = static_cast<unsigned>(y); n != 0;) {
    if ((n & 1u) != 0) r *= b;
    n >>= 1;
    if (n != 0) b *= b;
  }
  return r;
}

inline float light_dot3(const float* a, const float* b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// Scale v to unit length; a zero vector stays zero.
inline void light_normalize3(float* v) {
  const float len2 = light_dot3(v, v);
  if (len2 > 0.0f) {
    const float inv = 1.0f / std::sqrt(len2);
    v[0] *= inv, v[1] *= inv, v[2] *= inv;
  }
}

// The terms of eq. 2.1 that depend on the material and the lights but not on the vertex, for
// the front [0] and back [1] face: made once per material while COLOR_MATERIAL is off, per
// vertex while it tracks the vertex colour.
struct LitFace {
  float base[3];            // e_cm + a_cm * a_cs
  float amb[kMaxLights][3]; // a_cm * a_cli
  float dif[kMaxLights][3]; // d_cm * d_cli
  float spe[kMaxLights][3]; // s_cm * s_cli
  float shininess;          // s_rm
  float alpha;              // the alpha of d_cm, clamped
};
struct LitFaces {
  LitFace face[2];
};

// The LitFaces of materials `mat` ([0] front, [1] back) with the vertex colour `color` for
// the tracked properties (§2.14.3).
void prepare_lit_faces(const LightSetup& s, const Material* mat, const float color[4],
                       LitFaces& out);

// Light one vertex from prepared faces; otherwise as light_vertex.
void light_vertex_faces(const LightSetup& s, const LitFaces& faces, const float pos[4],
                        const float normal[3], float* attr);

// Light one vertex: object position, object normal and vertex colour (the colour only matters
// for COLOR_MATERIAL) with the materials `mat` ([0] front, [1] back). Writes the clamped
// (§2.14.6) front primary colour to attr[kAttrColor..+4]; the secondary colour to
// attr[kAttrColor2..+4] with SEPARATE_SPECULAR_COLOR; and with two-sided lighting the back
// colours to attr[kAttrBackColor..] and attr[kAttrBackColor2..].
void light_vertex(const LightSetup& s, const Material* mat, const float pos[4],
                  const float normal[3], const float color[4], float* attr);

} // namespace pineda
