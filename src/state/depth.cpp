// Depth buffer test and control (GL 2.1 §4.1.6, §4.2.2).
#include "state/api_util.h"
#include "dispatch.h"

namespace pineda {
namespace exec {

void GLAPIENTRY DepthFunc(GLenum func) {
  PINEDA_CTX_OUTSIDE("glDepthFunc");
  if (func < GL_NEVER || func > GL_ALWAYS) {
    record_error(ctx, GL_INVALID_ENUM, "glDepthFunc", func);
    return;
  }
  if (ctx->depth.func == func) return;
  ctx->depth.func = func;
  mark_dirty(ctx, kDirtyFragment);
}

void GLAPIENTRY DepthMask(GLboolean flag) {
  PINEDA_CTX_OUTSIDE("glDepthMask");
  const bool value = flag != GL_FALSE;
  if (ctx->depth.mask == value) return;
  ctx->depth.mask = value;
  mark_dirty(ctx, kDirtyFragment);
}

void GLAPIENTRY ClearDepth(GLdouble depth) {
  PINEDA_CTX_OUTSIDE("glClearDepth");
  ctx->depth.clear = clampd01(depth);
}

} // namespace exec
} // namespace pineda
