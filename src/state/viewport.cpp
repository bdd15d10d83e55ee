// Viewport, depth range and user clip planes (GL 2.1 §2.11.1, §2.12).
#include <algorithm>

#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include "core/api_util.h"
#include "dispatch.h"

namespace pineda {
namespace exec {

void GLAPIENTRY Viewport(GLint x, GLint y, GLsizei w, GLsizei h) {
  PINEDA_CTX_OUTSIDE("glViewport");
  if (w < 0 || h < 0) {
    record_error(ctx, GL_INVALID_VALUE, "glViewport");
    return;
  }
  // GL 2.1 §2.11.1: width and height are silently clamped to MAX_VIEWPORT_DIMS.
  w = std::min<GLsizei>(w, kMaxViewportDim);
  h = std::min<GLsizei>(h, kMaxViewportDim);
  if (ctx->vp_x == x && ctx->vp_y == y && ctx->vp_w == w && ctx->vp_h == h) return;
  ctx->vp_x = x, ctx->vp_y = y, ctx->vp_w = w, ctx->vp_h = h;
  mark_dirty(ctx, kDirtyViewport | kDirtyClipPlanes);
}

void GLAPIENTRY DepthRange(GLdouble n, GLdouble f) {
  PINEDA_CTX_OUTSIDE("glDepthRange");
  // GL 2.1 §2.11.1: both values are clamped to [0,1]; n > f is allowed.
  ctx->depth_near = clampd01(n);
  ctx->depth_far = clampd01(f);
  mark_dirty(ctx, kDirtyViewport);
}

// GL 2.1 §2.12: the plane is given in object coordinates and stored in eye coordinates,
// transformed by the inverse of the modelview matrix current at this call.
void GLAPIENTRY ClipPlane(GLenum plane, const GLdouble* eq) {
  PINEDA_CTX_OUTSIDE("glClipPlane");
  if (plane < GL_CLIP_PLANE0 || plane >= GL_CLIP_PLANE0 + kMaxClipPlanes) {
    record_error(ctx, GL_INVALID_ENUM, "glClipPlane", plane);
    return;
  }
  if (eq == nullptr) return;
  const glm::dmat4 inv = glm::inverse(glm::dmat4(ctx->modelview.top()));
  const glm::dvec4 p(eq[0], eq[1], eq[2], eq[3]);
  const glm::dvec4 e = p * inv; // row vector times matrix
  double* dst = ctx->clip_plane[plane - GL_CLIP_PLANE0];
  for (int i = 0; i < 4; ++i)
    dst[i] = e[i];
  mark_dirty(ctx, kDirtyClipPlanes);
}

void GLAPIENTRY GetClipPlane(GLenum plane, GLdouble* eq) {
  PINEDA_CTX_OUTSIDE("glGetClipPlane");
  if (plane < GL_CLIP_PLANE0 || plane >= GL_CLIP_PLANE0 + kMaxClipPlanes) {
    record_error(ctx, GL_INVALID_ENUM, "glGetClipPlane", plane);
    return;
  }
  if (eq == nullptr) return;
  for (int i = 0; i < 4; ++i)
    eq[i] = ctx->clip_plane[plane - GL_CLIP_PLANE0][i];
}

} // namespace exec
} // namespace pineda
