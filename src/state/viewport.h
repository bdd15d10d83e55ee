// Viewport and depth range (GL 2.1 §2.11.1; Table 6.8 "Viewport", the "viewport" attribute
// group). Commands in viewport.cpp.
#pragma once

#include <GL/gl.h>

namespace pineda {

struct StateArea;

// VIEWPORT_BIT: Table 6.8.
struct ViewportGroup {
  GLint x = 0, y = 0;
  GLsizei w = 0, h = 0;
  double near = 0.0, far = 1.0; // DEPTH_RANGE, clamped to [0, 1]
};

extern const StateArea kViewportArea; // viewport.cpp

} // namespace pineda
