// GLX contexts, the current context and drawables, buffer swaps, synchronisation, strings and
// glXGetProcAddress (GLX 1.4 §3.3.1-§3.3.2, §3.3.7, §3.3.9-§3.3.10, §3.3.12, §3.5;
// GLX_ARB_create_context, GLX_MESA_swap_control).
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <new>
#include <unordered_set>

#include "dispatch.h"
#include "state/attrib.h"
#include "winsys/glx/glx_internal.h"

#define GLX_EXPORT extern "C" __attribute__((visibility("default")))

namespace pineda::glx {

namespace {

constexpr const char* kVendor = "Pineda";
constexpr const char* kVersion = "1.4";
constexpr const char* kExtensions =
    "GLX_ARB_create_context GLX_ARB_create_context_profile GLX_ARB_get_proc_address "
    "GLX_EXT_swap_control GLX_EXT_visual_info GLX_MESA_swap_control";

std::unordered_set<GlxContext*>& contexts() {
  // Never destroyed: a library loaded after the application registered its exit handlers
  // (glvnd loads vendors on first use) has its destructors run before them, and handlers such
  // as freeglut's still make GLX calls.
  static auto* set = new std::unordered_set<GlxContext*>;
  return *set;
}

// This thread's GLX binding (GLX 1.4 §3.3.7: a context is current to one thread at a time).
thread_local GlxContext* t_ctx = nullptr;
thread_local Display* t_dpy = nullptr;

GlxContext* lookup_context(GLXContext handle) {
  auto* ctx = reinterpret_cast<GlxContext*>(handle);
  return handle != nullptr && contexts().count(ctx) != 0 ? ctx : nullptr;
}

// Whether this thread's GLX context is the one GL calls go to (OSMesa may have taken over).
GlxContext* current_glx() {
  return t_ctx != nullptr && current_context() == t_ctx ? t_ctx : nullptr;
}

bool presents_on_flush(const Surface& s) {
  return s.kind != SurfaceKind::Pbuffer && !has_back_buffer(s);
}

// What glFlush shows of ctx's draw drawable: a single-buffered window or a pixmap shows what
// was rendered, a double-buffered window what was rendered into its front buffer (GL 2.1
// §5.5); back-buffer rendering waits for the swap.
void flush_front(GlxContext* ctx) {
  if (ctx->draw == nullptr) return;
  if (presents_on_flush(*ctx->draw))
    present(*ctx->draw);
  else if (draws_front(*ctx))
    x11::present_front(*ctx->draw);
}

// glFlush / glFinish.
void present_front_hook(Context* gl) {
  std::lock_guard<std::mutex> lock(registry_mutex());
  flush_front(static_cast<GlxContext*>(gl));
}

// DrawBuffer/ReadBuffer chose the front buffer: fetch its contents if a swap left them to the
// window.
void front_selected_hook(Context* gl) {
  std::lock_guard<std::mutex> lock(registry_mutex());
  auto* ctx = static_cast<GlxContext*>(gl);
  if (ctx->draw != nullptr && ctx->draw->front_stale) x11::pull_front(*ctx->draw);
}

// Ends ctx's binding on this thread: pending front-buffer rendering is flushed first
// (§3.3.7: the previous context is flushed when it is released).
void unbind(GlxContext* ctx) {
  if (ctx->draw != nullptr) {
    flush_front(ctx);
    auto& bound = ctx->draw->bound;
    bound.erase(std::remove(bound.begin(), bound.end(), ctx), bound.end());
  }
  ctx->draw.reset();
  ctx->read.reset();
  ctx->draw_id = ctx->read_id = None;
  ctx->is_current = false;
  ctx->thread = std::thread::id{};
  if (ctx->destroy_pending) delete ctx;
}

void release_current() {
  if (t_ctx != nullptr) {
    GlxContext* ctx = t_ctx;
    t_ctx = nullptr;
    t_dpy = nullptr;
    if (current_context() == ctx) set_current_context(nullptr);
    unbind(ctx);
  }
}

// The surface a MakeCurrent names: a GLX drawable, or an X window used directly (GLX 1.2
// style), which gets an implicit surface with the context's config.
std::shared_ptr<Surface> resolve(DisplayState* ds, GLXDrawable id, GlxContext* ctx, int req) {
  const Config* want = ctx->config;
  std::shared_ptr<Surface> s = find_surface(ds, id);
  if (s != nullptr && !s->implicit) {
    // Compatible configs (§3.3.7): same screen and the same colour buffer layout.
    if (s->config->screen != want->screen || s->config->x.color != want->x.color ||
        s->config->x.depth != want->x.depth) {
      report_error(ds, -1, BadMatch, id, req);
      return nullptr;
    }
    return s;
  }
  // An X window used directly. The server says whether it still exists and which visual it
  // has now: window ids are reused after XDestroyWindow.
  XWindowAttributes wa{};
  const int err = trap_errors(ds->dpy, [&] { XGetWindowAttributes(ds->dpy, id, &wa); });
  if (err != 0 || wa.visual == nullptr) {
    if (s != nullptr && s->bound.empty()) ds->surfaces.erase(id);
    report_error(ds, GLXBadDrawable, 0, id, req);
    return nullptr;
  }
  if (XVisualIDFromVisual(wa.visual) != want->x.visual_id) {
    report_error(ds, -1, BadMatch, id, req);
    return nullptr;
  }
  if (s != nullptr) {
    // The window takes the ancillary buffers of the context that binds it, unless another
    // context is drawing into it right now.
    if (s->config != want && s->bound.empty()) {
      s->config = want;
      if (!allocate_buffers(*s, wa.width, wa.height)) {
        ds->surfaces.erase(id);
        report_error(ds, -1, BadAlloc, id, req);
        return nullptr;
      }
    }
    return s;
  }
  s = std::make_shared<Surface>();
  init_surface(*s, ds, SurfaceKind::Window, id, want);
  s->implicit = true;
  s->id = id;
  if (!allocate_buffers(*s, wa.width, wa.height)) {
    report_error(ds, -1, BadAlloc, id, req);
    return nullptr;
  }
  ds->surfaces[id] = s;
  return s;
}

Bool make_current(Display* dpy, GLXDrawable draw, GLXDrawable read, GLXContext handle, int req) {
  ApiLock api;
  DisplayState* ds = display_state(dpy);
  GlxContext* ctx = lookup_context(handle);
  // A context destroyed while current lives on until it is released (§3.3.7), and may be made
  // current again meanwhile on its thread, as Mesa allows: freeglut's exit handler destroys
  // the current context and then binds it again to close its window.
  if (ctx == nullptr && handle != nullptr && reinterpret_cast<GlxContext*>(handle) == t_ctx)
    ctx = t_ctx;
  if (handle != nullptr && ctx == nullptr) {
    report_error(ds, GLXBadContext, 0, 0, req);
    return False;
  }
  if (ctx == nullptr) {
    // §3.3.7: releasing takes None drawables.
    if (draw != None || read != None) {
      report_error(ds, -1, BadMatch, draw, req);
      return False;
    }
    release_current();
    return True;
  }
  if (ds == nullptr || ctx->ds != ds || draw == None || read == None) {
    report_error(ds, -1, BadMatch, draw, req);
    return False;
  }
  if (ctx->is_current && ctx->thread != std::this_thread::get_id()) {
    report_error(ds, -1, BadAccess, draw, req);
    return False;
  }
  std::shared_ptr<Surface> s = resolve(ds, draw, ctx, req);
  if (s == nullptr) return False;
  std::shared_ptr<Surface> r = read == draw ? s : resolve(ds, read, ctx, req);
  if (r == nullptr) return False;
  // Pineda's GL reads from the drawable it draws to: a separate read drawable cannot be
  // honoured yet, so it is refused rather than silently ignored.
  if (r != s) {
    report_error(ds, -1, BadMatch, read, req);
    return False;
  }
  if (!refresh_size(*s)) {
    report_error(ds, GLXBadDrawable, 0, draw, req);
    return False;
  }
  if (t_ctx != nullptr && t_ctx != ctx) release_current();
  if (ctx->draw != s) {
    if (ctx->draw != nullptr) {
      if (presents_on_flush(*ctx->draw)) present(*ctx->draw);
      auto& bound = ctx->draw->bound;
      bound.erase(std::remove(bound.begin(), bound.end(), ctx), bound.end());
    }
    s->bound.push_back(ctx);
  }
  ctx->draw = s;
  ctx->read = r;
  ctx->draw_id = draw;
  ctx->read_id = read;
  // GL rendering must see what X drew into a pixmap (§3.3.9 glXWaitX semantics on binding).
  if (s->kind == SurfaceKind::Pixmap) x11::pull_pixmap(*s);
  // The viewport, scissor box and draw and read buffers start from the drawable; set before
  // attach, which selects the buffers they name.
  winsys::first_make_current(ctx, s->width, s->height, has_back_buffer(*s));
  attach(ctx, *s);
  winsys::set_hooks(ctx, &present_front_hook, &front_selected_hook);
  ctx->is_current = true;
  ctx->thread = std::this_thread::get_id();
  t_ctx = ctx;
  t_dpy = dpy;
  set_current_context(ctx);
  return True;
}

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

GLXContext create_context(DisplayState* ds, const Config* c, GLXContext share, int req) {
  GlxContext* other = nullptr;
  if (share != nullptr) {
    other = lookup_context(share);
    if (other == nullptr) {
      report_error(ds, GLXBadContext, 0, 0, req);
      return nullptr;
    }
    if (other->ds != ds || other->config->screen != c->screen) {
      report_error(ds, -1, BadMatch, 0, req);
      return nullptr;
    }
  }
  // §3.3.7: the new context shares the objects of share_list's group.
  auto* ctx = other != nullptr ? new (std::nothrow) GlxContext(other->shared)
                               : new (std::nothrow) GlxContext();
  if (ctx == nullptr) {
    report_error(ds, -1, BadAlloc, 0, req);
    return nullptr;
  }
  ctx->ds = ds;
  ctx->config = c;
  ctx->id = alloc_xid(ds->dpy);
  contexts().insert(ctx);
  return reinterpret_cast<GLXContext>(ctx);
}

// GLX_ARB_create_context: the OpenGL versions that exist.
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

} // namespace

GlxContext* current_binding(Display** dpy) {
  GlxContext* c = current_glx();
  *dpy = c != nullptr ? t_dpy : nullptr;
  return c;
}

} // namespace pineda::glx

