// Fog and the colour sum (GL 2.1 §3.9, §3.10; Table 6.11 "Coloring" fog rows, the "fog"
// attribute group). Commands in fog.cpp; the current fog coordinate is a current value
// (current.h).
#pragma once

#include <GL/gl.h>

namespace pineda {

struct StateArea;

// FOG_BIT: Table 6.11 (FOG and COLOR_SUM are also "enable").
struct FogGroup {
  bool enabled = false; // FOG
  GLenum mode = GL_EXP;
  float color[4] = {0, 0, 0, 0};
  float density = 1.0f, start = 0.0f, end = 1.0f;
  float index = 0.0f;
  GLenum coord_src = GL_FRAGMENT_DEPTH; // FOG_COORD_SRC
  bool color_sum = false;               // COLOR_SUM (§3.9)
};

extern const StateArea kFogArea; // fog.cpp

} // namespace pineda
