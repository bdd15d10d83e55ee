// Framebuffer control and clears (GL 2.1 §4.2), pixel storage (§3.6.1) and glReadPixels
// (§4.3.2).
#include <algorithm>
#include <cmath>

#include <GL/glext.h>

#include "state/api_util.h"
#include "dispatch.h"
#include "framebuffer/read_pixels.h"
#include "raster/schedule.h"
#include "pixel/unpack.h"
#include "state/pixel.h"
#include "state/pixel_buffer.h"

namespace pineda {

namespace {

// GL 2.1 §3.6.1 glPixelStore: the parameter and its value check.
void pixel_store(const char* func, GLenum pname, double value) {
  PINEDA_CTX_OUTSIDE(func);
  PixelStore* ps = nullptr;
  GLenum base = pname;
  if (pname >= GL_PACK_SWAP_BYTES && pname <= GL_PACK_ALIGNMENT) {
    ps = &ctx->pixel_store.pack;
    base = pname - GL_PACK_SWAP_BYTES + GL_UNPACK_SWAP_BYTES;
  } else if (pname >= GL_UNPACK_SWAP_BYTES && pname <= GL_UNPACK_ALIGNMENT) {
    ps = &ctx->pixel_store.unpack;
  } else if (pname == GL_PACK_IMAGE_HEIGHT || pname == GL_PACK_SKIP_IMAGES) {
    ps = &ctx->pixel_store.pack;
  } else if (pname == GL_UNPACK_IMAGE_HEIGHT || pname == GL_UNPACK_SKIP_IMAGES) {
    ps = &ctx->pixel_store.unpack;
  } else {
    record_error(ctx, GL_INVALID_ENUM, func, pname);
    return;
  }
  // GL 2.1 §3.6.1: integer parameters from a float value are rounded to the nearest integer.
  // Clamped to the int range first (converting a larger double is undefined); NaN has no
  // nearest integer and is refused like a negative value.
  const double v = std::isnan(value) ? -1.0 : std::clamp(value, -2147483648.0, 2147483647.0);
  const int iv = static_cast<int>(v < 0 ? -std::floor(-v + 0.5) : std::floor(v + 0.5));
  switch (base) {
  case GL_UNPACK_SWAP_BYTES:
    ps->swap_bytes = value != 0.0;
    return;
  case GL_UNPACK_LSB_FIRST:
    ps->lsb_first = value != 0.0;
    return;
  default:
    break;
  }
  if (iv < 0) {
    record_error(ctx, GL_INVALID_VALUE, func);
    return;
  }
  switch (base) {
  case GL_UNPACK_ROW_LENGTH:
    ps->row_length = iv;
    break;
  case GL_UNPACK_SKIP_ROWS:
    ps->skip_rows = iv;
    break;
  case GL_UNPACK_SKIP_PIXELS:
    ps->skip_pixels = iv;
    break;
  case GL_UNPACK_ALIGNMENT:
    if (iv != 1 && iv != 2 && iv != 4 && iv != 8) {
      record_error(ctx, GL_INVALID_VALUE, func);
      return;
    }
    ps->alignment = iv;
    break;
  case GL_PACK_IMAGE_HEIGHT:
  case GL_UNPACK_IMAGE_HEIGHT:
    ps->image_height = iv;
    break;
  case GL_PACK_SKIP_IMAGES:
  case GL_UNPACK_SKIP_IMAGES:
    ps->skip_images = iv;
    break;
  default:
    break;
  }
}

} // namespace

namespace exec {

void GLAPIENTRY Clear(GLbitfield mask) {
  PINEDA_CTX_OUTSIDE("glClear");
  constexpr GLbitfield kAll =
      GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT;
  if ((mask & ~kAll) != 0) {
    record_error(ctx, GL_INVALID_VALUE, "glClear");
    return;
  }
  // ARB_framebuffer_object §4.4.4: an incomplete draw framebuffer is not written.
  if (!draw_framebuffer_ready(ctx, "glClear")) return;
  // GL 2.1 §5.2, §5.3: no framebuffer updates in SELECT and FEEDBACK mode.
  if (!ctx->fb.present() || !render_mode_is_render(ctx)) return;
  if (mask & GL_ACCUM_BUFFER_BIT) accum_clear(ctx); // src/state/accum.cpp
  ClearState cs;
  for (int i = 0; i < 4; ++i) {
    cs.color[i] = ctx->color_buffer.clear_color[i];
    // GL 2.1 §4.2.3: the colour buffers cleared are those enabled for writing (§4.2.1).
    cs.color_write[i] = ctx->color_buffer.color_mask[i];
  }
  cs.depth = ctx->depth.clear;
  cs.depth_write = ctx->depth.mask;
  cs.stencil = ctx->stencil.clear;
  cs.stencil_writemask = ctx->stencil.front.writemask;
  cs.scissor_test = ctx->scissor.test;
  for (int i = 0; i < 4; ++i)
    cs.scissor[i] = ctx->scissor.box[i];
  // GL 2.1 §4.2.3: clearing a buffer that does not exist has no effect.
  GLbitfield m = ctx->fb.color != nullptr ? mask & GL_COLOR_BUFFER_BIT : 0u;
  if (ctx->fb.depth != nullptr) m |= mask & GL_DEPTH_BUFFER_BIT;
  if (ctx->fb.stencil != nullptr) m |= mask & GL_STENCIL_BUFFER_BIT;
  if (m != 0) clear_buffers_shared(&ctx->workers, ctx->fb, cs, m);
  // GL 2.1 §4.2.3: every colour buffer drawing writes is cleared (FRONT_AND_BACK, DrawBuffers).
  if ((m & GL_COLOR_BUFFER_BIT) != 0)
    for (int i = 0; i < ctx->fb.more_count; ++i) {
      Framebuffer other = ctx->fb.with_color(ctx->fb.more[i]);
      clear_buffers_shared(&ctx->workers, other, cs, GL_COLOR_BUFFER_BIT);
    }
}

void GLAPIENTRY ClearColor(GLclampf r, GLclampf g, GLclampf b, GLclampf a) {
  PINEDA_CTX_OUTSIDE("glClearColor");
  ctx->color_buffer.clear_color[0] = clampf01(r);
  ctx->color_buffer.clear_color[1] = clampf01(g);
  ctx->color_buffer.clear_color[2] = clampf01(b);
  ctx->color_buffer.clear_color[3] = clampf01(a);
}

void GLAPIENTRY ClearStencil(GLint s) {
  PINEDA_CTX_OUTSIDE("glClearStencil");
  ctx->stencil.clear = s;
}

void GLAPIENTRY ColorMask(GLboolean r, GLboolean g, GLboolean b, GLboolean a) {
  PINEDA_CTX_OUTSIDE("glColorMask");
  const bool m[4] = {r != GL_FALSE, g != GL_FALSE, b != GL_FALSE, a != GL_FALSE};
  for (int i = 0; i < 4; ++i)
    ctx->color_buffer.color_mask[i] = m[i];
  mark_dirty(ctx, kDirtyFragment);
}

void GLAPIENTRY PixelStorei(GLenum pname, GLint param) {
  pixel_store("glPixelStorei", pname, param);
}
void GLAPIENTRY PixelStoref(GLenum pname, GLfloat param) {
  pixel_store("glPixelStoref", pname, param);
}

void GLAPIENTRY ReadPixels(GLint x, GLint y, GLsizei w, GLsizei h, GLenum format, GLenum type,
                           void* pixels) {
  PINEDA_CTX_OUTSIDE("glReadPixels");
  if (w < 0 || h < 0) return record_error(ctx, GL_INVALID_VALUE, "glReadPixels");
  // Format/type legality (GL 2.1 §3.6.4, §4.3.2): unknown enums are INVALID_ENUM, a packed
  // type with a format of another component count is INVALID_OPERATION.
  const GLenum err = read_format_type_error(format, type);
  if (err != GL_NO_ERROR) return record_error(ctx, err, "glReadPixels", format);
  // GL 2.1 §4.3.2: COLOR_INDEX in RGBA mode, and depth/stencil reads with no such buffer,
  // are INVALID_OPERATION.
  if (format == GL_COLOR_INDEX) return record_error(ctx, GL_INVALID_OPERATION, "glReadPixels");
  // ARB_framebuffer_object §4.4.4: an incomplete read framebuffer is not read.
  if (!read_framebuffer_ready(ctx, "glReadPixels")) return;
  const Framebuffer& fb = ctx->read_fb;
  if (format == GL_DEPTH_COMPONENT && fb.depth == nullptr)
    return record_error(ctx, GL_INVALID_OPERATION, "glReadPixels");
  if (format == GL_STENCIL_INDEX && fb.stencil == nullptr)
    return record_error(ctx, GL_INVALID_OPERATION, "glReadPixels");
  // EXT_packed_depth_stencil: DEPTH_STENCIL needs both buffers.
  if (format == GL_DEPTH_STENCIL && (fb.depth == nullptr || fb.stencil == nullptr))
    return record_error(ctx, GL_INVALID_OPERATION, "glReadPixels");
  const bool color =
      format != GL_DEPTH_COMPONENT && format != GL_STENCIL_INDEX && format != GL_DEPTH_STENCIL;
  // GL 3.0 §4.3.2: reading colour with the read buffer NONE is INVALID_OPERATION.
  if (color && fb.color == nullptr && fb.present())
    return record_error(ctx, GL_INVALID_OPERATION, "glReadPixels");
  // GL 2.1 §4.3.2: into the pixel pack buffer when one is bound.
  const PixelStore& st = ctx->pixel_store.pack;
  if (!pack_memory(ctx, pixels, client_image_bytes(w, h, 1, format, type, store_2d(st)),
                   pixel_type_unit(type), "glReadPixels", &pixels))
    return;
  if (pixels == nullptr || w == 0 || h == 0 || !fb.present()) return;
  if (read_pixels_transfer(ctx, x, y, w, h, format, type, pixels)) return;
  read_pixels(fb, x, y, w, h, format, type, ctx->pixel_store.pack, pixels);
}

} // namespace exec
} // namespace pineda