using namespace pineda::glx;

GLX_EXPORT Bool glXQueryExtension(Display* dpy, int* errorBase, int* eventBase) {
  ApiLock api;
  DisplayState* ds = display_state(dpy);
  if (ds == nullptr) return False;
  // GLX is implemented here, on the client, so every display supports it.
  if (errorBase != nullptr) *errorBase = ds->error_base;
  if (eventBase != nullptr) *eventBase = ds->event_base;
  return True;
}

GLX_EXPORT Bool glXQueryVersion(Display* dpy, int* major, int* minor) {
  if (dpy == nullptr) return False;
  if (major != nullptr) *major = 1;
  if (minor != nullptr) *minor = 4;
  return True;
}

GLX_EXPORT const char* glXQueryExtensionsString(Display* dpy, int screen) {
  if (dpy == nullptr || screen < 0 || screen >= ScreenCount(dpy)) return nullptr;
  return kExtensions;
}

GLX_EXPORT const char* glXGetClientString(Display* /*dpy*/, int name) {
  switch (name) {
  case GLX_VENDOR:
    return kVendor;
  case GLX_VERSION:
    return kVersion;
  case GLX_EXTENSIONS:
    return kExtensions;
  default:
    return nullptr;
  }
}

// The server side of GLX is this library as well, so it answers with the client's strings.
GLX_EXPORT const char* glXQueryServerString(Display* dpy, int screen, int name) {
  if (dpy == nullptr || screen < 0 || screen >= ScreenCount(dpy)) return nullptr;
  return glXGetClientString(dpy, name);
}

