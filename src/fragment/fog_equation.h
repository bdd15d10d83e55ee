// The fog blend factor f of GL 2.1 §3.10 (eq 3.31-3.33), clamped to [0,1]: one definition for
// the fragment stage (fragment/shade.cpp, per fragment) and the geometry stage
// (geometry/texcoord.cpp, per vertex under GL_FOG_HINT = FASTEST).
#pragma once

#include <GL/gl.h>

#include <cmath>

namespace pineda {

inline float fog_equation(GLenum mode, float density, float start, float end, float c) {
  float f;
  switch (mode) {
  case GL_LINEAR: {
    // eq 3.33: f = (e - c) / (e - s); equal start and end leave no fog range.
    const float range = end - start;
    f = range != 0.0f ? (end - c) / range : 1.0f;
    break;
  }
  case GL_EXP: // eq 3.31
    f = std::exp(-density * c);
    break;
  default: { // EXP2, eq 3.32
    const float dc = density * c;
    f = std::exp(-dc * dc);
    break;
  }
  }
  // "No matter which equation and approximation is used to compute f, the result is clamped
  // to [0, 1]"; NaN (infinite coordinates) becomes 0.
  return f > 0.0f ? (f < 1.0f ? f : 1.0f) : 0.0f;
}

} // namespace pineda
