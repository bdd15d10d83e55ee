// EGL surfaces (EGL 1.5 §3.5, §3.9, §3.10): window, pixmap and pbuffer surfaces, their
// attributes, buffer swaps, swap intervals and eglCopyBuffers. Windows and pixmaps present
// through the X11 path GLX uses (src/winsys/x11).
#include <algorithm>
#include <cstring>
#include <new>

#include "winsys/common/swap_pacing.h"
#include "winsys/egl/egl_internal.h"

namespace pineda::egl {

namespace {

constexpr EGLint kMaxSwapInterval = 64;

// (Re)allocates the colour, depth and stencil buffers for a new size.
bool allocate(EglSurface& s, int width, int height) {
  const size_t pixels = static_cast<size_t>(width) * static_cast<size_t>(height);
  try {
    if (s.type == EGL_PBUFFER_BIT) {
      s.memory.assign(std::max<size_t>(pixels, 1) * 4, 0);
      s.width = width;
      s.height = height;
    } else if (!x11::allocate_images(s, width, height, s.display->shm)) {
      return false;
    }
    s.depth.assign(s.config->depth > 0 ? pixels : 0, 0);
    s.stencil.assign(s.config->stencil > 0 ? pixels : 0, 0);
  } catch (const std::bad_alloc&) {
    return false;
  }
  return true;
}

// The attributes every surface type takes (§3.5.1-§3.5.4): colour space and the OpenVG ones,
// which only have their default values here (sRGB rendering and OpenVG are not offered).
// Returns EGL_SUCCESS, or the error an unacceptable one gives.
EGLint common_attribute(EGLAttrib attribute, EGLAttrib value) {
  switch (attribute) {
  case EGL_GL_COLORSPACE:
    if (value == EGL_GL_COLORSPACE_LINEAR) return EGL_SUCCESS;
    return value == EGL_GL_COLORSPACE_SRGB ? EGL_BAD_MATCH : EGL_BAD_ATTRIBUTE;
  case EGL_VG_ALPHA_FORMAT:
    if (value == EGL_VG_ALPHA_FORMAT_NONPRE) return EGL_SUCCESS;
    return value == EGL_VG_ALPHA_FORMAT_PRE ? EGL_BAD_MATCH : EGL_BAD_ATTRIBUTE;
  case EGL_VG_COLORSPACE:
    if (value == EGL_VG_COLORSPACE_sRGB) return EGL_SUCCESS;
    return value == EGL_VG_COLORSPACE_LINEAR ? EGL_BAD_MATCH : EGL_BAD_ATTRIBUTE;
  default:
    return EGL_BAD_ATTRIBUTE;
  }
}

EGLSurface register_surface(EglDisplay* d, std::unique_ptr<EglSurface> s) {
  EglSurface* raw = s.release();
  d->surfaces.insert(raw);
  succeed();
  return static_cast<EGLSurface>(raw);
}

// §3.5.1 / §3.5.4: a window or pixmap surface on X drawable `x`.
EGLSurface native_surface(EGLDisplay dpy, EGLConfig config, Drawable x, bool window,
                          const EGLAttrib* attribs, const char* fn) {
  std::lock_guard<std::mutex> lock(egl_mutex());
  EglDisplay* d = initialized_display(dpy, fn);
  if (d == nullptr) return EGL_NO_SURFACE;
  const EglConfig* c = find_config(d, config);
  if (c == nullptr) return fail(EGL_BAD_CONFIG, fn, EGL_NO_SURFACE);
  const EGLint bad_native = window ? EGL_BAD_NATIVE_WINDOW : EGL_BAD_NATIVE_PIXMAP;
  // The surfaceless platform has no native windows or pixmaps.
  if (d->platform != Platform::X11) return fail(bad_native, fn, EGL_NO_SURFACE);
  EGLint render_buffer = window ? EGL_BACK_BUFFER : EGL_SINGLE_BUFFER;
  for (int i = 0; attribs != nullptr && attribs[i] != EGL_NONE; i += 2) {
    if (window && attribs[i] == EGL_RENDER_BUFFER) {
      if (attribs[i + 1] != EGL_BACK_BUFFER && attribs[i + 1] != EGL_SINGLE_BUFFER)
        return fail(EGL_BAD_ATTRIBUTE, fn, EGL_NO_SURFACE);
      render_buffer = static_cast<EGLint>(attribs[i + 1]);
      continue;
    }
    const EGLint e = common_attribute(attribs[i], attribs[i + 1]);
    if (e != EGL_SUCCESS) return fail(e, fn, EGL_NO_SURFACE);
  }
  if ((c->surface_type & (window ? EGL_WINDOW_BIT : EGL_PIXMAP_BIT)) == 0)
    return fail(EGL_BAD_MATCH, fn, EGL_NO_SURFACE);
  int w = 0, h = 0, depth = 0, screen = -1;
  if (x == 0 || !x11::geometry(d->dpy, x, &w, &h, &depth, &screen))
    return fail(bad_native, fn, EGL_NO_SURFACE);
  if (window) {
    XWindowAttributes wa{};
    const int err = x11::trap_errors(d->dpy, [&] { XGetWindowAttributes(d->dpy, x, &wa); });
    if (err != 0 || wa.visual == nullptr) return fail(bad_native, fn, EGL_NO_SURFACE);
    // The window's visual must be the config's (EGL_NATIVE_VISUAL_ID).
    if (XVisualIDFromVisual(wa.visual) != c->x.visual_id || screen != d->screen)
      return fail(EGL_BAD_MATCH, fn, EGL_NO_SURFACE);
    // §3.5.1: one EGL window surface per native window.
    for (EglSurface* other : d->surfaces)
      if (other->type == EGL_WINDOW_BIT && other->x_drawable == x)
        return fail(EGL_BAD_ALLOC, fn, EGL_NO_SURFACE);
  } else if (depth != c->x.depth || screen != d->screen) {
    return fail(EGL_BAD_MATCH, fn, EGL_NO_SURFACE);
  }
  auto s = std::make_unique<EglSurface>();
  s->display = d;
  s->dpy = d->dpy;
  s->type = window ? EGL_WINDOW_BIT : EGL_PIXMAP_BIT;
  s->config = c;
  s->x_drawable = x;
  s->format = c->x;
  s->is_window = window;
  s->render_buffer = render_buffer;
  s->double_buffered = window && render_buffer == EGL_BACK_BUFFER;
  if (!allocate(*s, w, h)) return fail(EGL_BAD_ALLOC, fn, EGL_NO_SURFACE);
  return register_surface(d, std::move(s));
}

std::vector<EGLAttrib> widen(const EGLint* list) {
  std::vector<EGLAttrib> out;
  for (int i = 0; list != nullptr && list[i] != EGL_NONE; i += 2) {
    out.push_back(list[i]);
    out.push_back(list[i + 1]);
  }
  out.push_back(EGL_NONE);
  return out;
}

// The native handle a platform surface function receives: a pointer to the X Window or
// Pixmap (EGL_KHR_platform_x11). A null pointer names no drawable.
Drawable native_handle(void* native) {
  return native != nullptr ? *static_cast<const Drawable*>(native) : 0;
}

void free_surface(EglSurface* s) {
  x11::release_images(*s);
  delete s;
}

} // namespace

EglSurface* find_surface(EglDisplay* d, EGLSurface handle) {
  auto* s = static_cast<EglSurface*>(handle);
  // A surface destroyed while current stays in the display's set until it is released, but
  // its handle is no longer valid (§3.5.5).
  return d->surfaces.count(s) != 0 && !s->destroy_pending ? s : nullptr;
}

void destroy_surface(EglDisplay* d, EglSurface* s) {
  if (s->bound.empty()) {
    d->surfaces.erase(s);
    free_surface(s);
  } else {
    s->destroy_pending = true;
  }
}

void release_surface(EglContext* ctx, EglSurface* s) {
  if (s == nullptr) return;
  auto& bound = s->bound;
  bound.erase(std::remove(bound.begin(), bound.end(), ctx), bound.end());
  if (s->destroy_pending && bound.empty()) {
    s->display->surfaces.erase(s);
    free_surface(s);
  }
}

bool has_back_buffer(const EglSurface& s) {
  // A pbuffer's only colour buffer is a back buffer (GL 2.1 table 4.4); a window has one
  // unless it renders to EGL_SINGLE_BUFFER.
  return s.type == EGL_PBUFFER_BIT || (s.type == EGL_WINDOW_BIT && s.double_buffered);
}

bool refresh_size(EglSurface& s) {
  if (s.type == EGL_PBUFFER_BIT) return true;
  if (s.dpy == nullptr) return false;
  int w = 0, h = 0;
  if (!x11::geometry(s.dpy, s.x_drawable, &w, &h, nullptr, nullptr)) return false;
  if (w == s.width && h == s.height && s.image != nullptr) return true;
  if (!allocate(s, w, h)) return false;
  for (EglContext* ctx : s.bound)
    attach(ctx, s);
  return true;
}

void attach(EglContext* ctx, EglSurface& s) {
  winsys::SurfaceBuffers b;
  b.width = s.width;
  b.height = s.height;
  b.format = s.config->format;
  b.alpha_bits = s.config->alpha;
  if (s.type == EGL_PBUFFER_BIT) {
    b.color = s.memory.data();
    b.stride = static_cast<ptrdiff_t>(s.width) * 4;
  } else {
    x11::describe_color(s, &b.color, &b.stride, &b.front);
  }
  b.back = has_back_buffer(s);
  b.depth_bits = s.config->depth;
  b.depth = s.depth.empty() ? nullptr : s.depth.data();
  b.stencil_bits = s.config->stencil;
  b.stencil = s.stencil.empty() ? nullptr : s.stencil.data();
  winsys::bind_buffers(ctx, b);
  // The lock is held: the front_selected hook did not run, so the front buffer is fetched here.
  if (b.front != nullptr && s.front_stale && winsys::uses_front(ctx)) x11::pull_front(s);
}

void flush_front(EglContext* ctx) {
  EglSurface* s = ctx->draw;
  if (s == nullptr || s->type == EGL_PBUFFER_BIT) return;
  if (!has_back_buffer(*s))
    x11::present(*s);
  else if (winsys::draws_front(ctx))
    x11::present_front(*s);
}

} // namespace pineda::egl

