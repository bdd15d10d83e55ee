// Per-vertex fixed-function lighting (GL 2.1 §2.14.1): per-draw constants from the lighting
// state, then the lighting equation for each vertex in eye coordinates.
#pragma once

#include <glm/mat4x4.hpp>

#include "state/lighting_state.h"

namespace pineda {

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