GLX_EXPORT GLXContext glXCreateContext(Display* dpy, XVisualInfo* vis, GLXContext shareList,
                                       Bool /*direct*/) {
  ApiLock api;
  DisplayState* ds = display_state(dpy);
  if (ds == nullptr) return nullptr;
  // §3.5: the config is the visual's; a visual without one is a BadValue.
  const Config* c = config_for_visual(ds, vis);
  if (c == nullptr) {
    report_error(ds, -1, BadValue, 0, kReqCreateContext);
    return nullptr;
  }
  return create_context(ds, c, shareList, kReqCreateContext);
}

GLX_EXPORT GLXContext glXCreateNewContext(Display* dpy, GLXFBConfig config, int renderType,
                                          GLXContext shareList, Bool /*direct*/) {
  ApiLock api;
  DisplayState* ds = display_state(dpy);
  if (ds == nullptr) return nullptr;
  const Config* c = find_config(ds, config);
  if (c == nullptr) {
    report_error(ds, GLXBadFBConfig, 0, 0, kReqCreateNewContext);
    return nullptr;
  }
  if (renderType != GLX_RGBA_TYPE) {
    // §3.3.7: colour index needs a config with GLX_COLOR_INDEX_BIT, which none has.
    report_error(ds, -1, renderType == GLX_COLOR_INDEX_TYPE ? BadMatch : BadValue, 0,
                 kReqCreateNewContext);
    return nullptr;
  }
  return create_context(ds, c, shareList, kReqCreateNewContext);
}

