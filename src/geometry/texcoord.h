// Per-vertex texture coordinates and fog coordinate (GL 2.1 §2.11.4 coordinate generation,
// §2.11.2 texture matrices, §3.10 fog coordinate): what the geometry stage writes into the
// PVertex slots kAttrTex0 + 4u and kAttrFog for the units and fog the fragment stage reads.
#pragma once

#include <GL/gl.h>

#include <cstdint>

#include "core/vertex.h"

namespace pineda {

struct TexVertexUnit {
  bool gen[4] = {false, false, false, false}; // generation on for s, t, r, q
  GLenum mode[4] = {GL_EYE_LINEAR, GL_EYE_LINEAR, GL_EYE_LINEAR, GL_EYE_LINEAR};
  float plane[4][4] = {}; // the object or eye plane the mode uses
  bool identity = true;   // texture matrix is the identity
  float matrix[16] = {};  // texture matrix, column-major
};

// Derived once per state change (validate_texpipe); plain data.
struct TexVertexSetup {
  uint32_t units = 0;          // bit u: unit u's coordinates are live
  bool need_eye = false;       // some generation mode reads eye coordinates
  bool need_normal = false;    // some generation mode reads the eye-space normal
  float modelview[16] = {};    // column-major
  float normal_matrix[9] = {}; // inverse transpose of the model-view's upper 3x3, column-major
  bool normalize = false;      // GL_NORMALIZE
  float rescale = 1.0f;        // GL_RESCALE_NORMAL factor (1 when off)
  bool fog = false;            // the fog coordinate is live
  bool fog_from_depth = false; // FOG_COORD_SRC is FRAGMENT_DEPTH: the eye-space distance
  // GL_FOG_HINT = FASTEST: kAttrFog receives the fog factor f (§3.10) instead of the
  // coordinate, from these parameters.
  bool fog_per_vertex = false;
  GLenum fog_mode = GL_EXP;
  float fog_density = 1.0f, fog_start = 0.0f, fog_end = 1.0f;
  TexVertexUnit unit[kMaxTexUnits];
};

// Writes attr[kAttrTex0 + 4u ..] for every live unit and attr[kAttrFog] when fog is live (the
// fog coordinate, or the fog factor with fog_per_vertex).
void tex_vertex(const TexVertexSetup& ts, const float pos[4], const float normal[3],
                const float (*tex)[4], float fog_coord, float* attr);

} // namespace pineda
