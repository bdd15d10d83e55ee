// Texture images from the framebuffer (GL 2.1 §3.8.2 "Alternate Texture Image Specification
// Commands"): glCopyTexImage1D/2D and glCopyTexSubImage1D/2D/3D read the current read buffer
// (colour) or the depth buffer (depth textures) the way glCopyPixels does.
#include <algorithm>
#include <new>
#include <stdexcept>
#include <vector>

#include "state/api_util.h"
#include "dispatch.h"
#include "framebuffer/read_pixels.h"
#include "pixel/transfer.h"
#include "state/tex_format.h"
#include "state/texture_internal.h"

namespace pineda {

namespace {

// Reads the w x h rectangle at window (x, y) as RGBA floats or depth floats and applies the
// pixel transfer operations (§3.8.2: as CopyPixels, up to the final expansion to RGBA).
// Pixels outside the framebuffer are undefined in GL (§4.3.2); they read as zero here.
void read_framebuffer(const Context* ctx, int x, int y, int w, int h, bool depth, float* out) {
  const size_t n = size_t(w) * size_t(h);
  std::fill(out, out + n * (depth ? 1 : 4), 0.0f);
  if (!ctx->read_fb.present() || w == 0 || h == 0) return;
  PixelStore pack; // tightly packed floats
  read_pixels(ctx->read_fb, x, y, w, h, depth ? GL_DEPTH_COMPONENT : GL_RGBA, GL_FLOAT, pack, out);
  if (depth)
    transfer_depth(pixel_transfer_view(ctx), out, n);
  else
    transfer_rgba(pixel_transfer_view(ctx), out, n);
}

// The source buffer must exist: a depth texture needs a depth buffer (§3.8.2, §4.3.2), a
// depth-stencil one a stencil buffer too (EXT_packed_depth_stencil).
bool source_missing(const Context* ctx, bool depth, bool stencil = false) {
  if (stencil && ctx->read_fb.stencil == nullptr) return true;
  return depth ? ctx->read_fb.depth == nullptr : ctx->read_fb.color == nullptr;
}

// The stencil indices of the w x h rectangle at (x, y), through the stencil transfer
// operations, into a DEPTH_STENCIL image (EXT_packed_depth_stencil).
void copy_stencil(const Context* ctx, TexImage& im, int dims, int xoffset, int yoffset, int zoffset,
                  int x, int y, int w, int h) {
  if (im.stencil.empty() || ctx->read_fb.stencil == nullptr) return;
  std::vector<uint32_t> s(size_t(w) * size_t(h), 0u);
  PixelStore pack;
  read_pixels(ctx->read_fb, x, y, w, h, GL_STENCIL_INDEX, GL_UNSIGNED_INT, pack, s.data());
  transfer_stencil(pixel_transfer_view(ctx), s.data(), s.size());
  store_stencil_region(im, dims, xoffset, yoffset, zoffset, w, h, s.data());
}

void copy_tex_image(const char* func, int dims, GLenum target, GLint level, GLenum internalformat,
                    GLint x, GLint y, GLsizei width, GLsizei height, GLint border) {
  PINEDA_CTX_OUTSIDE(func);
  ImageTarget it;
  if (!image_target(ctx, target, dims, false, it))
    return record_error(ctx, GL_INVALID_ENUM, func, target);
  if (level < 0 || level >= it.max_levels) return record_error(ctx, GL_INVALID_VALUE, func);
  TexFormatInfo info;
  // §3.8.2: internalformat as for TexImage, except that 1, 2, 3 and 4 are not allowed; an
  // invalid one is INVALID_ENUM here (not INVALID_VALUE as for TexImage). The 1D command takes
  // its arguments "as TexImage1D" but the same rule, as in Mesa.
  if (internalformat <= 4 || !lookup_internal_format(GLint(internalformat), info))
    return record_error(ctx, GL_INVALID_ENUM, func);
  if (border != 0 && border != 1) return record_error(ctx, GL_INVALID_VALUE, func);
  if (dims < 2) height = 1;
  const int bb = 2 * border;
  if (width < bb || (dims >= 2 && height < bb)) return record_error(ctx, GL_INVALID_VALUE, func);
  if (it.cube && width != height) return record_error(ctx, GL_INVALID_VALUE, func);
  const int limit = it.max_size >> level;
  if (width - bb > limit || (dims >= 2 && height - bb > limit))
    return record_error(ctx, GL_INVALID_VALUE, func);
  if (info.depth && it.cube) return record_error(ctx, GL_INVALID_OPERATION, func);
  // ARB_framebuffer_object §4.4.4: an incomplete read framebuffer is not read.
  if (!read_framebuffer_ready(ctx, func)) return;
  if (source_missing(ctx, info.depth, info.s != 0))
    return record_error(ctx, GL_INVALID_OPERATION, func);
  TexImage im;
  set_image_info(im, internalformat, info, width, height, 1, border);
  const size_t count = size_t(width) * size_t(height);
  try {
    if (info.depth) {
      im.z.assign(count, 0u);
      if (info.s != 0) im.stencil.assign(count, 0);
    } else
      im.rgba.assign(count * 4, 0);
    std::vector<float> tmp(count * (info.depth ? 1 : 4));
    read_framebuffer(ctx, x, y, width, height, info.depth, tmp.data());
    store_region(im, dims, -border, dims >= 2 ? -border : 0, 0, width, height, 1, tmp.data());
    copy_stencil(ctx, im, dims, -border, dims >= 2 ? -border : 0, 0, x, y, width, height);
  } catch (const std::bad_alloc&) {
    return record_error(ctx, GL_OUT_OF_MEMORY, func);
  } catch (const std::length_error&) {
    return record_error(ctx, GL_OUT_OF_MEMORY, func);
  }
  it.tex->images[it.face][level] = std::move(im);
  image_changed(ctx, *it.tex, it.face, level, dims, func);
}

void copy_tex_sub_image(const char* func, int dims, GLenum target, GLint level, GLint xoffset,
                        GLint yoffset, GLint zoffset, GLint x, GLint y, GLsizei width,
                        GLsizei height) {
  PINEDA_CTX_OUTSIDE(func);
  ImageTarget it;
  if (!image_target(ctx, target, dims, false, it))
    return record_error(ctx, GL_INVALID_ENUM, func, target);
  if (dims < 2) height = 1;
  // The copied rectangle is one row (1D) or one slice (3D) of the image.
  TexImage* im =
      sub_image_target(ctx, func, it, level, xoffset, yoffset, zoffset, width, height, 1);
  if (im == nullptr) return;
  if (!read_framebuffer_ready(ctx, func)) return;
  if (source_missing(ctx, im->is_depth, !im->stencil.empty()))
    return record_error(ctx, GL_INVALID_OPERATION, func);
  const size_t count = size_t(width) * size_t(height);
  if (count == 0) return;
  try {
    std::vector<float> tmp(count * (im->is_depth ? 1 : 4));
    read_framebuffer(ctx, x, y, width, height, im->is_depth, tmp.data());
    store_region(*im, dims, xoffset, yoffset, zoffset, width, height, 1, tmp.data());
    copy_stencil(ctx, *im, dims, xoffset, yoffset, zoffset, x, y, width, height);
  } catch (const std::bad_alloc&) {
    return record_error(ctx, GL_OUT_OF_MEMORY, func);
  }
  image_changed(ctx, *it.tex, it.face, level, dims, func);
}

} // namespace

namespace exec {

void GLAPIENTRY CopyTexImage1D(GLenum target, GLint level, GLenum internalformat, GLint x, GLint y,
                               GLsizei width, GLint border) {
  copy_tex_image("glCopyTexImage1D", 1, target, level, internalformat, x, y, width, 1, border);
}

void GLAPIENTRY CopyTexImage2D(GLenum target, GLint level, GLenum internalformat, GLint x, GLint y,
                               GLsizei width, GLsizei height, GLint border) {
  copy_tex_image("glCopyTexImage2D", 2, target, level, internalformat, x, y, width, height, border);
}

void GLAPIENTRY CopyTexSubImage1D(GLenum target, GLint level, GLint xoffset, GLint x, GLint y,
                                  GLsizei width) {
  copy_tex_sub_image("glCopyTexSubImage1D", 1, target, level, xoffset, 0, 0, x, y, width, 1);
}

void GLAPIENTRY CopyTexSubImage2D(GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint x,
                                  GLint y, GLsizei width, GLsizei height) {
  copy_tex_sub_image("glCopyTexSubImage2D", 2, target, level, xoffset, yoffset, 0, x, y, width,
                     height);
}

void GLAPIENTRY CopyTexSubImage3D(GLenum target, GLint level, GLint xoffset, GLint yoffset,
                                  GLint zoffset, GLint x, GLint y, GLsizei width, GLsizei height) {
  copy_tex_sub_image("glCopyTexSubImage3D", 3, target, level, xoffset, yoffset, zoffset, x, y,
                     width, height);
}

} // namespace exec

} // namespace pineda
