// Hints (GL 2.1 §5.6; Table 6.32 "Hints", the "hint" attribute group). glHint in hints.cpp.
#pragma once

#include <GL/gl.h>

namespace pineda {

struct StateArea;

// HINT_BIT: Table 6.32.
struct HintGroup {
  GLenum perspective = GL_DONT_CARE;
  GLenum point_smooth = GL_DONT_CARE;
  GLenum line_smooth = GL_DONT_CARE;
  GLenum polygon_smooth = GL_DONT_CARE;
  GLenum fog = GL_DONT_CARE; // FASTEST: fog per vertex (validate_texpipe.cpp)
  GLenum generate_mipmap = GL_DONT_CARE;
  GLenum texture_compression = GL_DONT_CARE;
};

extern const StateArea kHintArea; // hints.cpp

} // namespace pineda
