// Viewport, depth range and user clip planes (GL 2.1 §2.11.1, §2.12); the viewport area
// (Table 6.8, viewport.h).
#include <algorithm>

#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include "state/api_util.h"
#include "dispatch.h"
#include "state/area.h"

namespace pineda {
namespace {

bool get_viewport(Context& ctx, GLenum pname, QueryValues& out) {
  const ViewportGroup& vp = ctx.viewport;
  switch (pname) {
  case GL_VIEWPORT:
    out.ints({double(vp.x), double(vp.y), double(vp.w), double(vp.h)});
    return true;
  case GL_DEPTH_RANGE:
    out.normalized({vp.near, vp.far});
    return true;
  case GL_MAX_VIEWPORT_DIMS:
    out.ints({kMaxViewportDim, kMaxViewportDim});
    return true;
  default:
    return false;
  }
}

constexpr AttribGroup kViewportGroups[] = {
    member_group<&Context::viewport>(GL_VIEWPORT_BIT, kDirtyViewport),
};

} // namespace

const StateArea kViewportArea = {
    .name = "viewport (GL 2.1 §2.11.1, Table 6.8)",
    .get = get_viewport,
    .groups = kViewportGroups,
};

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
  if (ctx->viewport.x == x && ctx->viewport.y == y && ctx->viewport.w == w && ctx->viewport.h == h)
    return;
  ctx->viewport.x = x, ctx->viewport.y = y, ctx->viewport.w = w, ctx->viewport.h = h;
  mark_dirty(ctx, kDirtyViewport | kDirtyClipPlanes);
}

void GLAPIENTRY DepthRange(GLdouble n, GLdouble f) {
  PINEDA_CTX_OUTSIDE("glDepthRange");
  // GL 2.1 §2.11.1: both values are clamped to [0,1]; n > f is allowed.
  ctx->viewport.near = clampd01(n);
  ctx->viewport.far = clampd01(f);
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
  double* dst = ctx->transform.clip_plane[plane - GL_CLIP_PLANE0];
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
    eq[i] = ctx->transform.clip_plane[plane - GL_CLIP_PLANE0][i];
}

} // namespace exec
} // namespace pineda
