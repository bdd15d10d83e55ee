// GLX drawables (GLX 1.4 §3.3.4-§3.3.6, §3.3.8, §3.4.2): GLXWindows, GLXPixmaps and
// GLXPbuffers, the buffers Pineda renders into for them, and their attributes.
#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <new>

#include "state/draw_read_buffer.h"
#include "winsys/glx/glx_internal.h"

#define GLX_EXPORT extern "C" __attribute__((visibility("default")))

namespace pineda::glx {

namespace {

// The largest swap interval glXSwapIntervalEXT keeps (GLX_MAX_SWAP_INTERVAL_EXT).
constexpr int kMaxSwapInterval = 64;

using x11::geometry;

// A new surface of `kind` for an X drawable (or a pbuffer when `x` is 0) with its buffers.
std::shared_ptr<Surface> make_surface(DisplayState* ds, SurfaceKind kind, Drawable x,
                                      const Config* c, int w, int h) {
  auto s = std::make_shared<Surface>();
  init_surface(*s, ds, kind, x, c);
  if (!allocate_buffers(*s, w, h)) return nullptr;
  return s;
}

// GLX 1.4 §3.3.5: a GLXPixmap on an X pixmap of the config's depth and screen.
GLXPixmap create_pixmap(DisplayState* ds, const Config* c, Pixmap pixmap, int request) {
  int w = 0, h = 0, depth = 0, screen = -1;
  if (!geometry(ds->dpy, pixmap, &w, &h, &depth, &screen)) {
    report_error(ds, -1, BadPixmap, pixmap, request);
    return None;
  }
  if (depth != c->x.depth || screen != c->screen) {
    report_error(ds, -1, BadMatch, pixmap, request);
    return None;
  }
  std::shared_ptr<Surface> s = make_surface(ds, SurfaceKind::Pixmap, pixmap, c, w, h);
  if (s == nullptr) {
    report_error(ds, -1, BadAlloc, pixmap, request);
    return None;
  }
  s->id = alloc_xid(ds->dpy);
  ds->surfaces[s->id] = s;
  return s->id;
}

// Drops a GLX drawable's id; its storage lives on while a context is current on it (§3.3.4).
void destroy_surface(DisplayState* ds, XID id, SurfaceKind kind, int glx_error, int request) {
  auto it = ds->surfaces.find(id);
  if (it == ds->surfaces.end() || it->second->kind != kind || it->second->implicit) {
    report_error(ds, glx_error, 0, id, request);
    return;
  }
  ds->surfaces.erase(it);
}

bool attribs_empty(const int* list) {
  return list == nullptr || list[0] == None;
}

} // namespace

Surface::~Surface() {
  orphan_surface(*this);
}

void init_surface(Surface& s, DisplayState* ds, SurfaceKind kind, Drawable x, const Config* c) {
  s.ds = ds;
  s.dpy = ds->dpy;
  s.kind = kind;
  s.x_drawable = x;
  s.config = c;
  s.format = c->x;
  s.is_window = kind == SurfaceKind::Window;
  s.double_buffered = c->double_buffer && kind != SurfaceKind::Pixmap;
}

void orphan_surface(Surface& s) {
  if (s.ds == nullptr) return;
  for (GlxContext* ctx : s.bound)
    winsys::unbind_buffers(ctx);
  x11::release_images(s);
  s.ds = nullptr;
  s.dpy = nullptr;
}

std::shared_ptr<Surface> find_surface(DisplayState* ds, XID id) {
  auto it = ds->surfaces.find(id);
  return it == ds->surfaces.end() ? nullptr : it->second;
}

bool allocate_buffers(Surface& s, int width, int height) {
  const size_t pixels = static_cast<size_t>(width) * static_cast<size_t>(height);
  try {
    if (s.kind == SurfaceKind::Pbuffer) {
      s.memory.assign(std::max<size_t>(pixels, 1) * 4, 0);
      s.width = width;
      s.height = height;
    } else if (!x11::allocate_images(s, width, height, s.ds->shm)) {
      return false;
    }
    s.depth.assign(s.config->depth_bits > 0 ? pixels : 0, 0);
    s.stencil.assign(s.config->stencil_bits > 0 ? pixels : 0, 0);
    s.accum.assign(s.config->accum_bits > 0 ? 4 * pixels : 0, 0);
  } catch (const std::bad_alloc&) {
    return false;
  }
  return true;
}

bool refresh_size(Surface& s) {
  if (s.kind == SurfaceKind::Pbuffer) return true;
  if (s.ds == nullptr) return false;
  int w = 0, h = 0;
  if (!geometry(s.dpy, s.x_drawable, &w, &h, nullptr, nullptr)) return false;
  if (w == s.width && h == s.height && (s.image != nullptr || w == 0)) return true;
  if (!allocate_buffers(s, w, h)) return false;
  // Every context drawing here sees the new buffers (a resize while another thread renders
  // into the same drawable is not synchronised).
  for (GlxContext* ctx : s.bound)
    attach(ctx, s);
  return true;
}

bool swap_images(Surface& s) {
  if (s.kind != SurfaceKind::Window || s.ds == nullptr) return false;
  int w = 0, h = 0;
  if (!x11::swap_images(s, &w, &h)) return false;
  if ((w != s.width || h != s.height) && !allocate_buffers(s, w, h)) return true;
  for (GlxContext* ctx : s.bound)
    attach(ctx, s);
  return true;
}

void attach(GlxContext* ctx, Surface& s) {
  winsys::SurfaceBuffers b;
  b.width = s.width;
  b.height = s.height;
  b.format = s.config->x.color;
  b.alpha_bits = s.config->alpha_bits;
  if (s.kind == SurfaceKind::Pbuffer) {
    b.color = s.memory.data();
    b.stride = static_cast<ptrdiff_t>(s.width) * 4;
  } else {
    x11::describe_color(s, &b.color, &b.stride, &b.front);
  }
  b.back = has_back_buffer(s);
  b.depth_bits = s.config->depth_bits;
  b.depth = s.depth.empty() ? nullptr : s.depth.data();
  b.stencil_bits = s.config->stencil_bits;
  b.stencil = s.stencil.empty() ? nullptr : s.stencil.data();
  b.accum_bits = s.config->accum_bits;
  b.accum = s.accum.empty() ? nullptr : s.accum.data();
  winsys::bind_buffers(ctx, b);
  // The registry lock is held here, so the front_selected hook (which takes it) did not run;
  // the front buffer is fetched directly instead.
  if (b.front != nullptr && s.front_stale && uses_front(*ctx)) x11::pull_front(s);
}

bool has_back_buffer(const Surface& s) {
  return s.config->double_buffer && s.kind != SurfaceKind::Pixmap;
}

} // namespace pineda::glx