using namespace pineda::egl;

EGL_EXPORT EGLSurface EGLAPIENTRY eglCreateWindowSurface(EGLDisplay dpy, EGLConfig config,
                                                         EGLNativeWindowType win,
                                                         const EGLint* attrib_list) {
  const std::vector<EGLAttrib> attribs = widen(attrib_list);
  return native_surface(dpy, config, static_cast<Drawable>(win), true, attribs.data(),
                        "eglCreateWindowSurface");
}

EGL_EXPORT EGLSurface EGLAPIENTRY eglCreatePlatformWindowSurface(EGLDisplay dpy, EGLConfig config,
                                                                 void* native_window,
                                                                 const EGLAttrib* attrib_list) {
  return native_surface(dpy, config, native_handle(native_window), true, attrib_list,
                        "eglCreatePlatformWindowSurface");
}

EGL_EXPORT EGLSurface EGLAPIENTRY eglCreatePlatformWindowSurfaceEXT(EGLDisplay dpy,
                                                                    EGLConfig config,
                                                                    void* native_window,
                                                                    const EGLint* attrib_list) {
  const std::vector<EGLAttrib> attribs = widen(attrib_list);
  return native_surface(dpy, config, native_handle(native_window), true, attribs.data(),
                        "eglCreatePlatformWindowSurfaceEXT");
}

