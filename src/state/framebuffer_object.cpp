// Framebuffer objects (ARB_framebuffer_object, EXT_framebuffer_object; GL 3.0 §4.4 on GL 2.1):
// names, bindings, attachments, completeness (§4.4.4), GetFramebufferAttachmentParameteriv
// (§6.1.3), and the derivation of Context::fb and Context::read_fb. Renderbuffers are in
// renderbuffer.cpp, glBlitFramebuffer in blit.cpp.
#include "state/framebuffer_object.h"

#include <GL/glext.h>

#include <algorithm>
#include <cmath>

#include "dispatch.h"
#include "state/api_util.h"
#include "state/area.h"
#include "state/texture_internal.h"

namespace pineda {

namespace {

// ---- attachment points and targets ----

// The attachment index of an attachment enum; -1 for DEPTH_STENCIL_ATTACHMENT (both), -2 for
// COLOR_ATTACHMENTm with m >= MAX_COLOR_ATTACHMENTS (INVALID_OPERATION), -3 for anything else
// (INVALID_ENUM).
int attachment_index(GLenum attachment) {
  if (attachment >= GL_COLOR_ATTACHMENT0 && attachment <= GL_COLOR_ATTACHMENT15) {
    const int i = int(attachment - GL_COLOR_ATTACHMENT0);
    return i < kMaxColorAttachments ? i : -2;
  }
  switch (attachment) {
  case GL_DEPTH_ATTACHMENT:
    return kAttachDepth;
  case GL_STENCIL_ATTACHMENT:
    return kAttachStencil;
  case GL_DEPTH_STENCIL_ATTACHMENT:
    return -1;
  default:
    return -3;
  }
}

bool is_framebuffer_target(GLenum target) {
  return target == GL_FRAMEBUFFER || target == GL_DRAW_FRAMEBUFFER || target == GL_READ_FRAMEBUFFER;
}

FramebufferObject* find_framebuffer(Context* ctx, GLuint name) {
  if (name == 0) return nullptr;
  auto it = ctx->fbo.objects.find(name);
  return it == ctx->fbo.objects.end() ? nullptr : it->second.get();
}

// The framebuffer object bound to `target` (FRAMEBUFFER means the draw framebuffer, §4.4.1).
FramebufferObject* bound_object(Context* ctx, GLenum target) {
  return find_framebuffer(ctx, target == GL_READ_FRAMEBUFFER ? ctx->fbo.read_binding
                                                             : ctx->fbo.draw_binding);
}

} // namespace

std::shared_ptr<Renderbuffer> find_renderbuffer(Context* ctx, GLuint name) {
  if (name == 0) return nullptr;
  auto it = ctx->shared->renderbuffers.find(name);
  return it == ctx->shared->renderbuffers.end() ? nullptr : it->second;
}

bool attached_image(const Attachment& a, AttachedImage& out) {
  out = AttachedImage{};
  if (a.type == GL_RENDERBUFFER) {
    const Renderbuffer* rb = a.renderbuffer.get();
    if (rb == nullptr || rb->width <= 0 || rb->height <= 0) return false;
    out.width = rb->width, out.height = rb->height;
    out.internal_format = rb->internal_format;
    out.color = rb->color;
    out.base = rb->base;
    if (!rb->rgba.empty()) {
      out.rgba = const_cast<uint8_t*>(rb->rgba.data());
      out.rgba_stride = ptrdiff_t(rb->width) * 4;
    }
    if (!rb->depth.empty()) {
      out.depth = const_cast<uint32_t*>(rb->depth.data());
      out.depth_bits = rb->depth_size;
      out.depth_stride = rb->width;
    }
    if (!rb->stencil.empty()) {
      out.stencil = const_cast<uint8_t*>(rb->stencil.data());
      out.stencil_stride = rb->width;
    }
    out.red_size = rb->red_size, out.green_size = rb->green_size;
    out.blue_size = rb->blue_size, out.alpha_size = rb->alpha_size;
    out.depth_size = rb->depth_size, out.stencil_size = rb->stencil_size;
    return true;
  }
  if (a.type != GL_TEXTURE || a.texture == nullptr) return false;
  const TextureObject& tex = *a.texture;
  if (a.level < 0 || a.level >= kMaxTexLevels || a.face < 0 || a.face >= 6) return false;
  TexImage& im = const_cast<TexImage&>(tex.images[a.face][a.level]);
  if (im.width <= 0) return false;
  const int dims = texture_dims(tex.target);
  const int b = im.border, bj = dims >= 2 ? b : 0, bk = dims >= 3 ? b : 0;
  const int w = im.width - 2 * b, h = dims >= 2 ? im.height - 2 * bj : 1;
  const int d = dims >= 3 ? im.depth - 2 * bk : 1;
  if (w <= 0 || h <= 0 || a.layer < 0 || a.layer >= d) return false;
  const size_t origin =
      (size_t(a.layer + bk) * size_t(im.height) + size_t(bj)) * size_t(im.width) + size_t(b);
  out.width = w, out.height = h;
  out.internal_format = im.internal_format;
  out.color = !im.is_depth;
  out.base = im.base;
  if (im.is_depth) {
    if (im.z.empty()) return false;
    out.depth = im.z.data() + origin;
    out.depth_bits = im.depth_size;
    out.depth_stride = im.width;
    // A DEPTH_STENCIL texture (EXT_packed_depth_stencil) is depth- and stencil-renderable.
    if (!im.stencil.empty()) {
      out.stencil = im.stencil.data() + origin;
      out.stencil_stride = im.width;
      out.stencil_size = im.stencil_size;
    }
  } else {
    if (im.rgba.empty()) return false;
    out.rgba = im.rgba.data() + origin * 4;
    out.rgba_stride = ptrdiff_t(im.width) * 4;
  }
  const bool lum = im.base == TexBase::Luminance || im.base == TexBase::LuminanceAlpha;
  const int rgb_size = lum                             ? im.luminance_size
                       : im.base == TexBase::Intensity ? im.intensity_size
                                                       : 0;
  out.red_size = reported_bits(im.red_size != 0 ? im.red_size : rgb_size);
  out.green_size = reported_bits(im.green_size);
  out.blue_size = reported_bits(im.blue_size);
  out.alpha_size = reported_bits(im.base == TexBase::Intensity ? im.intensity_size : im.alpha_size);
  out.depth_size = im.depth_size;
  return true;
}

namespace {

// §4.4.4 attachment completeness: an image, of a format renderable at this attachment point.
bool attachment_complete(const Attachment& a, int index) {
  AttachedImage im;
  if (!attached_image(a, im)) return false;
  if (index == kAttachDepth) return im.depth != nullptr;
  if (index == kAttachStencil) return im.stencil != nullptr;
  return im.color && im.rgba != nullptr;
}

// The attachment a draw or read buffer names, or -1 for NONE or a value that names none.
int buffer_attachment(GLenum buf) {
  if (buf >= GL_COLOR_ATTACHMENT0 && buf < GL_COLOR_ATTACHMENT0 + kMaxColorAttachments)
    return int(buf - GL_COLOR_ATTACHMENT0);
  return -1;
}

// §4.4.4 framebuffer completeness of a framebuffer object with these draw and read buffers.
GLenum object_status(const FramebufferObject& fbo, const GLenum* draw_buffers, GLenum read_buffer) {
  bool any = false;
  for (int i = 0; i < kAttachCount; ++i) {
    if (fbo.att[i].type == GL_NONE) continue;
    if (!attachment_complete(fbo.att[i], i)) return GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT;
    any = true;
  }
  if (!any) return GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT;
  for (int i = 0; i < kMaxDrawBuffers; ++i) {
    if (draw_buffers[i] == GL_NONE) continue;
    const int a = buffer_attachment(draw_buffers[i]);
    if (a < 0 || fbo.att[a].type == GL_NONE) return GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER;
  }
  if (read_buffer != GL_NONE) {
    const int a = buffer_attachment(read_buffer);
    if (a < 0 || fbo.att[a].type == GL_NONE) return GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER;
  }
  return GL_FRAMEBUFFER_COMPLETE;
}

// The draw buffers and read buffer that apply to `fbo`: the context's own when it is the
// bound draw (read) framebuffer, else the object's.
const GLenum* object_draw_buffers(const Context* ctx, const FramebufferObject& fbo) {
  return ctx->fbo.draw_binding == fbo.name ? ctx->color_buffer.draw_buffers : fbo.draw_buffers;
}
GLenum object_read_buffer(const Context* ctx, const FramebufferObject& fbo) {
  return ctx->fbo.read_binding == fbo.name ? ctx->pixel.read_buffer : fbo.read_buffer;
}

// ---- the window's colour buffers (GL 2.1 §4.2.1, §4.3.2, table 4.4) ----

constexpr uint32_t kFront = kColorBufferFrontLeft | kColorBufferFrontRight;
constexpr uint32_t kBack = kColorBufferBackLeft | kColorBufferBackRight;

uint32_t window_buffer_set(GLenum buf) {
  switch (buf) {
  case GL_FRONT_LEFT:
    return kColorBufferFrontLeft;
  case GL_FRONT_RIGHT:
    return kColorBufferFrontRight;
  case GL_BACK_LEFT:
    return kColorBufferBackLeft;
  case GL_BACK_RIGHT:
    return kColorBufferBackRight;
  case GL_FRONT:
    return kFront;
  case GL_BACK:
    return kBack;
  case GL_LEFT:
    return kColorBufferFrontLeft | kColorBufferBackLeft;
  case GL_RIGHT:
    return kColorBufferFrontRight | kColorBufferBackRight;
  case GL_FRONT_AND_BACK:
    return kFront | kBack;
  default:
    return 0;
  }
}

// The window's buffers as the draw and read framebuffers: `color` is the back buffer when the
// draw buffers name it (the primary target, so BACK-only drawing costs one pass), `more` the
// front buffer when both are drawn.
void derive_window_draw(Context* ctx, Framebuffer& fb) {
  const Framebuffer& w = ctx->window;
  fb = w;
  fb.more_count = 0;
  uint32_t set = 0;
  bool none = true;
  for (GLenum b : ctx->color_buffer.draw_buffers) {
    set |= window_buffer_set(b);
    none = none && b == GL_NONE;
  }
  set &= ctx->color_buffers;
  if (w.front_color == nullptr || w.back_color == nullptr) {
    // One colour buffer: drawn unless the draw buffers are NONE (a draw buffer kept from a
    // double-buffered drawable the context was current on before still draws into it).
    if (none) fb.color = nullptr;
    return;
  }
  const bool front = (set & kFront) != 0, back = (set & kBack) != 0;
  fb.color = none ? nullptr : back || !front ? w.back_color : w.front_color;
  if (front && back) {
    fb.more[0] = ColorTarget{w.front_color, w.color_stride, w.alpha_bits};
    fb.more_count = 1;
  }
}

void derive_window_read(Context* ctx, Framebuffer& fb) {
  const Framebuffer& w = ctx->window;
  fb = w;
  fb.more_count = 0;
  const uint32_t set = window_buffer_set(ctx->pixel.read_buffer) & ctx->color_buffers;
  if (ctx->pixel.read_buffer == GL_NONE || set == 0) {
    fb.color = ctx->pixel.read_buffer == GL_NONE ? nullptr : fb.color;
    return;
  }
  if (w.front_color != nullptr && w.back_color != nullptr)
    fb.color = (set & kFront) != 0 && (set & kBack) == 0 ? w.front_color : w.back_color;
  // FRONT names the front left buffer even when BACK exists too (§4.3.2).
  if (w.front_color != nullptr &&
      (ctx->pixel.read_buffer == GL_FRONT || ctx->pixel.read_buffer == GL_FRONT_LEFT ||
       ctx->pixel.read_buffer == GL_LEFT))
    fb.color = w.front_color;
}

// A framebuffer object's images as a Framebuffer: the size is the smallest of the attached
// images' (rendering outside some image is undefined, ARB_framebuffer_object §4.4.4).
void derive_object(const FramebufferObject& fbo, const GLenum* draw_buffers, bool draw,
                   GLenum read_buffer, Framebuffer& fb, std::vector<Attachment>* expand) {
  fb = Framebuffer{};
  fb.color_format = ColorFormat::RGBA8;
  int w = 1 << 30, h = 1 << 30;
  bool any = false;
  AttachedImage im;
  for (const Attachment& a : fbo.att)
    if (attached_image(a, im)) {
      w = std::min(w, im.width);
      h = std::min(h, im.height);
      any = true;
    }
  if (!any) return;
  fb.width = w, fb.height = h;
  if (attached_image(fbo.att[kAttachDepth], im) && im.depth != nullptr) {
    fb.depth = im.depth;
    fb.depth_bits = im.depth_bits;
    fb.depth_stride = im.depth_stride;
  }
  if (attached_image(fbo.att[kAttachStencil], im) && im.stencil != nullptr) {
    fb.stencil = im.stencil;
    fb.stencil_bits = 8;
    fb.stencil_stride = im.stencil_stride;
  }
  const auto target_of = [&](int a, ColorTarget& t) {
    if (a < 0 || !attached_image(fbo.att[a], im) || im.rgba == nullptr) return false;
    // Formats without alpha read destination alpha as 1 (GL 2.1 §4.1.8).
    const bool alpha = im.base == TexBase::RGBA || im.base == TexBase::Alpha ||
                       im.base == TexBase::LuminanceAlpha || im.base == TexBase::Intensity;
    t = ColorTarget{im.rgba, im.rgba_stride, alpha ? 8 : 0};
    if (expand != nullptr && im.base != TexBase::RGBA) expand->push_back(fbo.att[a]);
    return true;
  };
  ColorTarget t;
  if (!draw) {
    if (target_of(buffer_attachment(read_buffer), t)) {
      fb.color = t.data, fb.color_stride = t.stride, fb.alpha_bits = t.alpha_bits;
    }
    return;
  }
  bool primary = false;
  for (int i = 0; i < kMaxDrawBuffers; ++i) {
    if (draw_buffers[i] == GL_NONE || !target_of(buffer_attachment(draw_buffers[i]), t)) continue;
    t.output = i;
    if (!primary) {
      fb.color = t.data, fb.color_stride = t.stride, fb.alpha_bits = t.alpha_bits;
      fb.color_output = i;
      primary = true;
    } else if (fb.more_count < kMaxDrawBuffers - 1) {
      fb.more[fb.more_count++] = t;
    }
  }
}

// Table 3.23's expansion of one texel of base format `base` written as RGBA.
void expand_texel(TexBase base, uint8_t* t) {
  switch (base) {
  case TexBase::Alpha:
    t[0] = t[1] = t[2] = 0;
    break;
  case TexBase::Luminance:
    t[1] = t[2] = t[0];
    t[3] = 255;
    break;
  case TexBase::LuminanceAlpha:
    t[1] = t[2] = t[0];
    break;
  case TexBase::Intensity:
    t[1] = t[2] = t[3] = t[0];
    break;
  case TexBase::RGB:
    t[3] = 255;
    break;
  case TexBase::RGBA:
    break;
  }
}

} // namespace

FramebufferObject* draw_framebuffer_object(Context* ctx) {
  return find_framebuffer(ctx, ctx->fbo.draw_binding);
}
FramebufferObject* read_framebuffer_object(Context* ctx) {
  return find_framebuffer(ctx, ctx->fbo.read_binding);
}

void framebuffers_changed(Context* ctx) {
  ctx->fbo.stale = true;
  mark_dirty(ctx, kDirtyFramebuffer);
  // Commands read Context::fb and read_fb directly: they are remade at once.
  sync_framebuffers(ctx);
}

void sync_framebuffers(Context* ctx) {
  FramebufferState& st = ctx->fbo;
  const uint64_t gen = ctx->shared->texture_generation;
  if (!st.stale && st.generation == gen) return;
  // Objects bound nowhere else may have changed their images: whatever was drawn with the old
  // description is expanded first (the attachments hold their objects alive).
  normalize_drawn_images(ctx);
  st.stale = false;
  st.generation = gen;
  st.expand_after_drawing.clear();
  const FramebufferObject* draw = draw_framebuffer_object(ctx);
  const FramebufferObject* read = read_framebuffer_object(ctx);
  if (draw == nullptr) {
    derive_window_draw(ctx, ctx->fb);
    st.draw_status = ctx->window.present() ? GL_FRAMEBUFFER_COMPLETE : GL_FRAMEBUFFER_UNDEFINED;
  } else {
    derive_object(*draw, ctx->color_buffer.draw_buffers, true, GL_NONE, ctx->fb,
                  &st.expand_after_drawing);
    st.draw_status =
        object_status(*draw, ctx->color_buffer.draw_buffers, object_read_buffer(ctx, *draw));
  }
  if (read == nullptr) {
    derive_window_read(ctx, ctx->read_fb);
    st.read_status = ctx->window.present() ? GL_FRAMEBUFFER_COMPLETE : GL_FRAMEBUFFER_UNDEFINED;
  } else {
    derive_object(*read, nullptr, false, ctx->pixel.read_buffer, ctx->read_fb, nullptr);
    st.read_status = object_status(*read, object_draw_buffers(ctx, *read), ctx->pixel.read_buffer);
  }
  mark_dirty(ctx, kDirtyFramebuffer);
}

bool draw_framebuffer_ready(Context* ctx, const char* func) {
  sync_framebuffers(ctx);
  if (ctx->fbo.draw_binding == 0) return true;
  if (ctx->fbo.draw_status != GL_FRAMEBUFFER_COMPLETE) {
    record_error(ctx, GL_INVALID_FRAMEBUFFER_OPERATION, func);
    return false;
  }
  ctx->fbo.drawn = true;
  return true;
}

bool read_framebuffer_ready(Context* ctx, const char* func) {
  sync_framebuffers(ctx);
  if (ctx->fbo.read_binding == 0) return true;
  if (ctx->fbo.read_status != GL_FRAMEBUFFER_COMPLETE) {
    record_error(ctx, GL_INVALID_FRAMEBUFFER_OPERATION, func);
    return false;
  }
  // What drawing wrote into the images read is read in its base format.
  normalize_drawn_images(ctx);
  return true;
}

void normalize_drawn_images(Context* ctx) {
  FramebufferState& st = ctx->fbo;
  if (!st.drawn) return;
  st.drawn = false;
  for (const Attachment& a : st.expand_after_drawing) {
    AttachedImage im;
    if (!attached_image(a, im) || im.rgba == nullptr) continue;
    for (int y = 0; y < im.height; ++y) {
      uint8_t* row = im.rgba + ptrdiff_t(y) * im.rgba_stride;
      for (int x = 0; x < im.width; ++x)
        expand_texel(im.base, row + 4 * x);
    }
  }
}

void detach_deleted_texture(Context* ctx, const TextureObject* tex) {
  bool changed = false;
  for (FramebufferObject* f : {draw_framebuffer_object(ctx), read_framebuffer_object(ctx)}) {
    if (f == nullptr) continue;
    for (Attachment& a : f->att)
      if (a.type == GL_TEXTURE && a.texture.get() == tex) {
        normalize_drawn_images(ctx);
        a = Attachment{};
        changed = true;
      }
  }
  if (changed) framebuffers_changed(ctx);
}

namespace {

// ---- queries (Table 6.X "Framebuffer", implementation limits) ----

bool get_framebuffer_objects(Context& ctx, GLenum pname, QueryValues& out) {
  switch (pname) {
  case GL_DRAW_FRAMEBUFFER_BINDING: // also FRAMEBUFFER_BINDING
    out.ints({double(ctx.fbo.draw_binding)});
    return true;
  case GL_READ_FRAMEBUFFER_BINDING:
    out.ints({double(ctx.fbo.read_binding)});
    return true;
  case GL_RENDERBUFFER_BINDING:
    out.ints({double(ctx.fbo.renderbuffer_binding)});
    return true;
  case GL_MAX_RENDERBUFFER_SIZE:
    out.ints({double(kMaxRenderbufferSize)});
    return true;
  case GL_MAX_COLOR_ATTACHMENTS:
    out.ints({double(kMaxColorAttachments)});
    return true;
  case GL_MAX_SAMPLES:
    out.ints({0});
    return true;
  default:
    return false;
  }
}

// After glPopAttrib restored the draw buffers (COLOR_BUFFER_BIT) or the read buffer
// (PIXEL_MODE_BIT): they apply to the bound framebuffers.
uint32_t buffers_restored(Context& ctx, GLbitfield mask) {
  if ((mask & (GL_COLOR_BUFFER_BIT | GL_PIXEL_MODE_BIT)) != 0) framebuffers_changed(&ctx);
  return 0;
}

uint32_t objects_stale(const Context& ctx) {
  return ctx.fbo.draw_binding != 0 || ctx.fbo.read_binding != 0 ? kDirtyFramebuffer : 0u;
}

void derive_framebuffers(Context& ctx, uint32_t) {
  sync_framebuffers(&ctx);
}

// ---- binding ----

// Moves the per-framebuffer draw and read buffers between the context's groups and the
// objects (or the window's store) when the bindings change (FramebufferObject::draw_buffers).
void rebind(Context* ctx, GLuint draw, GLuint read) {
  FramebufferState& st = ctx->fbo;
  if (draw != st.draw_binding) {
    normalize_drawn_images(ctx);
    FramebufferObject* old = find_framebuffer(ctx, st.draw_binding);
    GLenum* keep = old != nullptr ? old->draw_buffers : st.window_draw_buffers;
    std::copy_n(ctx->color_buffer.draw_buffers, kMaxDrawBuffers, keep);
    FramebufferObject* now = find_framebuffer(ctx, draw);
    const GLenum* load = now != nullptr ? now->draw_buffers : st.window_draw_buffers;
    std::copy_n(load, kMaxDrawBuffers, ctx->color_buffer.draw_buffers);
    st.draw_binding = draw;
    mark_dirty(ctx, kDirtyFragment);
  }
  if (read != st.read_binding) {
    FramebufferObject* old = find_framebuffer(ctx, st.read_binding);
    (old != nullptr ? old->read_buffer : st.window_read_buffer) = ctx->pixel.read_buffer;
    FramebufferObject* now = find_framebuffer(ctx, read);
    ctx->pixel.read_buffer = now != nullptr ? now->read_buffer : st.window_read_buffer;
    st.read_binding = read;
  }
  framebuffers_changed(ctx);
}

void bind_framebuffer(GLenum target, GLuint framebuffer, const char* func) {
  PINEDA_CTX_OUTSIDE(func);
  if (!is_framebuffer_target(target)) return record_error(ctx, GL_INVALID_ENUM, func, target);
  // Names need not come from GenFramebuffers (ARB_framebuffer_object on a compatibility
  // context, EXT_framebuffer_object): binding an unused name creates the object.
  if (framebuffer != 0) {
    auto& slot = ctx->fbo.objects[framebuffer];
    if (!slot) {
      slot = std::make_unique<FramebufferObject>();
      slot->name = framebuffer;
    }
    slot->bound_once = true;
  }
  const GLuint draw = target == GL_READ_FRAMEBUFFER ? ctx->fbo.draw_binding : framebuffer;
  const GLuint read = target == GL_DRAW_FRAMEBUFFER ? ctx->fbo.read_binding : framebuffer;
  if (draw == ctx->fbo.draw_binding && read == ctx->fbo.read_binding) return;
  rebind(ctx, draw, read);
}

// ---- attachments ----

// The framebuffer object of an attachment command, or null with the error recorded.
FramebufferObject* attach_target(Context* ctx, GLenum target, GLenum attachment, int* index,
                                 const char* func) {
  if (!is_framebuffer_target(target)) {
    record_error(ctx, GL_INVALID_ENUM, func, target);
    return nullptr;
  }
  *index = attachment_index(attachment);
  if (*index == -3) {
    record_error(ctx, GL_INVALID_ENUM, func, attachment);
    return nullptr;
  }
  if (*index == -2) {
    record_error(ctx, GL_INVALID_OPERATION, func);
    return nullptr;
  }
  FramebufferObject* fbo = bound_object(ctx, target);
  // §4.4.2.2: attaching to the default framebuffer is INVALID_OPERATION.
  if (fbo == nullptr) record_error(ctx, GL_INVALID_OPERATION, func);
  return fbo;
}

void set_attachment(Context* ctx, FramebufferObject* fbo, int index, const Attachment& a) {
  normalize_drawn_images(ctx);
  if (index == -1) {
    fbo->att[kAttachDepth] = a;
    fbo->att[kAttachStencil] = a;
  } else {
    fbo->att[index] = a;
  }
  framebuffers_changed(ctx);
}

// FramebufferTexture1D/2D/3D and FramebufferTextureLayer (§4.4.2.3). `dims` is the
// dimensionality the command takes (0 for FramebufferTextureLayer: a 3D texture).
void framebuffer_texture(GLenum target, GLenum attachment, GLenum textarget, GLuint texture,
                         GLint level, GLint layer, int dims, const char* func) {
  PINEDA_CTX_OUTSIDE(func);
  int index = 0;
  FramebufferObject* fbo = attach_target(ctx, target, attachment, &index, func);
  if (fbo == nullptr) return;
  if (texture == 0) return set_attachment(ctx, fbo, index, Attachment{});
  auto it = ctx->shared->textures.find(texture);
  if (it == ctx->shared->textures.end() || it->second->target == 0)
    return record_error(ctx, GL_INVALID_OPERATION, func);
  const std::shared_ptr<TextureObject>& tex = it->second;
  int face = 0;
  if (dims == 0) {
    // FramebufferTextureLayer: a 3D texture (no array textures on GL 2.1).
    if (tex->target != GL_TEXTURE_3D) return record_error(ctx, GL_INVALID_OPERATION, func);
    textarget = GL_TEXTURE_3D;
  } else {
    const bool face_target =
        textarget >= GL_TEXTURE_CUBE_MAP_POSITIVE_X && textarget <= GL_TEXTURE_CUBE_MAP_NEGATIVE_Z;
    const bool ok = dims == 1   ? textarget == GL_TEXTURE_1D
                    : dims == 2 ? textarget == GL_TEXTURE_2D || face_target
                                : textarget == GL_TEXTURE_3D;
    if (!ok) return record_error(ctx, GL_INVALID_ENUM, func, textarget);
    const GLenum object_target = face_target ? GL_TEXTURE_CUBE_MAP : textarget;
    if (tex->target != object_target) return record_error(ctx, GL_INVALID_OPERATION, func);
    if (face_target) face = int(textarget - GL_TEXTURE_CUBE_MAP_POSITIVE_X);
  }
  const int max_levels = tex->target == GL_TEXTURE_3D ? kMax3DTexLevels : kMaxTexLevels;
  if (level < 0 || level >= max_levels) return record_error(ctx, GL_INVALID_VALUE, func);
  if (tex->target == GL_TEXTURE_3D && (layer < 0 || layer >= kMax3DTextureSize))
    return record_error(ctx, GL_INVALID_VALUE, func);
  Attachment a;
  a.type = GL_TEXTURE;
  a.name = texture;
  a.texture = tex;
  a.level = level;
  a.face = face;
  a.layer = tex->target == GL_TEXTURE_3D ? layer : 0;
  a.textarget = textarget;
  set_attachment(ctx, fbo, index, a);
}

// ---- GetFramebufferAttachmentParameteriv (§6.1.3) ----

bool attachment_param(Context* ctx, const Attachment& a, GLenum pname, GLint* v, const char* func) {
  if (pname == GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE) {
    *v = GLint(a.type);
    return true;
  }
  if (pname == GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME) {
    *v = GLint(a.name);
    return true;
  }
  // With no object attached, other pnames are INVALID_ENUM (ARB_framebuffer_object §6.1.3).
  if (a.type == GL_NONE) {
    record_error(ctx, GL_INVALID_ENUM, func, pname);
    return false;
  }
  switch (pname) {
  case GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL:
  case GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE:
  case GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER:
    if (a.type != GL_TEXTURE) break;
    *v = pname == GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL ? a.level
         : pname == GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER
             ? a.layer
             : (a.textarget >= GL_TEXTURE_CUBE_MAP_POSITIVE_X &&
                        a.textarget <= GL_TEXTURE_CUBE_MAP_NEGATIVE_Z
                    ? GLint(a.textarget)
                    : 0);
    return true;
  case GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING:
    *v = GL_LINEAR;
    return true;
  case GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE: {
    AttachedImage im;
    const bool has = attached_image(a, im);
    *v = has && im.stencil != nullptr && im.depth == nullptr ? GL_INDEX : GL_UNSIGNED_NORMALIZED;
    return true;
  }
  case GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE:
  case GL_FRAMEBUFFER_ATTACHMENT_GREEN_SIZE:
  case GL_FRAMEBUFFER_ATTACHMENT_BLUE_SIZE:
  case GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE:
  case GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE:
  case GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE: {
    AttachedImage im;
    if (!attached_image(a, im)) {
      *v = 0;
      return true;
    }
    *v = pname == GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE     ? im.red_size
         : pname == GL_FRAMEBUFFER_ATTACHMENT_GREEN_SIZE ? im.green_size
         : pname == GL_FRAMEBUFFER_ATTACHMENT_BLUE_SIZE  ? im.blue_size
         : pname == GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE ? im.alpha_size
         : pname == GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE ? im.depth_size
                                                         : (im.stencil != nullptr ? 8 : 0);
    return true;
  }
  default:
    break;
  }
  record_error(ctx, GL_INVALID_ENUM, func, pname);
  return false;
}

} // namespace

const StateArea kFramebufferObjectArea = {
    .name = "framebuffer objects (ARB_framebuffer_object §4.4)",
    .get = get_framebuffer_objects,
    .restored = buffers_restored,
    .derive_on = kDirtyFramebuffer,
    .derive = derive_framebuffers,
    .stale = objects_stale,
};

namespace exec {

// ---- framebuffer objects (§4.4.1) ----

void GLAPIENTRY GenFramebuffers(GLsizei n, GLuint* framebuffers) {
  PINEDA_CTX_OUTSIDE("glGenFramebuffers");
  if (n < 0) return record_error(ctx, GL_INVALID_VALUE, "glGenFramebuffers");
  if (framebuffers == nullptr) return;
  GLuint next = 1;
  for (GLsizei i = 0; i < n; ++i) {
    while (ctx->fbo.objects.count(next) != 0)
      ++next;
    // A generated name is reserved; it becomes an object when first bound.
    auto obj = std::make_unique<FramebufferObject>();
    obj->name = next;
    ctx->fbo.objects.emplace(next, std::move(obj));
    framebuffers[i] = next++;
  }
}

void GLAPIENTRY DeleteFramebuffers(GLsizei n, const GLuint* framebuffers) {
  PINEDA_CTX_OUTSIDE("glDeleteFramebuffers");
  if (n < 0) return record_error(ctx, GL_INVALID_VALUE, "glDeleteFramebuffers");
  if (framebuffers == nullptr) return;
  for (GLsizei i = 0; i < n; ++i) {
    const GLuint name = framebuffers[i];
    if (name == 0 || ctx->fbo.objects.count(name) == 0) continue;
    // §4.4.1: a deleted bound framebuffer reverts its bindings to the window's (0).
    const GLuint draw = ctx->fbo.draw_binding == name ? 0 : ctx->fbo.draw_binding;
    const GLuint read = ctx->fbo.read_binding == name ? 0 : ctx->fbo.read_binding;
    if (draw != ctx->fbo.draw_binding || read != ctx->fbo.read_binding) rebind(ctx, draw, read);
    ctx->fbo.objects.erase(name);
  }
}

GLboolean GLAPIENTRY IsFramebuffer(GLuint framebuffer) {
  Context* ctx = outside_begin_end("glIsFramebuffer");
  if (ctx == nullptr) return GL_FALSE;
  const FramebufferObject* f = find_framebuffer(ctx, framebuffer);
  return f != nullptr && f->bound_once ? GL_TRUE : GL_FALSE;
}

void GLAPIENTRY BindFramebuffer(GLenum target, GLuint framebuffer) {
  bind_framebuffer(target, framebuffer, "glBindFramebuffer");
}

// EXT_framebuffer_object's BindFramebufferEXT: the same (gl.xml gives it no alias because the
// EXT version has no DRAW/READ targets without EXT_framebuffer_blit, which Pineda has).
void GLAPIENTRY BindFramebufferEXT(GLenum target, GLuint framebuffer) {
  bind_framebuffer(target, framebuffer, "glBindFramebufferEXT");
}

GLenum GLAPIENTRY CheckFramebufferStatus(GLenum target) {
  Context* ctx = outside_begin_end("glCheckFramebufferStatus");
  if (ctx == nullptr) return 0;
  if (!is_framebuffer_target(target)) {
    record_error(ctx, GL_INVALID_ENUM, "glCheckFramebufferStatus", target);
    return 0;
  }
  const FramebufferObject* fbo = bound_object(ctx, target);
  if (fbo == nullptr)
    return ctx->window.present() ? GL_FRAMEBUFFER_COMPLETE : GL_FRAMEBUFFER_UNDEFINED;
  return object_status(*fbo, object_draw_buffers(ctx, *fbo), object_read_buffer(ctx, *fbo));
}

void GLAPIENTRY FramebufferTexture1D(GLenum target, GLenum attachment, GLenum textarget,
                                     GLuint texture, GLint level) {
  framebuffer_texture(target, attachment, textarget, texture, level, 0, 1,
                      "glFramebufferTexture1D");
}

void GLAPIENTRY FramebufferTexture2D(GLenum target, GLenum attachment, GLenum textarget,
                                     GLuint texture, GLint level) {
  framebuffer_texture(target, attachment, textarget, texture, level, 0, 2,
                      "glFramebufferTexture2D");
}

void GLAPIENTRY FramebufferTexture3D(GLenum target, GLenum attachment, GLenum textarget,
                                     GLuint texture, GLint level, GLint zoffset) {
  framebuffer_texture(target, attachment, textarget, texture, level, zoffset, 3,
                      "glFramebufferTexture3D");
}

void GLAPIENTRY FramebufferTextureLayer(GLenum target, GLenum attachment, GLuint texture,
                                        GLint level, GLint layer) {
  framebuffer_texture(target, attachment, GL_NONE, texture, level, layer, 0,
                      "glFramebufferTextureLayer");
}

void GLAPIENTRY FramebufferRenderbuffer(GLenum target, GLenum attachment, GLenum renderbuffertarget,
                                        GLuint renderbuffer) {
  const char* func = "glFramebufferRenderbuffer";
  PINEDA_CTX_OUTSIDE(func);
  int index = 0;
  FramebufferObject* fbo = attach_target(ctx, target, attachment, &index, func);
  if (fbo == nullptr) return;
  if (renderbuffertarget != GL_RENDERBUFFER)
    return record_error(ctx, GL_INVALID_ENUM, func, renderbuffertarget);
  if (renderbuffer == 0) return set_attachment(ctx, fbo, index, Attachment{});
  std::shared_ptr<Renderbuffer> rb = find_renderbuffer(ctx, renderbuffer);
  if (rb == nullptr || !rb->bound_once) return record_error(ctx, GL_INVALID_OPERATION, func);
  Attachment a;
  a.type = GL_RENDERBUFFER;
  a.name = renderbuffer;
  a.renderbuffer = std::move(rb);
  set_attachment(ctx, fbo, index, a);
}

void GLAPIENTRY GetFramebufferAttachmentParameteriv(GLenum target, GLenum attachment, GLenum pname,
                                                    GLint* params) {
  const char* func = "glGetFramebufferAttachmentParameteriv";
  PINEDA_CTX_OUTSIDE(func);
  int index = 0;
  FramebufferObject* fbo = attach_target(ctx, target, attachment, &index, func);
  if (fbo == nullptr) return;
  if (index == -1) {
    // DEPTH_STENCIL_ATTACHMENT: the depth and stencil attachments must be the same image.
    const Attachment& d = fbo->att[kAttachDepth];
    const Attachment& s = fbo->att[kAttachStencil];
    if (d.type != s.type || d.texture != s.texture || d.renderbuffer != s.renderbuffer ||
        d.level != s.level || d.face != s.face || d.layer != s.layer)
      return record_error(ctx, GL_INVALID_OPERATION, func);
    index = kAttachDepth;
  }
  GLint v = 0;
  if (attachment_param(ctx, fbo->att[index], pname, &v, func) && params != nullptr) *params = v;
}

} // namespace exec
} // namespace pineda