using namespace pineda::glx;

GLX_EXPORT GLXWindow glXCreateWindow(Display* dpy, GLXFBConfig config, Window win,
                                     const int* attribList) {
  ApiLock api;
  DisplayState* ds = display_state(dpy);
  if (ds == nullptr) return None;
  const Config* c = find_config(ds, config);
  if (c == nullptr) {
    report_error(ds, GLXBadFBConfig, 0, win, kReqCreateWindow);
    return None;
  }
  // §3.3.4: no attributes are defined.
  if (!attribs_empty(attribList)) {
    report_error(ds, -1, BadValue, win, kReqCreateWindow);
    return None;
  }
  XWindowAttributes wa{};
  int err = trap_errors(dpy, [&] { XGetWindowAttributes(dpy, win, &wa); });
  if (err != 0) {
    report_error(ds, -1, BadWindow, win, kReqCreateWindow);
    return None;
  }
  if (wa.visual == nullptr || XVisualIDFromVisual(wa.visual) != c->x.visual_id ||
      XScreenNumberOfScreen(wa.screen) != c->screen) {
    report_error(ds, -1, BadMatch, win, kReqCreateWindow);
    return None;
  }
  for (const auto& [id, s] : ds->surfaces)
    if (s->kind == SurfaceKind::Window && !s->implicit && s->x_drawable == win) {
      report_error(ds, -1, BadAlloc, win, kReqCreateWindow);
      return None;
    }
  std::shared_ptr<Surface> s = make_surface(ds, SurfaceKind::Window, win, c, wa.width, wa.height);
  if (s == nullptr) {
    report_error(ds, -1, BadAlloc, win, kReqCreateWindow);
    return None;
  }
  s->id = alloc_xid(dpy);
  ds->surfaces[s->id] = s;
  return s->id;
}

GLX_EXPORT void glXDestroyWindow(Display* dpy, GLXWindow window) {
  ApiLock api;
  if (DisplayState* ds = display_state(dpy))
    destroy_surface(ds, window, SurfaceKind::Window, GLXBadWindow, kReqDestroyWindow);
}

