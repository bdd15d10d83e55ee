// EGL contexts and the current state (EGL 1.5 §3.7: eglBindAPI, eglCreateContext with
// EGL_KHR_create_context's attributes, eglMakeCurrent, the eglGetCurrent* queries), the wait
// functions and eglReleaseThread (§3.8, §3.11), fence syncs (§3.8.1) and images (§3.9).
#include <cstdio>

#include "dispatch.h"
#include "winsys/egl/egl_internal.h"

namespace pineda::egl {

namespace {

// This thread's EGL binding (§3.7.3: a context is current to one thread at a time).
thread_local EglContext* t_ctx = nullptr;
thread_local EglDisplay* t_display = nullptr;
// eglBindAPI's value on this thread when no glvnd libEGL keeps it. OpenGL ES is not
// supported, so the initial value is EGL_NONE (§3.7).
thread_local EGLenum t_api = EGL_NONE;
EGLenum (*g_api_source)() = nullptr;

// The highest GL version glGetString(GL_VERSION) reports, as major*10+minor.
int supported_gl_version() {
  static const int version = [] {
    Context* saved = current_context();
    int major = 1, minor = 0;
    {
      Context probe;
      set_current_context(&probe);
      const auto* s = reinterpret_cast<const char*>(exec::GetString(GL_VERSION));
      if (s != nullptr && std::sscanf(s, "%d.%d", &major, &minor) != 2) major = 1, minor = 0;
      set_current_context(saved);
    }
    return major * 10 + minor;
  }();
  return version;
}

bool version_defined(int major, int minor) {
  switch (major) {
  case 1:
    return minor >= 0 && minor <= 5;
  case 2:
    return minor >= 0 && minor <= 1;
  case 3:
    return minor >= 0 && minor <= 3;
  case 4:
    return minor >= 0 && minor <= 6;
  default:
    return false;
  }
}

// glFlush / glFinish: a single-buffered window or a pixmap shows what was rendered.
void present_front_hook(Context* gl) {
  std::lock_guard<std::mutex> lock(egl_mutex());
  flush_front(static_cast<EglContext*>(gl));
}

// DrawBuffer/ReadBuffer chose the front buffer of a window: fetch what the window shows.
void front_selected_hook(Context* gl) {
  std::lock_guard<std::mutex> lock(egl_mutex());
  auto* ctx = static_cast<EglContext*>(gl);
  if (ctx->draw != nullptr && ctx->draw->front_stale) x11::pull_front(*ctx->draw);
}

// Ends ctx's binding to this thread, flushing it first (§3.7.3).
void unbind(EglContext* ctx) {
  flush_front(ctx);
  release_surface(ctx, ctx->draw);
  ctx->draw = ctx->read = nullptr;
  ctx->is_current = false;
  ctx->thread = std::thread::id{};
  if (ctx->destroy_pending) delete ctx;
}

void release_current() {
  if (t_ctx == nullptr) return;
  EglContext* ctx = t_ctx;
  t_ctx = nullptr;
  t_display = nullptr;
  if (current_context() == ctx) set_current_context(nullptr);
  unbind(ctx);
}

} // namespace

EglContext* find_context(EglDisplay* d, EGLContext handle) {
  auto* c = static_cast<EglContext*>(handle);
  return d->contexts.count(c) != 0 ? c : nullptr;
}

EglContext* current() {
  return t_ctx != nullptr && current_context() == t_ctx ? t_ctx : nullptr;
}

void terminate_objects(EglDisplay* d) {
  for (EglContext* c : std::vector<EglContext*>(d->contexts.begin(), d->contexts.end())) {
    d->contexts.erase(c);
    if (c->is_current)
      c->destroy_pending = true;
    else
      delete c;
  }
  for (EglSurface* s : std::vector<EglSurface*>(d->surfaces.begin(), d->surfaces.end()))
    if (!s->destroy_pending) destroy_surface(d, s);
  for (EglSync* s : d->syncs)
    delete s;
  d->syncs.clear();
}

EGLenum bound_api() {
  return g_api_source != nullptr ? g_api_source() : t_api;
}

void set_api_source(EGLenum (*get_current_api)()) {
  g_api_source = get_current_api;
}

} // namespace pineda::egl