EGL_EXPORT EGLSurface EGLAPIENTRY eglCreatePixmapSurface(EGLDisplay dpy, EGLConfig config,
                                                         EGLNativePixmapType pixmap,
                                                         const EGLint* attrib_list) {
  const std::vector<EGLAttrib> attribs = widen(attrib_list);
  return native_surface(dpy, config, static_cast<Drawable>(pixmap), false, attribs.data(),
                        "eglCreatePixmapSurface");
}

EGL_EXPORT EGLSurface EGLAPIENTRY eglCreatePlatformPixmapSurface(EGLDisplay dpy, EGLConfig config,
                                                                 void* native_pixmap,
                                                                 const EGLAttrib* attrib_list) {
  return native_surface(dpy, config, native_handle(native_pixmap), false, attrib_list,
                        "eglCreatePlatformPixmapSurface");
}

EGL_EXPORT EGLSurface EGLAPIENTRY eglCreatePlatformPixmapSurfaceEXT(EGLDisplay dpy,
                                                                    EGLConfig config,
                                                                    void* native_pixmap,
                                                                    const EGLint* attrib_list) {
  const std::vector<EGLAttrib> attribs = widen(attrib_list);
  return native_surface(dpy, config, native_handle(native_pixmap), false, attribs.data(),
                        "eglCreatePlatformPixmapSurfaceEXT");
}