GLX_EXPORT GLXPixmap glXCreatePixmap(Display* dpy, GLXFBConfig config, Pixmap pixmap,
                                     const int* attribList) {
  ApiLock api;
  DisplayState* ds = display_state(dpy);
  if (ds == nullptr) return None;
  const Config* c = find_config(ds, config);
  if (c == nullptr) {
    report_error(ds, GLXBadFBConfig, 0, pixmap, kReqCreatePixmap);
    return None;
  }
  if (!attribs_empty(attribList)) {
    report_error(ds, -1, BadValue, pixmap, kReqCreatePixmap);
    return None;
  }
  return create_pixmap(ds, c, pixmap, kReqCreatePixmap);
}

GLX_EXPORT void glXDestroyPixmap(Display* dpy, GLXPixmap pixmap) {
  ApiLock api;
  if (DisplayState* ds = display_state(dpy))
    destroy_surface(ds, pixmap, SurfaceKind::Pixmap, GLXBadPixmap, kReqDestroyPixmap);
}

GLX_EXPORT GLXPixmap glXCreateGLXPixmap(Display* dpy, XVisualInfo* visual, Pixmap pixmap) {
  ApiLock api;
  DisplayState* ds = display_state(dpy);
  if (ds == nullptr) return None;
  // §3.4.2: the config is the one the visual's GLX_FBCONFIG_ID names.
  const Config* c = config_for_visual(ds, visual);
  if (c == nullptr) {
    report_error(ds, -1, BadValue, pixmap, kReqCreateGLXPixmap);
    return None;
  }
  return create_pixmap(ds, c, pixmap, kReqCreateGLXPixmap);
}

GLX_EXPORT void glXDestroyGLXPixmap(Display* dpy, GLXPixmap pixmap) {
  ApiLock api;
  if (DisplayState* ds = display_state(dpy))
    destroy_surface(ds, pixmap, SurfaceKind::Pixmap, GLXBadPixmap, kReqDestroyGLXPixmap);
}

GLX_EXPORT GLXPbuffer glXCreatePbuffer(Display* dpy, GLXFBConfig config, const int* attribList) {
  ApiLock api;
  DisplayState* ds = display_state(dpy);
  if (ds == nullptr) return None;
  const Config* c = find_config(ds, config);
  if (c == nullptr) {
    report_error(ds, GLXBadFBConfig, 0, 0, kReqCreatePbuffer);
    return None;
  }
  int w = 0, h = 0;
  bool preserved = true, largest = false;
  for (int i = 0; attribList != nullptr && attribList[i] != None; i += 2) {
    const int v = attribList[i + 1];
    switch (attribList[i]) {
    case GLX_PBUFFER_WIDTH:
      w = v;
      break;
    case GLX_PBUFFER_HEIGHT:
      h = v;
      break;
    case GLX_PRESERVED_CONTENTS:
      preserved = v != False;
      break;
    case GLX_LARGEST_PBUFFER:
      largest = v != False;
      break;
    default:
      report_error(ds, -1, BadValue, 0, kReqCreatePbuffer);
      return None;
    }
  }
  if (w < 0 || h < 0) {
    report_error(ds, -1, BadValue, 0, kReqCreatePbuffer);
    return None;
  }
  int max_w = 0, max_h = 0;
  config_attrib(*c, GLX_MAX_PBUFFER_WIDTH, &max_w);
  config_attrib(*c, GLX_MAX_PBUFFER_HEIGHT, &max_h);
  if (largest) {
    // §3.3.5: the largest available pbuffer no bigger than the request.
    w = std::min(w, max_w);
    h = std::min(h, max_h);
  } else if (w > max_w || h > max_h) {
    report_error(ds, -1, BadAlloc, 0, kReqCreatePbuffer);
    return None;
  }
  std::shared_ptr<Surface> s = make_surface(ds, SurfaceKind::Pbuffer, 0, c, w, h);
  if (s == nullptr) {
    report_error(ds, -1, BadAlloc, 0, kReqCreatePbuffer);
    return None;
  }
  s->preserved = preserved;
  s->largest = largest;
  s->id = alloc_xid(dpy);
  ds->surfaces[s->id] = s;
  return s->id;
}