using namespace pineda::egl;

EGL_EXPORT EGLBoolean EGLAPIENTRY eglBindAPI(EGLenum api) {
  // §3.7: only OpenGL is offered until Pineda has OpenGL ES contexts.
  if (api != EGL_OPENGL_API) return fail(EGL_BAD_PARAMETER, "eglBindAPI", EGL_FALSE);
  pineda::egl::t_api = api;
  succeed();
  return EGL_TRUE;
}

EGL_EXPORT EGLenum EGLAPIENTRY eglQueryAPI(void) {
  succeed();
  return bound_api();
}

EGL_EXPORT EGLContext EGLAPIENTRY eglCreateContext(EGLDisplay dpy, EGLConfig config,
                                                   EGLContext share_context,
                                                   const EGLint* attrib_list) {
  const char* fn = "eglCreateContext";
  std::lock_guard<std::mutex> lock(egl_mutex());
  EglDisplay* d = initialized_display(dpy, fn);
  if (d == nullptr) return EGL_NO_CONTEXT;
  // §3.7.1: a context of the bound API; with none bound (or OpenGL ES, which Pineda's configs
  // do not support) there is nothing to create.
  if (bound_api() != EGL_OPENGL_API) return fail(EGL_BAD_MATCH, fn, EGL_NO_CONTEXT);
  const EglConfig* c = find_config(d, config);
  if (c == nullptr) return fail(EGL_BAD_CONFIG, fn, EGL_NO_CONTEXT);
  EGLint major = 1, minor = 0, flags = 0, profile = EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT;
  EGLint reset = EGL_NO_RESET_NOTIFICATION;
  bool robust = false;
  for (int i = 0; attrib_list != nullptr && attrib_list[i] != EGL_NONE; i += 2) {
    const EGLint v = attrib_list[i + 1];
    switch (attrib_list[i]) {
    case EGL_CONTEXT_MAJOR_VERSION:
      major = v;
      break;
    case EGL_CONTEXT_MINOR_VERSION:
      minor = v;
      break;
    case EGL_CONTEXT_FLAGS_KHR:
      flags = v;
      break;
    case EGL_CONTEXT_OPENGL_PROFILE_MASK:
      profile = v;
      break;
    case EGL_CONTEXT_OPENGL_DEBUG:
      if (v != EGL_TRUE && v != EGL_FALSE) return fail(EGL_BAD_ATTRIBUTE, fn, EGL_NO_CONTEXT);
      if (v == EGL_TRUE) flags |= EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR;
      break;
    case EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE:
      if (v != EGL_TRUE && v != EGL_FALSE) return fail(EGL_BAD_ATTRIBUTE, fn, EGL_NO_CONTEXT);
      if (v == EGL_TRUE) flags |= EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE_BIT_KHR;
      break;
    case EGL_CONTEXT_OPENGL_ROBUST_ACCESS:
      if (v != EGL_TRUE && v != EGL_FALSE) return fail(EGL_BAD_ATTRIBUTE, fn, EGL_NO_CONTEXT);
      robust = v == EGL_TRUE;
      break;
    case EGL_CONTEXT_OPENGL_RESET_NOTIFICATION_STRATEGY:
      if (v != EGL_NO_RESET_NOTIFICATION && v != EGL_LOSE_CONTEXT_ON_RESET)
        return fail(EGL_BAD_ATTRIBUTE, fn, EGL_NO_CONTEXT);
      reset = v;
      break;
    default:
      return fail(EGL_BAD_ATTRIBUTE, fn, EGL_NO_CONTEXT);
    }
  }
  const EGLint known_flags = EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR |
                             EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE_BIT_KHR |
                             EGL_CONTEXT_OPENGL_ROBUST_ACCESS_BIT_KHR;
  if ((flags & ~known_flags) != 0) return fail(EGL_BAD_ATTRIBUTE, fn, EGL_NO_CONTEXT);
  robust = robust || (flags & EGL_CONTEXT_OPENGL_ROBUST_ACCESS_BIT_KHR) != 0;
  // A version that does not exist, or that the config cannot give: Pineda's contexts provide
  // the version glGetString(GL_VERSION) reports (compatibility profile) and no more.
  if (!version_defined(major, minor) || major * 10 + minor > supported_gl_version())
    return fail(EGL_BAD_MATCH, fn, EGL_NO_CONTEXT);
  // The profile mask matters from 3.2 on and must name one profile.
  if (major * 10 + minor >= 32 && profile != EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT &&
      profile != EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT)
    return fail(EGL_BAD_MATCH, fn, EGL_NO_CONTEXT);
  // Robust buffer access and reset notification are not offered.
  if (robust || reset != EGL_NO_RESET_NOTIFICATION) return fail(EGL_BAD_MATCH, fn, EGL_NO_CONTEXT);
  EglContext* share = nullptr;
  if (share_context != EGL_NO_CONTEXT) {
    share = find_context(d, share_context);
    if (share == nullptr) return fail(EGL_BAD_CONTEXT, fn, EGL_NO_CONTEXT);
  }
  auto* ctx = share != nullptr ? new (std::nothrow) EglContext(share->shared)
                               : new (std::nothrow) EglContext();
  if (ctx == nullptr) return fail(EGL_BAD_ALLOC, fn, EGL_NO_CONTEXT);
  ctx->display = d;
  ctx->config = c;
  ctx->major = major;
  ctx->minor = minor;
  d->contexts.insert(ctx);
  succeed();
  return static_cast<EGLContext>(ctx);
}

