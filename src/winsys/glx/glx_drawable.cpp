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

void release_image(Surface& s) {
  if (s.image == nullptr) return;
  if (s.shm) {
    shm_destroy(s);
  } else {
    XDestroyImage(s.image); // frees the calloc'd pixels too
    s.image = nullptr;
  }
}

// Geometry of an X drawable, with errors trapped; false if it is not a drawable.
bool geometry(Display* dpy, Drawable d, int* w, int* h, int* depth, int* screen_root_ok) {
  Window root = 0;
  int x = 0, y = 0;
  unsigned int uw = 0, uh = 0, border = 0, udepth = 0;
  Status ok = 0;
  const int err = trap_reply_errors(
      [&] { ok = XGetGeometry(dpy, d, &root, &x, &y, &uw, &uh, &border, &udepth); });
  if (err != 0 || !ok) return false;
  *w = static_cast<int>(uw);
  *h = static_cast<int>(uh);
  if (depth != nullptr) *depth = static_cast<int>(udepth);
  if (screen_root_ok != nullptr) {
    *screen_root_ok = -1;
    for (int i = 0; i < ScreenCount(dpy); ++i)
      if (RootWindow(dpy, i) == root) *screen_root_ok = i;
  }
  return true;
}

// A new surface of `kind` for an X drawable (or a pbuffer when `x` is 0) with its buffers.
std::shared_ptr<Surface> make_surface(DisplayState* ds, SurfaceKind kind, Drawable x,
                                      const Config* c, int w, int h) {
  auto s = std::make_shared<Surface>();
  s->ds = ds;
  s->kind = kind;
  s->x_drawable = x;
  s->config = c;
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
  if (depth != c->visual_depth || screen != c->screen) {
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

void orphan_surface(Surface& s) {
  if (s.ds == nullptr) return;
  for (GlxContext* ctx : s.bound) {
    ctx->fb = Framebuffer{};
    mark_dirty(ctx, kDirtyFramebuffer);
  }
  release_image(s);
  if (s.gc != nullptr) XFreeGC(s.ds->dpy, s.gc);
  s.gc = nullptr;
  s.ds = nullptr;
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
    } else {
      release_image(s);
      const bool shm = s.kind == SurfaceKind::Window && s.ds->shm && shm_create(s, width, height);
      if (!shm) {
        const Config& c = *s.config;
        XImage* img = XCreateImage(s.ds->dpy, c.visual, static_cast<unsigned>(c.visual_depth),
                                   ZPixmap, 0, nullptr, static_cast<unsigned>(width),
                                   static_cast<unsigned>(height), 32, 0);
        if (img == nullptr) return false;
        const size_t bytes = static_cast<size_t>(img->bytes_per_line) * static_cast<size_t>(height);
        img->data = static_cast<char*>(std::calloc(std::max<size_t>(bytes, 1), 1));
        if (img->bits_per_pixel != 32 || img->data == nullptr) {
          XDestroyImage(img);
          return false;
        }
        s.image = img;
      }
      // A resize leaves the front buffer undefined: it is again what the window shows.
      if (has_back_buffer(s))
        s.front.assign(static_cast<size_t>(s.image->bytes_per_line) * static_cast<size_t>(height),
                       0);
      s.front_stale = true;
    }
    s.depth.assign(s.config->depth_bits > 0 ? pixels : 0, 0);
    s.stencil.assign(s.config->stencil_bits > 0 ? pixels : 0, 0);
    s.accum.assign(s.config->accum_bits > 0 ? 4 * pixels : 0, 0);
  } catch (const std::bad_alloc&) {
    return false;
  }
  s.width = width;
  s.height = height;
  return true;
}

bool refresh_size(Surface& s) {
  if (s.kind == SurfaceKind::Pbuffer) return true;
  if (s.ds == nullptr) return false;
  int w = 0, h = 0;
  if (!geometry(s.ds->dpy, s.x_drawable, &w, &h, nullptr, nullptr)) return false;
  if (w == s.width && h == s.height && (s.image != nullptr || w == 0)) return true;
  if (!allocate_buffers(s, w, h)) return false;
  // Every context drawing here sees the new buffers (a resize while another thread renders
  // into the same drawable is not synchronised).
  for (GlxContext* ctx : s.bound)
    attach(ctx, s);
  return true;
}

