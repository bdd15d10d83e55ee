// Transformation state (GL 2.1 §2.11, §2.12; Table 6.7 "Transformation state", the
// "transform" attribute group) and the matrix stacks, which no attribute group saves. Commands
// in matrix.cpp (MatrixMode, the matrix commands, the stacks) and viewport.cpp (ClipPlane).
#pragma once

#include <GL/gl.h>

#include <cstddef>
#include <vector>

#include <glm/mat4x4.hpp>

#include "core/limits.h"

namespace pineda {

struct StateArea;

// TRANSFORM_BIT: Table 6.7 (the clip plane enables and NORMALIZE, RESCALE_NORMAL are also
// "enable").
struct TransformGroup {
  GLenum matrix_mode = GL_MODELVIEW;
  double clip_plane[kMaxClipPlanes][4] = {}; // eye coordinates (§2.12)
  bool clip_enabled[kMaxClipPlanes] = {};
  bool normalize = false;
  bool rescale_normal = false;
};

// A matrix stack (GL 2.1 §2.11.2). Element 0 is the bottom; back() is the current matrix.
struct MatrixStack {
  std::vector<glm::mat4> stack;
  size_t max_depth = 0;
  explicit MatrixStack(size_t depth) : stack(1, glm::mat4(1.0f)), max_depth(depth) {}
  glm::mat4& top() { return stack.back(); }
  const glm::mat4& top() const { return stack.back(); }
};

extern const StateArea kTransformArea; // matrix.cpp

} // namespace pineda
