// Renderbuffer objects (ARB_framebuffer_object §4.4.2.1): names, binding, storage in every
// colour, depth, stencil and depth-stencil format Pineda stores, OUT_OF_MEMORY, deletion
// (detached from the bound framebuffers), GetRenderbufferParameteriv (§6.1.3).
#include <GL/glext.h>

#include <algorithm>
#include <new>

#include "dispatch.h"
#include "state/api_util.h"
#include "state/framebuffer_object.h"
#include "state/tex_format.h"

namespace pineda {

namespace {

// Records that renderbuffer storage changed: the framebuffers made from it are remade.
void storage_changed(Context* ctx) {
  ++ctx->shared->texture_generation;
  mark_dirty(ctx, kDirtyTexture);
  framebuffers_changed(ctx);
}

// ---- formats (§4.4.2.1 Table 4.X, §4.4.4 colour-, depth- and stencil-renderable) ----

struct RenderFormat {
  bool color = false;
  TexBase base = TexBase::RGBA;
  uint8_t r = 0, g = 0, b = 0, a = 0, l = 0, i = 0;
  uint8_t depth = 0, stencil = 0;
};

// The renderbuffer formats: the colour formats of Table 3.16 that are colour-renderable (the
// compatibility formats ALPHA, LUMINANCE, LUMINANCE_ALPHA and INTENSITY too; not the generic
// compressed or the numeric 1-4 ones), the depth formats, the stencil index formats and
// DEPTH_STENCIL.
bool renderbuffer_format(GLenum internalformat, RenderFormat& out) {
  switch (internalformat) {
  case GL_DEPTH_COMPONENT:
  case GL_DEPTH_COMPONENT24:
    out.depth = 24;
    return true;
  case GL_DEPTH_COMPONENT16:
    out.depth = 16;
    return true;
  case GL_DEPTH_COMPONENT32:
    out.depth = 32;
    return true;
  case GL_STENCIL_INDEX:
  case GL_STENCIL_INDEX1:
  case GL_STENCIL_INDEX4:
  case GL_STENCIL_INDEX8:
  case GL_STENCIL_INDEX16:
    out.stencil = 8;
    return true;
  case GL_DEPTH_STENCIL:
  case GL_DEPTH24_STENCIL8:
    out.depth = 24;
    out.stencil = 8;
    return true;
  case 1:
  case 2:
  case 3:
  case 4:
  case GL_COMPRESSED_ALPHA:
  case GL_COMPRESSED_LUMINANCE:
  case GL_COMPRESSED_LUMINANCE_ALPHA:
  case GL_COMPRESSED_INTENSITY:
  case GL_COMPRESSED_RGB:
  case GL_COMPRESSED_RGBA:
    return false;
  default:
    break;
  }
  TexFormatInfo f;
  if (!lookup_internal_format(GLint(internalformat), f) || f.depth) return false;
  out.color = true;
  out.base = f.base;
  out.r = f.r, out.g = f.g, out.b = f.b, out.a = f.a, out.l = f.l, out.i = f.i;
  return true;
}

void bind_renderbuffer(GLenum target, GLuint renderbuffer, const char* func) {
  PINEDA_CTX_OUTSIDE(func);
  if (target != GL_RENDERBUFFER) return record_error(ctx, GL_INVALID_ENUM, func, target);
  if (renderbuffer != 0) {
    auto& slot = ctx->shared->renderbuffers[renderbuffer];
    if (!slot) {
      slot = std::make_shared<Renderbuffer>();
      slot->name = renderbuffer;
    }
    slot->bound_once = true;
  }
  ctx->fbo.renderbuffer_binding = renderbuffer;
}

// ---- renderbuffer storage (§4.4.2.1) ----

void renderbuffer_storage(GLenum target, GLsizei samples, GLenum internalformat, GLsizei width,
                          GLsizei height, const char* func) {
  PINEDA_CTX_OUTSIDE(func);
  if (target != GL_RENDERBUFFER) return record_error(ctx, GL_INVALID_ENUM, func, target);
  RenderFormat f;
  if (!renderbuffer_format(internalformat, f))
    return record_error(ctx, GL_INVALID_ENUM, func, internalformat);
  if (width < 0 || height < 0 || width > kMaxRenderbufferSize || height > kMaxRenderbufferSize)
    return record_error(ctx, GL_INVALID_VALUE, func);
  // MAX_SAMPLES is 0: no multisampled renderbuffers.
  if (samples < 0 || samples > 0) return record_error(ctx, GL_INVALID_VALUE, func);
  std::shared_ptr<Renderbuffer> rb = find_renderbuffer(ctx, ctx->fbo.renderbuffer_binding);
  if (rb == nullptr) return record_error(ctx, GL_INVALID_OPERATION, func);
  const uint64_t pixels = uint64_t(width) * uint64_t(height);
  const uint64_t bytes = pixels * ((f.color ? 4 : 0) + (f.depth ? 4 : 0) + (f.stencil ? 1 : 0));
  if (bytes > kMaxRenderbufferBytes) return record_error(ctx, GL_OUT_OF_MEMORY, func);
  // The new storage is made completely before the object changes: OUT_OF_MEMORY changes
  // nothing (GL 2.1 §2.5). Its contents are undefined (§4.4.2.1); Pineda's are zero.
  Renderbuffer next;
  try {
    if (f.color) next.rgba.assign(pixels * 4, 0);
    if (f.depth) next.depth.assign(pixels, 0);
    if (f.stencil) next.stencil.assign(pixels, 0);
  } catch (const std::bad_alloc&) {
    return record_error(ctx, GL_OUT_OF_MEMORY, func);
  }
  normalize_drawn_images(ctx);
  rb->internal_format = internalformat;
  rb->width = width;
  rb->height = height;
  rb->color = f.color;
  rb->base = f.base;
  const bool lum = f.base == TexBase::Luminance || f.base == TexBase::LuminanceAlpha;
  rb->red_size = reported_bits(f.color ? (lum                            ? f.l
                                          : f.base == TexBase::Intensity ? f.i
                                                                         : f.r)
                                       : 0);
  rb->green_size = reported_bits(f.g);
  rb->blue_size = reported_bits(f.b);
  rb->alpha_size = reported_bits(f.base == TexBase::Intensity ? f.i : f.a);
  rb->depth_size = f.depth;
  rb->stencil_size = f.stencil;
  rb->rgba = std::move(next.rgba);
  rb->depth = std::move(next.depth);
  rb->stencil = std::move(next.stencil);
  storage_changed(ctx);
}

} // namespace

namespace exec {

// ---- renderbuffer objects (§4.4.2.1) ----

void GLAPIENTRY GenRenderbuffers(GLsizei n, GLuint* renderbuffers) {
  PINEDA_CTX_OUTSIDE("glGenRenderbuffers");
  if (n < 0) return record_error(ctx, GL_INVALID_VALUE, "glGenRenderbuffers");
  if (renderbuffers == nullptr) return;
  auto& objs = ctx->shared->renderbuffers;
  GLuint next = 1;
  for (GLsizei i = 0; i < n; ++i) {
    while (objs.count(next) != 0)
      ++next;
    auto obj = std::make_shared<Renderbuffer>();
    obj->name = next;
    objs.emplace(next, std::move(obj));
    renderbuffers[i] = next++;
  }
}

void GLAPIENTRY DeleteRenderbuffers(GLsizei n, const GLuint* renderbuffers) {
  PINEDA_CTX_OUTSIDE("glDeleteRenderbuffers");
  if (n < 0) return record_error(ctx, GL_INVALID_VALUE, "glDeleteRenderbuffers");
  if (renderbuffers == nullptr) return;
  for (GLsizei i = 0; i < n; ++i) {
    const GLuint name = renderbuffers[i];
    std::shared_ptr<Renderbuffer> rb = find_renderbuffer(ctx, name);
    if (rb == nullptr) continue;
    // §4.4.2.1: a deleted bound renderbuffer is unbound, and detached from the bound draw and
    // read framebuffers; other framebuffers keep it until they detach it.
    if (ctx->fbo.renderbuffer_binding == name) ctx->fbo.renderbuffer_binding = 0;
    bool changed = false;
    for (FramebufferObject* f : {draw_framebuffer_object(ctx), read_framebuffer_object(ctx)}) {
      if (f == nullptr) continue;
      for (Attachment& a : f->att)
        if (a.type == GL_RENDERBUFFER && a.renderbuffer == rb) {
          normalize_drawn_images(ctx);
          a = Attachment{};
          changed = true;
        }
    }
    ctx->shared->renderbuffers.erase(name);
    if (changed) framebuffers_changed(ctx);
  }
}

GLboolean GLAPIENTRY IsRenderbuffer(GLuint renderbuffer) {
  Context* ctx = outside_begin_end("glIsRenderbuffer");
  if (ctx == nullptr) return GL_FALSE;
  const std::shared_ptr<Renderbuffer> rb = find_renderbuffer(ctx, renderbuffer);
  return rb != nullptr && rb->bound_once ? GL_TRUE : GL_FALSE;
}

void GLAPIENTRY BindRenderbuffer(GLenum target, GLuint renderbuffer) {
  bind_renderbuffer(target, renderbuffer, "glBindRenderbuffer");
}

void GLAPIENTRY BindRenderbufferEXT(GLenum target, GLuint renderbuffer) {
  bind_renderbuffer(target, renderbuffer, "glBindRenderbufferEXT");
}

void GLAPIENTRY RenderbufferStorage(GLenum target, GLenum internalformat, GLsizei width,
                                    GLsizei height) {
  renderbuffer_storage(target, 0, internalformat, width, height, "glRenderbufferStorage");
}

void GLAPIENTRY RenderbufferStorageMultisample(GLenum target, GLsizei samples,
                                               GLenum internalformat, GLsizei width,
                                               GLsizei height) {
  renderbuffer_storage(target, samples, internalformat, width, height,
                       "glRenderbufferStorageMultisample");
}

void GLAPIENTRY GetRenderbufferParameteriv(GLenum target, GLenum pname, GLint* params) {
  const char* func = "glGetRenderbufferParameteriv";
  PINEDA_CTX_OUTSIDE(func);
  if (target != GL_RENDERBUFFER) return record_error(ctx, GL_INVALID_ENUM, func, target);
  std::shared_ptr<Renderbuffer> rb = find_renderbuffer(ctx, ctx->fbo.renderbuffer_binding);
  if (rb == nullptr) return record_error(ctx, GL_INVALID_OPERATION, func);
  GLint v = 0;
  switch (pname) {
  case GL_RENDERBUFFER_WIDTH:
    v = rb->width;
    break;
  case GL_RENDERBUFFER_HEIGHT:
    v = rb->height;
    break;
  case GL_RENDERBUFFER_INTERNAL_FORMAT:
    v = GLint(rb->internal_format);
    break;
  case GL_RENDERBUFFER_RED_SIZE:
    v = rb->red_size;
    break;
  case GL_RENDERBUFFER_GREEN_SIZE:
    v = rb->green_size;
    break;
  case GL_RENDERBUFFER_BLUE_SIZE:
    v = rb->blue_size;
    break;
  case GL_RENDERBUFFER_ALPHA_SIZE:
    v = rb->alpha_size;
    break;
  case GL_RENDERBUFFER_DEPTH_SIZE:
    v = rb->depth_size;
    break;
  case GL_RENDERBUFFER_STENCIL_SIZE:
    v = rb->stencil_size;
    break;
  case GL_RENDERBUFFER_SAMPLES:
    v = 0;
    break;
  default:
    return record_error(ctx, GL_INVALID_ENUM, func, pname);
  }
  if (params != nullptr) *params = v;
}

} // namespace exec
} // namespace pineda