bool swap_images(Surface& s) {
  if (s.kind != SurfaceKind::Window || !s.shm || s.spare == nullptr || s.ds == nullptr)
    return false;
  Display* dpy = s.ds->dpy;
  int w = 0, h = 0;
  // One round trip per swap. Its reply also tells that the server has finished reading the
  // spare image, sent by the previous swap: requests are processed in order.
  if (!geometry(dpy, s.x_drawable, &w, &h, nullptr, nullptr)) return false;
  present_async(s);
  if (w != s.width || h != s.height) {
    // The image just sent must outlive the server's read of it.
    XSync(dpy, False);
    if (!allocate_buffers(s, w, h)) return true;
    for (GlxContext* ctx : s.bound)
      attach(ctx, s);
    return true;
  }
  // GLX 1.4 §3.3.10 leaves the back buffer undefined after a swap; it is kept as it was, as
  // Mesa does, for programs that redraw only part of each frame. Both copies read the image
  // the server is reading.
  const size_t bytes = static_cast<size_t>(s.image->bytes_per_line) * static_cast<size_t>(s.height);
  std::memcpy(s.spare->data, s.image->data, bytes);
  std::swap(s.image, s.spare);
  for (GlxContext* ctx : s.bound)
    attach(ctx, s);
  return true;
}

void attach(GlxContext* ctx, Surface& s) {
  Framebuffer& fb = ctx->fb;
  fb.width = s.width;
  fb.height = s.height;
  fb.color_format = s.config->format;
  fb.alpha_bits = s.config->alpha_bits;
  if (s.kind == SurfaceKind::Pbuffer) {
    fb.color = s.memory.data();
    fb.color_stride = static_cast<ptrdiff_t>(s.width) * 4;
  } else {
    // X images are stored top row first; GL's row 0 is the bottom one.
    const ptrdiff_t row = s.image->bytes_per_line;
    fb.color =
        reinterpret_cast<uint8_t*>(s.image->data) + (s.height > 0 ? (s.height - 1) * row : 0);
    fb.color_stride = -row;
  }
  fb.depth_bits = s.config->depth_bits;
  fb.depth = s.depth.empty() ? nullptr : s.depth.data();
  fb.stencil_bits = s.config->stencil_bits;
  fb.stencil = s.stencil.empty() ? nullptr : s.stencil.data();
  fb.accum_bits = s.config->accum_bits;
  fb.accum = s.accum.empty() ? nullptr : s.accum.data();
  // GL 2.1 table 4.4: a double-buffered window has a front and a back buffer (`image` is the
  // back one, presented by swaps); a pbuffer only its back buffer (it is never shown); a
  // single-buffered window or a pixmap its front buffer (§3.3.5: swaps are ignored).
  fb.front_color = fb.back_color = fb.color_also = fb.read_color = nullptr;
  if (s.kind == SurfaceKind::Window && has_back_buffer(s) && !s.front.empty()) {
    ctx->color_buffers = kColorBufferFrontLeft | kColorBufferBackLeft;
    fb.back_color = fb.color;
    fb.front_color = s.front.data() + (fb.color - reinterpret_cast<uint8_t*>(s.image->data));
    // The registry lock is held here, so the hook (which takes it) is not run; the front
    // buffer is fetched directly instead.
    auto* const hook = ctx->front_selected;
    ctx->front_selected = nullptr;
    select_color_buffers(ctx);
    ctx->front_selected = hook;
    if (s.front_stale && uses_front(*ctx)) pull_front(s);
  } else {
    ctx->color_buffers = has_back_buffer(s) ? kColorBufferBackLeft : kColorBufferFrontLeft;
  }
  mark_dirty(ctx, kDirtyFramebuffer);
}

bool draws_front(const GlxContext& ctx) {
  const Framebuffer& fb = ctx.fb;
  return fb.front_color != nullptr &&
         (fb.color == fb.front_color || fb.color_also == fb.front_color);
}

bool uses_front(const GlxContext& ctx) {
  const Framebuffer& fb = ctx.fb;
  return draws_front(ctx) || (fb.front_color != nullptr && fb.read_color == fb.front_color);
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
  if (wa.visual == nullptr || XVisualIDFromVisual(wa.visual) != c->visual_id ||
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