GLX_EXPORT void glXDestroyPbuffer(Display* dpy, GLXPbuffer pbuf) {
  ApiLock api;
  if (DisplayState* ds = display_state(dpy))
    destroy_surface(ds, pbuf, SurfaceKind::Pbuffer, GLXBadPbuffer, kReqDestroyPbuffer);
}

GLX_EXPORT void glXQueryDrawable(Display* dpy, GLXDrawable draw, int attribute,
                                 unsigned int* value) {
  ApiLock api;
  DisplayState* ds = display_state(dpy);
  if (ds == nullptr) return;
  std::shared_ptr<Surface> s = find_surface(ds, draw);
  if (s == nullptr || draw == None) {
    report_error(ds, GLXBadDrawable, 0, draw, kReqGetDrawableAttributes);
    return;
  }
  unsigned int v = 0;
  switch (attribute) {
  case GLX_WIDTH:
  case GLX_HEIGHT:
    // A window's size is the server's, which may have changed since it was last current.
    refresh_size(*s);
    v = static_cast<unsigned>(attribute == GLX_WIDTH ? s->width : s->height);
    break;
  case GLX_PRESERVED_CONTENTS:
    v = s->preserved ? True : False;
    break;
  case GLX_LARGEST_PBUFFER:
    v = s->largest ? True : False;
    break;
  case GLX_FBCONFIG_ID:
    v = static_cast<unsigned>(s->config->id);
    break;
  case GLX_EVENT_MASK:
    v = static_cast<unsigned>(s->event_mask);
    break;
  case GLX_SWAP_INTERVAL_EXT:
    v = static_cast<unsigned>(s->swap_interval);
    break;
  case GLX_MAX_SWAP_INTERVAL_EXT:
    v = kMaxSwapInterval;
    break;
  default:
    report_error(ds, -1, BadValue, draw, kReqGetDrawableAttributes);
    return;
  }
  if (value != nullptr) *value = v;
}

GLX_EXPORT void glXSelectEvent(Display* dpy, GLXDrawable drawable, unsigned long mask) {
  ApiLock api;
  DisplayState* ds = display_state(dpy);
  if (ds == nullptr) return;
  std::shared_ptr<Surface> s = find_surface(ds, drawable);
  // §3.3.8: only GLXWindows and GLXPbuffers take GLX events.
  if (s == nullptr || s->kind == SurfaceKind::Pixmap) {
    report_error(ds, GLXBadDrawable, 0, drawable, kReqChangeDrawableAttributes);
    return;
  }
  if ((mask & ~static_cast<unsigned long>(GLX_PBUFFER_CLOBBER_MASK)) != 0) {
    report_error(ds, -1, BadValue, drawable, kReqChangeDrawableAttributes);
    return;
  }
  // Pineda's pbuffers live in ordinary memory and are never clobbered, so a selected clobber
  // event never has a reason to be sent.
  s->event_mask = mask;
}

GLX_EXPORT void glXGetSelectedEvent(Display* dpy, GLXDrawable drawable, unsigned long* mask) {
  ApiLock api;
  DisplayState* ds = display_state(dpy);
  if (ds == nullptr) return;
  std::shared_ptr<Surface> s = find_surface(ds, drawable);
  if (s == nullptr || s->kind == SurfaceKind::Pixmap) {
    report_error(ds, GLXBadDrawable, 0, drawable, kReqGetDrawableAttributes);
    return;
  }
  if (mask != nullptr) *mask = s->event_mask;
}

namespace pineda::glx {

// GLX_EXT_swap_control: the interval of a drawable; values above the maximum are clamped.
void set_swap_interval(DisplayState* ds, GLXDrawable drawable, int interval) {
  std::shared_ptr<Surface> s = find_surface(ds, drawable);
  if (s == nullptr || s->kind == SurfaceKind::Pixmap) {
    report_error(ds, GLXBadDrawable, 0, drawable, kReqChangeDrawableAttributes);
    return;
  }
  if (interval < 0) {
    report_error(ds, -1, BadValue, drawable, kReqChangeDrawableAttributes);
    return;
  }
  s->swap_interval = std::min(interval, kMaxSwapInterval);
}

} // namespace pineda::glx

GLX_EXPORT void glXSwapIntervalEXT(Display* dpy, GLXDrawable drawable, int interval) {
  ApiLock api;
  if (DisplayState* ds = display_state(dpy)) set_swap_interval(ds, drawable, interval);
}