EGL_EXPORT EGLSurface EGLAPIENTRY eglCreatePbufferSurface(EGLDisplay dpy, EGLConfig config,
                                                          const EGLint* attrib_list) {
  const char* fn = "eglCreatePbufferSurface";
  std::lock_guard<std::mutex> lock(egl_mutex());
  EglDisplay* d = initialized_display(dpy, fn);
  if (d == nullptr) return EGL_NO_SURFACE;
  const EglConfig* c = find_config(d, config);
  if (c == nullptr) return fail(EGL_BAD_CONFIG, fn, EGL_NO_SURFACE);
  EGLint w = 0, h = 0, largest = EGL_FALSE, tex_format = EGL_NO_TEXTURE;
  EGLint tex_target = EGL_NO_TEXTURE, mipmap = EGL_FALSE;
  for (int i = 0; attrib_list != nullptr && attrib_list[i] != EGL_NONE; i += 2) {
    const EGLint v = attrib_list[i + 1];
    switch (attrib_list[i]) {
    case EGL_WIDTH:
      w = v;
      break;
    case EGL_HEIGHT:
      h = v;
      break;
    case EGL_LARGEST_PBUFFER:
      largest = v != EGL_FALSE ? EGL_TRUE : EGL_FALSE;
      break;
    case EGL_TEXTURE_FORMAT:
      if (v != EGL_NO_TEXTURE && v != EGL_TEXTURE_RGB && v != EGL_TEXTURE_RGBA)
        return fail(EGL_BAD_ATTRIBUTE, fn, EGL_NO_SURFACE);
      tex_format = v;
      break;
    case EGL_TEXTURE_TARGET:
      if (v != EGL_NO_TEXTURE && v != EGL_TEXTURE_2D)
        return fail(EGL_BAD_ATTRIBUTE, fn, EGL_NO_SURFACE);
      tex_target = v;
      break;
    case EGL_MIPMAP_TEXTURE:
      mipmap = v != EGL_FALSE ? EGL_TRUE : EGL_FALSE;
      break;
    default: {
      const EGLint e = common_attribute(attrib_list[i], v);
      if (e != EGL_SUCCESS) return fail(e, fn, EGL_NO_SURFACE);
    }
    }
  }
  if ((c->surface_type & EGL_PBUFFER_BIT) == 0) return fail(EGL_BAD_MATCH, fn, EGL_NO_SURFACE);
  // §3.5.2: a texture format without a target (or the reverse) is a mismatch, and so is a
  // texture format the config cannot bind (none can: EGL_BIND_TO_TEXTURE_RGB(A) is false).
  if ((tex_format == EGL_NO_TEXTURE) != (tex_target == EGL_NO_TEXTURE) ||
      tex_format != EGL_NO_TEXTURE)
    return fail(EGL_BAD_MATCH, fn, EGL_NO_SURFACE);
  if (w < 0 || h < 0) return fail(EGL_BAD_PARAMETER, fn, EGL_NO_SURFACE);
  EGLint max_w = 0, max_h = 0;
  config_attrib(*c, EGL_MAX_PBUFFER_WIDTH, &max_w);
  config_attrib(*c, EGL_MAX_PBUFFER_HEIGHT, &max_h);
  if (largest == EGL_TRUE) {
    w = std::min(w, max_w);
    h = std::min(h, max_h);
  } else if (w > max_w || h > max_h) {
    return fail(EGL_BAD_ALLOC, fn, EGL_NO_SURFACE);
  }
  auto s = std::make_unique<EglSurface>();
  s->display = d;
  s->dpy = d->dpy;
  s->type = EGL_PBUFFER_BIT;
  s->config = c;
  s->is_window = false;
  s->largest = largest;
  s->mipmap_texture = mipmap;
  if (!allocate(*s, w, h)) return fail(EGL_BAD_ALLOC, fn, EGL_NO_SURFACE);
  return register_surface(d, std::move(s));
}

EGL_EXPORT EGLSurface EGLAPIENTRY eglCreatePbufferFromClientBuffer(EGLDisplay dpy, EGLenum buftype,
                                                                   EGLClientBuffer /*buffer*/,
                                                                   EGLConfig config,
                                                                   const EGLint* /*attribs*/) {
  const char* fn = "eglCreatePbufferFromClientBuffer";
  std::lock_guard<std::mutex> lock(egl_mutex());
  EglDisplay* d = initialized_display(dpy, fn);
  if (d == nullptr) return EGL_NO_SURFACE;
  // §3.5.3: the only client buffer type is EGL_OPENVG_IMAGE, and there is no OpenVG here.
  if (buftype != EGL_OPENVG_IMAGE) return fail(EGL_BAD_PARAMETER, fn, EGL_NO_SURFACE);
  if (find_config(d, config) == nullptr) return fail(EGL_BAD_CONFIG, fn, EGL_NO_SURFACE);
  return fail(EGL_BAD_ACCESS, fn, EGL_NO_SURFACE);
}