GLX_EXPORT GLXContext glXCreateContextAttribsARB(Display* dpy, GLXFBConfig config,
                                                 GLXContext shareContext, Bool /*direct*/,
                                                 const int* attribList) {
  ApiLock api;
  DisplayState* ds = display_state(dpy);
  if (ds == nullptr) return nullptr;
  const int req = kReqCreateContextAttribsARB;
  int major = 1, minor = 0, flags = 0, render_type = GLX_RGBA_TYPE;
  int profile = GLX_CONTEXT_CORE_PROFILE_BIT_ARB;
  for (int i = 0; attribList != nullptr && attribList[i] != None; i += 2) {
    const int v = attribList[i + 1];
    switch (attribList[i]) {
    case GLX_CONTEXT_MAJOR_VERSION_ARB:
      major = v;
      break;
    case GLX_CONTEXT_MINOR_VERSION_ARB:
      minor = v;
      break;
    case GLX_CONTEXT_FLAGS_ARB:
      flags = v;
      break;
    case GLX_CONTEXT_PROFILE_MASK_ARB:
      profile = v;
      break;
    case GLX_RENDER_TYPE:
      render_type = v;
      break;
    default:
      report_error(ds, -1, BadValue, 0, req);
      return nullptr;
    }
  }
  const int known_flags = GLX_CONTEXT_DEBUG_BIT_ARB | GLX_CONTEXT_FORWARD_COMPATIBLE_BIT_ARB;
  if ((flags & ~known_flags) != 0 || render_type != GLX_RGBA_TYPE) {
    report_error(ds, -1, BadValue, 0, req);
    return nullptr;
  }
  // A version that does not exist, or forward compatibility before 3.0 (deprecation starts
  // there), is BadMatch.
  if (!version_defined(major, minor) ||
      ((flags & GLX_CONTEXT_FORWARD_COMPATIBLE_BIT_ARB) != 0 && major < 3)) {
    report_error(ds, -1, BadMatch, 0, req);
    return nullptr;
  }
  // GLX_ARB_create_context_profile: the mask matters from 3.2 on, and must name one profile.
  if (major * 10 + minor >= 32 && profile != GLX_CONTEXT_CORE_PROFILE_BIT_ARB &&
      profile != GLX_CONTEXT_COMPATIBILITY_PROFILE_BIT_ARB) {
    report_error(ds, GLXBadProfileARB, 0, 0, req);
    return nullptr;
  }
  const Config* c = find_config(ds, config);
  // A config that cannot give the requested version is GLXBadFBConfig: Pineda's contexts
  // provide the version glGetString(GL_VERSION) reports (compatibility profile) and no more.
  if (c == nullptr || major * 10 + minor > supported_gl_version()) {
    report_error(ds, GLXBadFBConfig, 0, 0, req);
    return nullptr;
  }
  return create_context(ds, c, shareContext, req);
}

