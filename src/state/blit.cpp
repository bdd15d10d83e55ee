// glBlitFramebuffer (EXT_framebuffer_blit, ARB_framebuffer_object §4.3.3): the checks and
// the copy from the read framebuffer into the draw framebuffer (framebuffer/blit.h).
#include <GL/glext.h>

#include "dispatch.h"
#include "framebuffer/blit.h"
#include "state/api_util.h"
#include "state/framebuffer_object.h"

namespace pineda {
namespace exec {

void GLAPIENTRY BlitFramebuffer(GLint srcX0, GLint srcY0, GLint srcX1, GLint srcY1, GLint dstX0,
                                GLint dstY0, GLint dstX1, GLint dstY1, GLbitfield mask,
                                GLenum filter) {
  const char* func = "glBlitFramebuffer";
  PINEDA_CTX_OUTSIDE(func);
  constexpr GLbitfield kAll = GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT;
  if ((mask & ~kAll) != 0) return record_error(ctx, GL_INVALID_VALUE, func);
  if (filter != GL_NEAREST && filter != GL_LINEAR)
    return record_error(ctx, GL_INVALID_ENUM, func, filter);
  // Depth and stencil values are not filtered.
  if (filter == GL_LINEAR && (mask & (GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT)) != 0)
    return record_error(ctx, GL_INVALID_OPERATION, func);
  sync_framebuffers(ctx);
  if (ctx->fbo.draw_binding != 0 && ctx->fbo.draw_status != GL_FRAMEBUFFER_COMPLETE)
    return record_error(ctx, GL_INVALID_FRAMEBUFFER_OPERATION, func);
  if (ctx->fbo.read_binding != 0 && ctx->fbo.read_status != GL_FRAMEBUFFER_COMPLETE)
    return record_error(ctx, GL_INVALID_FRAMEBUFFER_OPERATION, func);
  const Framebuffer& src = ctx->read_fb;
  const Framebuffer& dst = ctx->fb;
  // A buffer missing from either framebuffer is silently left out; depth and stencil
  // buffers present in both must have the same format.
  BlitRequest r;
  r.color = (mask & GL_COLOR_BUFFER_BIT) != 0 && src.color != nullptr && dst.color != nullptr;
  r.depth = (mask & GL_DEPTH_BUFFER_BIT) != 0 && src.depth != nullptr && dst.depth != nullptr;
  r.stencil =
      (mask & GL_STENCIL_BUFFER_BIT) != 0 && src.stencil != nullptr && dst.stencil != nullptr;
  if ((r.depth && src.depth_bits != dst.depth_bits) ||
      (r.stencil && src.stencil_bits != dst.stencil_bits))
    return record_error(ctx, GL_INVALID_OPERATION, func);
  if (!src.present() || !dst.present() || !(r.color || r.depth || r.stencil)) return;
  r.src[0] = srcX0, r.src[1] = srcY0, r.src[2] = srcX1, r.src[3] = srcY1;
  r.dst[0] = dstX0, r.dst[1] = dstY0, r.dst[2] = dstX1, r.dst[3] = dstY1;
  r.linear = filter == GL_LINEAR;
  r.scissor_test = ctx->scissor.test;
  for (int i = 0; i < 4; ++i)
    r.scissor[i] = ctx->scissor.box[i];
  // What drawing wrote into the images read is read in its base format; the draw
  // framebuffer is written.
  normalize_drawn_images(ctx);
  if (ctx->fbo.draw_binding != 0) ctx->fbo.drawn = true;
  blit_framebuffer(src, dst, r);
}

} // namespace exec
} // namespace pineda