EGL_EXPORT EGLBoolean EGLAPIENTRY eglDestroySurface(EGLDisplay dpy, EGLSurface surface) {
  std::lock_guard<std::mutex> lock(egl_mutex());
  EglDisplay* d = initialized_display(dpy, "eglDestroySurface");
  if (d == nullptr) return EGL_FALSE;
  EglSurface* s = find_surface(d, surface);
  if (s == nullptr) return fail(EGL_BAD_SURFACE, "eglDestroySurface", EGL_FALSE);
  destroy_surface(d, s);
  succeed();
  return EGL_TRUE;
}

EGL_EXPORT EGLBoolean EGLAPIENTRY eglQuerySurface(EGLDisplay dpy, EGLSurface surface,
                                                  EGLint attribute, EGLint* value) {
  const char* fn = "eglQuerySurface";
  std::lock_guard<std::mutex> lock(egl_mutex());
  EglDisplay* d = initialized_display(dpy, fn);
  if (d == nullptr) return EGL_FALSE;
  EglSurface* s = find_surface(d, surface);
  if (s == nullptr) return fail(EGL_BAD_SURFACE, fn, EGL_FALSE);
  EGLint v = 0;
  switch (attribute) {
  case EGL_CONFIG_ID:
    v = s->config->id;
    break;
  case EGL_GL_COLORSPACE:
    v = EGL_GL_COLORSPACE_LINEAR;
    break;
  case EGL_WIDTH:
  case EGL_HEIGHT:
    // A window's size is the server's, which may have changed.
    if (s->type == EGL_WINDOW_BIT) refresh_size(*s);
    v = attribute == EGL_WIDTH ? s->width : s->height;
    break;
  case EGL_HORIZONTAL_RESOLUTION:
  case EGL_VERTICAL_RESOLUTION:
  case EGL_PIXEL_ASPECT_RATIO:
    v = EGL_UNKNOWN;
    break;
  case EGL_LARGEST_PBUFFER:
    // §3.5.6: only for pbuffers; other surfaces leave value unchanged.
    if (s->type != EGL_PBUFFER_BIT) {
      succeed();
      return EGL_TRUE;
    }
    v = s->largest;
    break;
  case EGL_MIPMAP_TEXTURE:
    v = s->mipmap_texture;
    break;
  case EGL_MIPMAP_LEVEL:
    v = s->mipmap_level;
    break;
  case EGL_MULTISAMPLE_RESOLVE:
    v = s->multisample_resolve;
    break;
  case EGL_RENDER_BUFFER:
    v = s->type == EGL_PIXMAP_BIT ? EGL_SINGLE_BUFFER : s->render_buffer;
    break;
  case EGL_SWAP_BEHAVIOR:
    v = s->swap_behavior;
    break;
  case EGL_TEXTURE_FORMAT:
    v = s->texture_format;
    break;
  case EGL_TEXTURE_TARGET:
    v = s->texture_target;
    break;
  case EGL_VG_ALPHA_FORMAT:
    v = EGL_VG_ALPHA_FORMAT_NONPRE;
    break;
  case EGL_VG_COLORSPACE:
    v = EGL_VG_COLORSPACE_sRGB;
    break;
  default:
    return fail(EGL_BAD_ATTRIBUTE, fn, EGL_FALSE);
  }
  if (value == nullptr) return fail(EGL_BAD_PARAMETER, fn, EGL_FALSE);
  *value = v;
  succeed();
  return EGL_TRUE;
}

