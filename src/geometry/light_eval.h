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

// Light one vertex: object position, object normal and vertex colour (the colour only matters
// for COLOR_MATERIAL) with the materials `mat` ([0] front, [1] back). Writes the clamped
// (§2.14.6) front primary colour to attr[kAttrColor..+4]; the secondary colour to
// attr[kAttrColor2..+4] with SEPARATE_SPECULAR_COLOR; and with two-sided lighting the back
// colours to attr[kAttrBackColor..] and attr[kAttrBackColor2..].
void light_vertex(const LightSetup& s, const Material* mat, const float pos[4],
                  const float normal[3], const float color[4], float* attr);

} // namespace pineda