GLX_EXPORT void glXDestroyContext(Display* dpy, GLXContext ctx) {
  ApiLock api;
  DisplayState* ds = display_state(dpy);
  GlxContext* c = lookup_context(ctx);
  if (c == nullptr) {
    report_error(ds, GLXBadContext, 0, 0, kReqDestroyContext);
    return;
  }
  contexts().erase(c);
  // §3.3.7: a context current to some thread lives on until it is released there.
  if (c->is_current)
    c->destroy_pending = true;
  else
    delete c;
}

// GLX 1.4 §3.3.7: copies the attribute groups of `mask` (glPushAttrib's bits) from source to
// dest, with glPopAttrib's order and the same code (src/state/attrib.cpp).
GLX_EXPORT void glXCopyContext(Display* dpy, GLXContext source, GLXContext dest,
                               unsigned long mask) {
  ApiLock api;
  DisplayState* ds = display_state(dpy);
  GlxContext* src = lookup_context(source);
  GlxContext* dst = lookup_context(dest);
  if (src == nullptr || dst == nullptr) {
    report_error(ds, GLXBadContext, 0, 0, kReqCopyContext);
    return;
  }
  // Every context lives in this process, so only the screens can differ.
  if (ds == nullptr || src->ds != ds || dst->ds != ds ||
      src->config->screen != dst->config->screen) {
    report_error(ds, -1, BadMatch, 0, kReqCopyContext);
    return;
  }
  if (dst->is_current) {
    report_error(ds, -1, BadAccess, 0, kReqCopyContext);
    return;
  }
  // The flush and the copy run GL code whose window-system hooks take the registry lock.
  const bool flush = src == current_glx();
  api.lock.unlock();
  // "glXCopyContext performs an implicit glFlush if source is the current context".
  if (flush) pineda::exec::Flush();
  pineda::copy_attrib_groups(src, dst, static_cast<GLbitfield>(mask));
  api.lock.lock();
}

GLX_EXPORT Bool glXMakeCurrent(Display* dpy, GLXDrawable drawable, GLXContext ctx) {
  return make_current(dpy, drawable, drawable, ctx, kReqMakeCurrent);
}

GLX_EXPORT Bool glXMakeContextCurrent(Display* dpy, GLXDrawable draw, GLXDrawable read,
                                      GLXContext ctx) {
  return make_current(dpy, draw, read, ctx, kReqMakeContextCurrent);
}

GLX_EXPORT GLXContext glXGetCurrentContext(void) {
  return reinterpret_cast<GLXContext>(current_glx());
}

GLX_EXPORT GLXDrawable glXGetCurrentDrawable(void) {
  GlxContext* c = current_glx();
  return c != nullptr ? c->draw_id : None;
}

GLX_EXPORT GLXDrawable glXGetCurrentReadDrawable(void) {
  GlxContext* c = current_glx();
  return c != nullptr ? c->read_id : None;
}

GLX_EXPORT Display* glXGetCurrentDisplay(void) {
  return current_glx() != nullptr ? t_dpy : nullptr;
}

GLX_EXPORT Bool glXIsDirect(Display* dpy, GLXContext ctx) {
  ApiLock api;
  if (lookup_context(ctx) == nullptr) {
    report_error(display_state(dpy), GLXBadContext, 0, 0, kReqIsDirect);
    return False;
  }
  // Rendering happens in the calling process, never through the X server.
  return True;
}