EGL_EXPORT EGLBoolean EGLAPIENTRY eglSurfaceAttrib(EGLDisplay dpy, EGLSurface surface,
                                                   EGLint attribute, EGLint value) {
  const char* fn = "eglSurfaceAttrib";
  std::lock_guard<std::mutex> lock(egl_mutex());
  EglDisplay* d = initialized_display(dpy, fn);
  if (d == nullptr) return EGL_FALSE;
  EglSurface* s = find_surface(d, surface);
  if (s == nullptr) return fail(EGL_BAD_SURFACE, fn, EGL_FALSE);
  switch (attribute) {
  case EGL_MIPMAP_LEVEL:
    s->mipmap_level = value;
    break;
  case EGL_MULTISAMPLE_RESOLVE:
    if (value == EGL_MULTISAMPLE_RESOLVE_BOX) {
      if ((s->config->surface_type & EGL_MULTISAMPLE_RESOLVE_BOX_BIT) == 0)
        return fail(EGL_BAD_MATCH, fn, EGL_FALSE);
    } else if (value != EGL_MULTISAMPLE_RESOLVE_DEFAULT) {
      return fail(EGL_BAD_PARAMETER, fn, EGL_FALSE);
    }
    s->multisample_resolve = value;
    break;
  case EGL_SWAP_BEHAVIOR:
    if (value == EGL_BUFFER_PRESERVED) {
      if ((s->config->surface_type & EGL_SWAP_BEHAVIOR_PRESERVED_BIT) == 0)
        return fail(EGL_BAD_MATCH, fn, EGL_FALSE);
    } else if (value != EGL_BUFFER_DESTROYED) {
      return fail(EGL_BAD_PARAMETER, fn, EGL_FALSE);
    }
    s->swap_behavior = value;
    break;
  default:
    return fail(EGL_BAD_ATTRIBUTE, fn, EGL_FALSE);
  }
  succeed();
  return EGL_TRUE;
}

EGL_EXPORT EGLBoolean EGLAPIENTRY eglSwapBuffers(EGLDisplay dpy, EGLSurface surface) {
  const char* fn = "eglSwapBuffers";
  std::unique_lock<std::mutex> lock(egl_mutex());
  EglDisplay* d = initialized_display(dpy, fn);
  if (d == nullptr) return EGL_FALSE;
  EglSurface* s = find_surface(d, surface);
  if (s == nullptr) return fail(EGL_BAD_SURFACE, fn, EGL_FALSE);
  // §3.10.1: the surface must be bound to the calling thread's current context.
  EglContext* ctx = current();
  if (ctx == nullptr || ctx->draw != s) return fail(EGL_BAD_SURFACE, fn, EGL_FALSE);
  if (s->type != EGL_WINDOW_BIT) {
    // Pixmaps and pbuffers have no back buffer to post: no effect.
    succeed();
    return EGL_TRUE;
  }
  if (!has_back_buffer(*s)) {
    flush_front(ctx);
    succeed();
    return EGL_TRUE;
  }
  const auto due = winsys::swap_due(s->swap_interval, s->last_swap);
  if (due > std::chrono::steady_clock::now()) {
    lock.unlock();
    std::this_thread::sleep_until(due);
    lock.lock();
    // The surface may have been destroyed meanwhile (by another thread's eglTerminate).
    if (ctx->draw != s) return fail(EGL_BAD_SURFACE, fn, EGL_FALSE);
  }
  // The back buffer becomes the front; as in GLX it is copied only while GL uses the front.
  if (winsys::uses_front(ctx) && !s->front.empty()) {
    std::memcpy(s->front.data(), s->image->data, s->front.size());
    s->front_stale = false;
  } else {
    s->front_stale = true;
  }
  int w = 0, h = 0;
  if (x11::swap_images(*s, &w, &h)) {
    if (w != s->width || h != s->height) refresh_size(*s);
    for (EglContext* c : s->bound)
      attach(c, *s);
  } else {
    x11::present(*s);
    if (!refresh_size(*s)) return fail(EGL_BAD_NATIVE_WINDOW, fn, EGL_FALSE);
  }
  succeed();
  return EGL_TRUE;
}

EGL_EXPORT EGLBoolean EGLAPIENTRY eglSwapInterval(EGLDisplay dpy, EGLint interval) {
  const char* fn = "eglSwapInterval";
  std::lock_guard<std::mutex> lock(egl_mutex());
  EglDisplay* d = initialized_display(dpy, fn);
  if (d == nullptr) return EGL_FALSE;
  // §3.10.3: the interval of the window surface bound to the current context, clamped to the
  // config's EGL_MIN_SWAP_INTERVAL and EGL_MAX_SWAP_INTERVAL.
  EglContext* ctx = current();
  if (ctx == nullptr || ctx->display != d) return fail(EGL_BAD_CONTEXT, fn, EGL_FALSE);
  if (ctx->draw == nullptr) return fail(EGL_BAD_SURFACE, fn, EGL_FALSE);
  ctx->draw->swap_interval = std::clamp(interval, 0, kMaxSwapInterval);
  succeed();
  return EGL_TRUE;
}