EGL_EXPORT EGLBoolean EGLAPIENTRY eglDestroyContext(EGLDisplay dpy, EGLContext ctx) {
  std::lock_guard<std::mutex> lock(egl_mutex());
  EglDisplay* d = initialized_display(dpy, "eglDestroyContext");
  if (d == nullptr) return EGL_FALSE;
  EglContext* c = find_context(d, ctx);
  if (c == nullptr) return fail(EGL_BAD_CONTEXT, "eglDestroyContext", EGL_FALSE);
  d->contexts.erase(c);
  // §3.7.2: a context current to some thread lives on until it is released there.
  if (c->is_current)
    c->destroy_pending = true;
  else
    delete c;
  succeed();
  return EGL_TRUE;
}

EGL_EXPORT EGLBoolean EGLAPIENTRY eglMakeCurrent(EGLDisplay dpy, EGLSurface draw, EGLSurface read,
                                                 EGLContext ctx) {
  const char* fn = "eglMakeCurrent";
  std::lock_guard<std::mutex> lock(egl_mutex());
  EglDisplay* d = find_display(dpy, fn);
  if (d == nullptr) return EGL_FALSE;
  if (ctx == EGL_NO_CONTEXT) {
    // §3.7.3: releasing takes no surfaces; it is allowed on a display that is not initialized.
    if (draw != EGL_NO_SURFACE || read != EGL_NO_SURFACE) return fail(EGL_BAD_MATCH, fn, EGL_FALSE);
    release_current();
    succeed();
    return EGL_TRUE;
  }
  if (!d->initialized) return fail(EGL_NOT_INITIALIZED, fn, EGL_FALSE);
  EglContext* c = find_context(d, ctx);
  if (c == nullptr) return fail(EGL_BAD_CONTEXT, fn, EGL_FALSE);
  // One surface without the other is a mismatch; neither is EGL_KHR_surfaceless_context.
  if ((draw == EGL_NO_SURFACE) != (read == EGL_NO_SURFACE))
    return fail(EGL_BAD_MATCH, fn, EGL_FALSE);
  EglSurface* s = nullptr;
  if (draw != EGL_NO_SURFACE) {
    s = find_surface(d, draw);
    EglSurface* r = find_surface(d, read);
    if (s == nullptr || r == nullptr) return fail(EGL_BAD_SURFACE, fn, EGL_FALSE);
    // Pineda's GL reads from the surface it draws to: a separate read surface is refused
    // rather than silently ignored.
    if (r != s) return fail(EGL_BAD_MATCH, fn, EGL_FALSE);
    // The surface's config must be compatible with the context's: the same colour layout
    // and ancillary buffers.
    if (s->config->format != c->config->format || s->config->alpha != c->config->alpha ||
        s->config->depth != c->config->depth || s->config->stencil != c->config->stencil)
      return fail(EGL_BAD_MATCH, fn, EGL_FALSE);
    // §3.7.3: a surface bound to a context of another thread.
    for (EglContext* other : s->bound)
      if (other != c && other->is_current && other->thread != std::this_thread::get_id())
        return fail(EGL_BAD_ACCESS, fn, EGL_FALSE);
  }
  if (c->is_current && c->thread != std::this_thread::get_id())
    return fail(EGL_BAD_ACCESS, fn, EGL_FALSE);
  if (s != nullptr && !refresh_size(*s)) return fail(EGL_BAD_NATIVE_WINDOW, fn, EGL_FALSE);
  if (t_ctx != nullptr && t_ctx != c) release_current();
  if (c->draw != s) {
    if (c->draw != nullptr) {
      flush_front(c);
      release_surface(c, c->draw);
    }
    if (s != nullptr) s->bound.push_back(c);
  }
  c->draw = c->read = s;
  if (s != nullptr) {
    if (s->type == EGL_PIXMAP_BIT) x11::pull_pixmap(*s);
    pineda::winsys::first_make_current(c, s->width, s->height, has_back_buffer(*s));
    attach(c, *s);
  } else {
    // EGL_KHR_surfaceless_context: no default framebuffer; drawing has no effect.
    pineda::winsys::unbind_buffers(c);
  }
  pineda::winsys::set_hooks(c, &present_front_hook, &front_selected_hook);
  c->is_current = true;
  c->thread = std::this_thread::get_id();
  t_ctx = c;
  t_display = d;
  pineda::set_current_context(c);
  succeed();
  return EGL_TRUE;
}