GLX_EXPORT int glXQueryContext(Display* dpy, GLXContext ctx, int attribute, int* value) {
  ApiLock api;
  DisplayState* ds = display_state(dpy);
  if (ds == nullptr) return GLX_NO_EXTENSION;
  GlxContext* c = lookup_context(ctx);
  if (c == nullptr) {
    report_error(ds, GLXBadContext, 0, 0, kReqQueryContext);
    return GLX_BAD_CONTEXT;
  }
  int v = 0;
  switch (attribute) {
  case GLX_FBCONFIG_ID:
    v = c->config->id;
    break;
  case GLX_RENDER_TYPE:
    v = c->render_type;
    break;
  case GLX_SCREEN:
    v = c->config->screen;
    break;
  default:
    return GLX_BAD_ATTRIBUTE;
  }
  if (value != nullptr) *value = v;
  return Success;
}

GLX_EXPORT void glXSwapBuffers(Display* dpy, GLXDrawable drawable) {
  ApiLock api;
  DisplayState* ds = display_state(dpy);
  if (ds == nullptr) return;
  std::shared_ptr<Surface> s = find_surface(ds, drawable);
  if (s == nullptr) {
    report_error(ds, GLXBadDrawable, 0, drawable, kReqSwapBuffers);
    return;
  }
  // §3.3.10: swapping a pixmap (or a single-buffered drawable) does nothing beyond the
  // implicit glFlush, which for those drawables presents what was rendered.
  if (s->kind == SurfaceKind::Window && has_back_buffer(*s)) {
    const auto due = swap_due(*s);
    if (due > std::chrono::steady_clock::now()) {
      api.lock.unlock();
      std::this_thread::sleep_until(due);
      api.lock.lock();
    }
    // The back buffer's contents become the front's; the copy keeps the back buffer as it was
    // (its contents are undefined after the swap). Skipped while no context uses the front
    // buffer: the window then holds it, fetched when a context selects it.
    bool front_used = false;
    for (GlxContext* c : s->bound)
      front_used = front_used || uses_front(*c);
    if (front_used && !s->front.empty()) {
      std::memcpy(s->front.data(), s->image->data, s->front.size());
      s->front_stale = false;
    } else {
      s->front_stale = true;
    }
    if (!swap_images(*s)) {
      present(*s);
      // The window may have been resized: the next frame renders at its new size (the back
      // buffer's contents are undefined after a swap, so nothing is lost).
      refresh_size(*s);
    }
  } else if (presents_on_flush(*s)) {
    present(*s);
  }
}

GLX_EXPORT void glXWaitGL(void) {
  ApiLock api;
  // GL rendering is finished when the call returns; what remains is to show it to X.
  GlxContext* c = current_glx();
  if (c != nullptr) flush_front(c);
}

GLX_EXPORT void glXWaitX(void) {
  ApiLock api;
  GlxContext* c = current_glx();
  if (c == nullptr || t_dpy == nullptr) return;
  XSync(t_dpy, False);
  // X rendering into a pixmap becomes visible to GL (§3.3.9).
  if (c->draw != nullptr && c->draw->kind == SurfaceKind::Pixmap)
    pineda::x11::pull_pixmap(*c->draw);
}

GLX_EXPORT int glXSwapIntervalMESA(unsigned int interval) {
  ApiLock api;
  GlxContext* c = current_glx();
  if (c == nullptr || c->draw == nullptr) return GLX_BAD_CONTEXT;
  if (interval > static_cast<unsigned>(INT32_MAX)) return GLX_BAD_VALUE;
  set_swap_interval(c->ds, c->draw->id, static_cast<int>(interval));
  return 0;
}

GLX_EXPORT int glXGetSwapIntervalMESA(void) {
  ApiLock api;
  GlxContext* c = current_glx();
  return c != nullptr && c->draw != nullptr ? c->draw->swap_interval : 0;
}

GLX_EXPORT __GLXextFuncPtr glXGetProcAddressARB(const GLubyte* procName);