EGL_EXPORT EGLBoolean EGLAPIENTRY eglCopyBuffers(EGLDisplay dpy, EGLSurface surface,
                                                 EGLNativePixmapType target) {
  const char* fn = "eglCopyBuffers";
  std::lock_guard<std::mutex> lock(egl_mutex());
  EglDisplay* d = initialized_display(dpy, fn);
  if (d == nullptr) return EGL_FALSE;
  EglSurface* s = find_surface(d, surface);
  if (s == nullptr) return fail(EGL_BAD_SURFACE, fn, EGL_FALSE);
  const auto pixmap = static_cast<Pixmap>(target);
  int w = 0, h = 0, depth = 0;
  if (d->platform != Platform::X11 || pixmap == 0 ||
      !x11::geometry(d->dpy, pixmap, &w, &h, &depth, nullptr))
    return fail(EGL_BAD_NATIVE_PIXMAP, fn, EGL_FALSE);
  // §3.9.2: the pixmap must have the surface's colour format (here: the visual's depth).
  if (s->config->x.visual == nullptr || depth != s->config->x.depth)
    return fail(EGL_BAD_MATCH, fn, EGL_FALSE);
  bool ok = false;
  if (s->type == EGL_PBUFFER_BIT) {
    // A pbuffer's rows are bottom-up in `memory`: an image of the visual over a flipped copy.
    x11::Target t;
    t.dpy = d->dpy;
    t.x_drawable = pixmap;
    t.format = s->config->x;
    t.is_window = false;
    if (x11::allocate_images(t, s->width, s->height, false)) {
      const size_t row = static_cast<size_t>(s->width) * 4;
      for (int y = 0; y < s->height; ++y)
        std::memcpy(t.image->data + static_cast<size_t>(y) * t.image->bytes_per_line,
                    s->memory.data() + static_cast<size_t>(s->height - 1 - y) * row, row);
      ok = x11::copy_to_pixmap(t, pixmap);
      x11::release_images(t);
    }
  } else {
    ok = x11::copy_to_pixmap(*s, pixmap);
  }
  if (!ok) return fail(EGL_BAD_NATIVE_PIXMAP, fn, EGL_FALSE);
  succeed();
  return EGL_TRUE;
}

// §3.6.1: no config has EGL_BIND_TO_TEXTURE_RGB or _RGBA, so no surface has a texture format.
EGL_EXPORT EGLBoolean EGLAPIENTRY eglBindTexImage(EGLDisplay dpy, EGLSurface surface,
                                                  EGLint buffer) {
  const char* fn = "eglBindTexImage";
  std::lock_guard<std::mutex> lock(egl_mutex());
  EglDisplay* d = initialized_display(dpy, fn);
  if (d == nullptr) return EGL_FALSE;
  EglSurface* s = find_surface(d, surface);
  if (s == nullptr) return fail(EGL_BAD_SURFACE, fn, EGL_FALSE);
  if (buffer != EGL_BACK_BUFFER) return fail(EGL_BAD_PARAMETER, fn, EGL_FALSE);
  if (s->type != EGL_PBUFFER_BIT) return fail(EGL_BAD_SURFACE, fn, EGL_FALSE);
  return fail(EGL_BAD_MATCH, fn, EGL_FALSE);
}

EGL_EXPORT EGLBoolean EGLAPIENTRY eglReleaseTexImage(EGLDisplay dpy, EGLSurface surface,
                                                     EGLint buffer) {
  const char* fn = "eglReleaseTexImage";
  std::lock_guard<std::mutex> lock(egl_mutex());
  EglDisplay* d = initialized_display(dpy, fn);
  if (d == nullptr) return EGL_FALSE;
  EglSurface* s = find_surface(d, surface);
  if (s == nullptr) return fail(EGL_BAD_SURFACE, fn, EGL_FALSE);
  if (buffer != EGL_BACK_BUFFER) return fail(EGL_BAD_PARAMETER, fn, EGL_FALSE);
  if (s->type != EGL_PBUFFER_BIT) return fail(EGL_BAD_SURFACE, fn, EGL_FALSE);
  return fail(EGL_BAD_MATCH, fn, EGL_FALSE);
}