EGL_EXPORT EGLContext EGLAPIENTRY eglGetCurrentContext(void) {
  succeed();
  EglContext* c = current();
  return c != nullptr ? static_cast<EGLContext>(c) : EGL_NO_CONTEXT;
}

EGL_EXPORT EGLSurface EGLAPIENTRY eglGetCurrentSurface(EGLint readdraw) {
  if (readdraw != EGL_DRAW && readdraw != EGL_READ)
    return fail(EGL_BAD_PARAMETER, "eglGetCurrentSurface", EGL_NO_SURFACE);
  succeed();
  EglContext* c = current();
  if (c == nullptr) return EGL_NO_SURFACE;
  return static_cast<EGLSurface>(readdraw == EGL_DRAW ? c->draw : c->read);
}

EGL_EXPORT EGLDisplay EGLAPIENTRY eglGetCurrentDisplay(void) {
  succeed();
  return current() != nullptr ? static_cast<EGLDisplay>(t_display) : EGL_NO_DISPLAY;
}

EGL_EXPORT EGLBoolean EGLAPIENTRY eglQueryContext(EGLDisplay dpy, EGLContext ctx, EGLint attribute,
                                                  EGLint* value) {
  const char* fn = "eglQueryContext";
  std::lock_guard<std::mutex> lock(egl_mutex());
  EglDisplay* d = initialized_display(dpy, fn);
  if (d == nullptr) return EGL_FALSE;
  EglContext* c = find_context(d, ctx);
  if (c == nullptr) return fail(EGL_BAD_CONTEXT, fn, EGL_FALSE);
  EGLint v = 0;
  switch (attribute) {
  case EGL_CONFIG_ID:
    v = c->config->id;
    break;
  case EGL_CONTEXT_CLIENT_TYPE:
    v = EGL_OPENGL_API;
    break;
  case EGL_CONTEXT_CLIENT_VERSION:
    v = c->major;
    break;
  case EGL_RENDER_BUFFER:
    // §3.7.4: the buffer the context renders to on its draw surface; EGL_NONE without one.
    if (c->draw == nullptr)
      v = EGL_NONE;
    else if (c->draw->type == EGL_PIXMAP_BIT)
      v = EGL_SINGLE_BUFFER;
    else
      v = has_back_buffer(*c->draw) ? EGL_BACK_BUFFER : EGL_SINGLE_BUFFER;
    break;
  default:
    return fail(EGL_BAD_ATTRIBUTE, fn, EGL_FALSE);
  }
  if (value == nullptr) return fail(EGL_BAD_PARAMETER, fn, EGL_FALSE);
  *value = v;
  succeed();
  return EGL_TRUE;
}

