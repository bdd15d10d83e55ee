// Per-vertex fixed-function lighting (GL 2.1 §2.14.1): per-draw constants from the lighting
// state, then the lighting equation for each vertex in eye coordinates.
#pragma once

#include <cmath>

#include <glm/mat4x4.hpp>

#include "state/lighting_state.h"

namespace pineda {

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

// Fill `s` from the lighting state and the current model-view matrix. Called by validation
// whenever lighting state, the normalize / rescale enables or the model-view changed.
void setup_lighting(LightSetup& s, const LightingState& ls, const glm::mat4& modelview,
                    bool normalize, bool rescale);

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