namespace {
struct GlxProc {
  const char* name;
  __GLXextFuncPtr proc;
};
#define PINEDA_GLX_PROC(f)                                                                         \
  { #f, reinterpret_cast < __GLXextFuncPtr>(&f) }
const GlxProc kGlxProcs[] = {
    PINEDA_GLX_PROC(glXChooseFBConfig),
    PINEDA_GLX_PROC(glXChooseVisual),
    PINEDA_GLX_PROC(glXCopyContext),
    PINEDA_GLX_PROC(glXCreateContext),
    PINEDA_GLX_PROC(glXCreateContextAttribsARB),
    PINEDA_GLX_PROC(glXCreateGLXPixmap),
    PINEDA_GLX_PROC(glXCreateNewContext),
    PINEDA_GLX_PROC(glXCreatePbuffer),
    PINEDA_GLX_PROC(glXCreatePixmap),
    PINEDA_GLX_PROC(glXCreateWindow),
    PINEDA_GLX_PROC(glXDestroyContext),
    PINEDA_GLX_PROC(glXDestroyGLXPixmap),
    PINEDA_GLX_PROC(glXDestroyPbuffer),
    PINEDA_GLX_PROC(glXDestroyPixmap),
    PINEDA_GLX_PROC(glXDestroyWindow),
    PINEDA_GLX_PROC(glXGetClientString),
    PINEDA_GLX_PROC(glXGetConfig),
    PINEDA_GLX_PROC(glXGetCurrentContext),
    PINEDA_GLX_PROC(glXGetCurrentDisplay),
    PINEDA_GLX_PROC(glXGetCurrentDrawable),
    PINEDA_GLX_PROC(glXGetCurrentReadDrawable),
    PINEDA_GLX_PROC(glXGetFBConfigAttrib),
    PINEDA_GLX_PROC(glXGetFBConfigs),
    PINEDA_GLX_PROC(glXGetProcAddress),
    PINEDA_GLX_PROC(glXGetProcAddressARB),
    PINEDA_GLX_PROC(glXGetSelectedEvent),
    PINEDA_GLX_PROC(glXGetSwapIntervalMESA),
    PINEDA_GLX_PROC(glXGetVisualFromFBConfig),
    PINEDA_GLX_PROC(glXIsDirect),
    PINEDA_GLX_PROC(glXMakeContextCurrent),
    PINEDA_GLX_PROC(glXMakeCurrent),
    PINEDA_GLX_PROC(glXQueryContext),
    PINEDA_GLX_PROC(glXQueryDrawable),
    PINEDA_GLX_PROC(glXQueryExtension),
    PINEDA_GLX_PROC(glXQueryExtensionsString),
    PINEDA_GLX_PROC(glXQueryServerString),
    PINEDA_GLX_PROC(glXQueryVersion),
    PINEDA_GLX_PROC(glXSelectEvent),
    PINEDA_GLX_PROC(glXSwapBuffers),
    PINEDA_GLX_PROC(glXSwapIntervalEXT),
    PINEDA_GLX_PROC(glXSwapIntervalMESA),
    PINEDA_GLX_PROC(glXUseXFont),
    PINEDA_GLX_PROC(glXWaitGL),
    PINEDA_GLX_PROC(glXWaitX),
};
#undef PINEDA_GLX_PROC
} // namespace

// GLX 1.4 §3.3.12: GL and GLX functions by name; NULL for names Pineda does not implement.
GLX_EXPORT __GLXextFuncPtr glXGetProcAddressARB(const GLubyte* procName) {
  const auto* name = reinterpret_cast<const char*>(procName);
  if (name == nullptr) return nullptr;
  for (const GlxProc& p : kGlxProcs)
    if (std::strcmp(p.name, name) == 0) return p.proc;
  return reinterpret_cast<__GLXextFuncPtr>(pineda::lookup_gl_proc(name));
}

GLX_EXPORT __GLXextFuncPtr glXGetProcAddress(const GLubyte* procName) {
  return glXGetProcAddressARB(procName);
}