// §3.8: GL rendering is complete when each command returns; what remains is to show a
// single-buffered window or pixmap to the window system.
EGL_EXPORT EGLBoolean EGLAPIENTRY eglWaitClient(void) {
  std::lock_guard<std::mutex> lock(egl_mutex());
  if (EglContext* c = current()) {
    if (c->draw != nullptr && c->draw->type != EGL_PBUFFER_BIT && c->draw->dpy == nullptr)
      return fail(EGL_BAD_CURRENT_SURFACE, "eglWaitClient", EGL_FALSE);
    flush_front(c);
  }
  succeed();
  return EGL_TRUE;
}

EGL_EXPORT EGLBoolean EGLAPIENTRY eglWaitGL(void) {
  return eglWaitClient();
}

EGL_EXPORT EGLBoolean EGLAPIENTRY eglWaitNative(EGLint engine) {
  std::lock_guard<std::mutex> lock(egl_mutex());
  if (engine != EGL_CORE_NATIVE_ENGINE) return fail(EGL_BAD_PARAMETER, "eglWaitNative", EGL_FALSE);
  EglContext* c = current();
  if (c != nullptr && c->draw != nullptr && c->draw->dpy != nullptr) {
    XSync(c->draw->dpy, False);
    // X rendering into a pixmap becomes visible to GL.
    if (c->draw->type == EGL_PIXMAP_BIT) x11::pull_pixmap(*c->draw);
  }
  succeed();
  return EGL_TRUE;
}

EGL_EXPORT EGLBoolean EGLAPIENTRY eglReleaseThread(void) {
  std::lock_guard<std::mutex> lock(egl_mutex());
  release_current();
  pineda::egl::t_api = EGL_NONE;
  succeed();
  return EGL_TRUE;
}

// ---- fence syncs (§3.8.1) ----

namespace {

EglSync* find_sync(EglDisplay* d, EGLSync handle) {
  auto* s = static_cast<EglSync*>(handle);
  return d->syncs.count(s) != 0 ? s : nullptr;
}

} // namespace

EGL_EXPORT EGLSync EGLAPIENTRY eglCreateSync(EGLDisplay dpy, EGLenum type,
                                             const EGLAttrib* attrib_list) {
  const char* fn = "eglCreateSync";
  std::lock_guard<std::mutex> lock(egl_mutex());
  EglDisplay* d = initialized_display(dpy, fn);
  if (d == nullptr) return EGL_NO_SYNC;
  if (type != EGL_SYNC_FENCE) return fail(EGL_BAD_PARAMETER, fn, EGL_NO_SYNC);
  if (attrib_list != nullptr && attrib_list[0] != EGL_NONE)
    return fail(EGL_BAD_ATTRIBUTE, fn, EGL_NO_SYNC);
  // A fence goes into the current context's command stream, which must be on this display.
  EglContext* c = current();
  if (c == nullptr || c->display != d) return fail(EGL_BAD_MATCH, fn, EGL_NO_SYNC);
  auto* s = new (std::nothrow) EglSync;
  if (s == nullptr) return fail(EGL_BAD_ALLOC, fn, EGL_NO_SYNC);
  s->display = d;
  d->syncs.insert(s);
  succeed();
  return static_cast<EGLSync>(s);
}

EGL_EXPORT EGLBoolean EGLAPIENTRY eglDestroySync(EGLDisplay dpy, EGLSync sync) {
  std::lock_guard<std::mutex> lock(egl_mutex());
  EglDisplay* d = initialized_display(dpy, "eglDestroySync");
  if (d == nullptr) return EGL_FALSE;
  EglSync* s = find_sync(d, sync);
  if (s == nullptr) return fail(EGL_BAD_PARAMETER, "eglDestroySync", EGL_FALSE);
  d->syncs.erase(s);
  delete s;
  succeed();
  return EGL_TRUE;
}

