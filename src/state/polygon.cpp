// Polygon rasterization state and shading (GL 2.1 §3.5.1, §3.5.4, §2.14.7).
#include "state/api_util.h"
#include "dispatch.h"

namespace pineda {
namespace exec {

void GLAPIENTRY FrontFace(GLenum mode) {
  PINEDA_CTX_OUTSIDE("glFrontFace");
  if (mode != GL_CW && mode != GL_CCW) {
    record_error(ctx, GL_INVALID_ENUM, "glFrontFace", mode);
    return;
  }
  if (ctx->polygon.front_face == mode) return;
  ctx->polygon.front_face = mode;
  mark_dirty(ctx, kDirtyPolygon);
}

void GLAPIENTRY CullFace(GLenum mode) {
  PINEDA_CTX_OUTSIDE("glCullFace");
  if (mode != GL_FRONT && mode != GL_BACK && mode != GL_FRONT_AND_BACK) {
    record_error(ctx, GL_INVALID_ENUM, "glCullFace", mode);
    return;
  }
  if (ctx->polygon.cull_face == mode) return;
  ctx->polygon.cull_face = mode;
  mark_dirty(ctx, kDirtyPolygon);
}

void GLAPIENTRY PolygonMode(GLenum face, GLenum mode) {
  PINEDA_CTX_OUTSIDE("glPolygonMode");
  if (face != GL_FRONT && face != GL_BACK && face != GL_FRONT_AND_BACK) {
    record_error(ctx, GL_INVALID_ENUM, "glPolygonMode", face);
    return;
  }
  if (mode != GL_POINT && mode != GL_LINE && mode != GL_FILL) {
    record_error(ctx, GL_INVALID_ENUM, "glPolygonMode", mode);
    return;
  }
  if (face != GL_BACK) ctx->polygon.mode[0] = mode;
  if (face != GL_FRONT) ctx->polygon.mode[1] = mode;
  mark_dirty(ctx, kDirtyPolygon);
}

void GLAPIENTRY ShadeModel(GLenum mode) {
  PINEDA_CTX_OUTSIDE("glShadeModel");
  if (mode != GL_FLAT && mode != GL_SMOOTH) {
    record_error(ctx, GL_INVALID_ENUM, "glShadeModel", mode);
    return;
  }
  if (ctx->lighting.shade_model == mode) return;
  ctx->lighting.shade_model = mode;
  mark_dirty(ctx, kDirtyPolygon);
}

} // namespace exec
} // namespace pineda