EGL_EXPORT EGLint EGLAPIENTRY eglClientWaitSync(EGLDisplay dpy, EGLSync sync, EGLint flags,
                                                EGLTime /*timeout*/) {
  const char* fn = "eglClientWaitSync";
  std::lock_guard<std::mutex> lock(egl_mutex());
  EglDisplay* d = initialized_display(dpy, fn);
  if (d == nullptr) return EGL_FALSE;
  if (find_sync(d, sync) == nullptr) return fail(EGL_BAD_PARAMETER, fn, EGL_FALSE);
  if ((flags & ~EGL_SYNC_FLUSH_COMMANDS_BIT) != 0) return fail(EGL_BAD_PARAMETER, fn, EGL_FALSE);
  // Every fence is signaled when it is made (rendering is synchronous).
  succeed();
  return EGL_CONDITION_SATISFIED;
}

EGL_EXPORT EGLBoolean EGLAPIENTRY eglWaitSync(EGLDisplay dpy, EGLSync sync, EGLint flags) {
  const char* fn = "eglWaitSync";
  std::lock_guard<std::mutex> lock(egl_mutex());
  EglDisplay* d = initialized_display(dpy, fn);
  if (d == nullptr) return EGL_FALSE;
  if (find_sync(d, sync) == nullptr) return fail(EGL_BAD_PARAMETER, fn, EGL_FALSE);
  if (flags != 0) return fail(EGL_BAD_PARAMETER, fn, EGL_FALSE);
  EglContext* c = current();
  if (c == nullptr || c->display != d) return fail(EGL_BAD_MATCH, fn, EGL_FALSE);
  succeed();
  return EGL_TRUE;
}

EGL_EXPORT EGLBoolean EGLAPIENTRY eglGetSyncAttrib(EGLDisplay dpy, EGLSync sync, EGLint attribute,
                                                   EGLAttrib* value) {
  const char* fn = "eglGetSyncAttrib";
  std::lock_guard<std::mutex> lock(egl_mutex());
  EglDisplay* d = initialized_display(dpy, fn);
  if (d == nullptr) return EGL_FALSE;
  EglSync* s = find_sync(d, sync);
  if (s == nullptr) return fail(EGL_BAD_PARAMETER, fn, EGL_FALSE);
  EGLAttrib v = 0;
  switch (attribute) {
  case EGL_SYNC_TYPE:
    v = s->type;
    break;
  case EGL_SYNC_STATUS:
    v = EGL_SIGNALED;
    break;
  case EGL_SYNC_CONDITION:
    v = EGL_SYNC_PRIOR_COMMANDS_COMPLETE;
    break;
  default:
    return fail(EGL_BAD_ATTRIBUTE, fn, EGL_FALSE);
  }
  if (value == nullptr) return fail(EGL_BAD_PARAMETER, fn, EGL_FALSE);
  *value = v;
  succeed();
  return EGL_TRUE;
}

// ---- images (§3.9) ----

// No client buffer can become an EGLImage yet (GL textures and renderbuffers as image sources
// are not offered), so every target is refused with the error §3.9.1 names.
EGL_EXPORT EGLImage EGLAPIENTRY eglCreateImage(EGLDisplay dpy, EGLContext ctx, EGLenum /*target*/,
                                               EGLClientBuffer /*buffer*/,
                                               const EGLAttrib* /*attrib_list*/) {
  const char* fn = "eglCreateImage";
  std::lock_guard<std::mutex> lock(egl_mutex());
  EglDisplay* d = initialized_display(dpy, fn);
  if (d == nullptr) return EGL_NO_IMAGE;
  if (ctx != EGL_NO_CONTEXT && find_context(d, ctx) == nullptr)
    return fail(EGL_BAD_CONTEXT, fn, EGL_NO_IMAGE);
  return fail(EGL_BAD_PARAMETER, fn, EGL_NO_IMAGE);
}

EGL_EXPORT EGLBoolean EGLAPIENTRY eglDestroyImage(EGLDisplay dpy, EGLImage /*image*/) {
  std::lock_guard<std::mutex> lock(egl_mutex());
  EglDisplay* d = initialized_display(dpy, "eglDestroyImage");
  if (d == nullptr) return EGL_FALSE;
  // No image exists, so no handle names one.
  return fail(EGL_BAD_PARAMETER, "eglDestroyImage", EGL_FALSE);
}
