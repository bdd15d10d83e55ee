// GLX implemented on the client side over Xlib. The server needs no GLX support: configs are
// derived from the screen's TrueColor visuals, Pineda renders into its own memory (an XImage in
// the window's pixel format) and presents it with XShmPutImage or XPutImage.
//
// Shared by glx_config.cpp (configs and visuals), glx_drawable.cpp (surfaces and their
// buffers), glx_errors.cpp (X errors as a server reports them) and glx_api.cpp (the
// exported entry points, contexts and the current state).
#pragma once

#include <GL/glx.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <X11/extensions/XShm.h>

#include <chrono>
#include <memory>
#include <mutex>
#include <thread>
#include <unordered_map>
#include <vector>

#include "state/context.h"
#include "winsys/common/surface_binding.h"
#include "winsys/x11/x11_target.h"

namespace pineda::glx {

// One GLXFBConfig (GLX 1.4 §3.3.3, Table 3.1). Every config is RGBA, renders to windows,
// pixmaps and pbuffers, and is tied to one TrueColor visual.
struct Config {
  int id = 0; // GLX_FBCONFIG_ID
  int screen = 0;
  x11::Format x; // the visual: Visual, id, depth, Pineda's colour format, colour bits
  bool double_buffer = false;
  int alpha_bits = 0;
  int depth_bits = 0;
  int stencil_bits = 0;
  int accum_bits = 0; // 0 or 16: signed 16 bits per channel, as Mesa gives (GL 2.1 §4.2.4)
};

struct Surface;

// What Pineda knows about one Display connection. Dropped when the display is closed.
struct DisplayState {
  Display* dpy = nullptr;
  // The server's GLX extension, when it has one: its error base numbers GLX errors.
  bool server_glx = false;
  int glx_opcode = 0;
  int error_base = 0;
  int event_base = 0;
  bool shm = false; // MIT-SHM present and not disabled by PINEDA_GLX_NO_SHM
  std::vector<std::unique_ptr<Config>> configs;
  // glXChooseVisual's last choice for each visual (GLX 1.4 §3.4.1: the attributes a visual
  // reports are those of the config chosen for it; before any choice, the first config).
  std::unordered_map<VisualID, const Config*> visual_choice;
  std::unordered_map<XID, std::shared_ptr<Surface>> surfaces;
};

enum class SurfaceKind { Window, Pixmap, Pbuffer };

struct GlxContext;

// A GLX drawable and the buffers Pineda renders into for it. Windows and pixmaps render into
// the X11 images of x11::Target (shared with EGL); a pbuffer into `memory`.
struct Surface : x11::Target {
  DisplayState* ds = nullptr;
  SurfaceKind kind = SurfaceKind::Window;
  XID id = 0; // the GLXDrawable applications name it by
  const Config* config = nullptr;
  bool implicit = false; // an X window used directly with glXMakeCurrent

  std::vector<uint8_t> memory; // a pbuffer's colour buffer
  std::vector<uint32_t> depth;
  std::vector<uint8_t> stencil;
  std::vector<int16_t> accum; // RGBA per pixel when the config has an accumulation buffer

  // Pbuffer creation attributes (GLX 1.4 §3.3.5).
  bool preserved = true;
  bool largest = false;
  unsigned long event_mask = 0; // glXSelectEvent (§3.3.8)
  // GLX_EXT_swap_control: swaps wait for this many periods of a virtual 60 Hz display.
  int swap_interval = 1;
  std::chrono::steady_clock::time_point last_swap{};

  std::vector<GlxContext*> bound; // contexts current on it (as draw drawable)

  ~Surface();
};

// A GLX rendering context: the GL state plus GLX bookkeeping (GLX 1.4 §3.3.7).
struct GlxContext final : Context {
  GlxContext() = default;
  // A context in the share group of `objects` (glXCreateContext's share list).
  explicit GlxContext(std::shared_ptr<SharedObjects> objects) : Context(std::move(objects)) {}
  DisplayState* ds = nullptr;
  const Config* config = nullptr;
  XID id = 0; // GLX_CONTEXT_ID / glXQueryContext
  int render_type = GLX_RGBA_TYPE;
  bool is_current = false;
  std::thread::id thread{};
  bool destroy_pending = false; // glXDestroyContext while current: freed on release
  std::shared_ptr<Surface> draw, read;
  GLXDrawable draw_id = 0, read_id = 0;
};

// The lock around all GLX bookkeeping; Xlib calls made under it are the application's display.
std::mutex& registry_mutex();

// Display state, created on first use (requires registry_mutex held). nullptr for a null dpy.
DisplayState* display_state(Display* dpy);
// The config behind a GLXFBConfig handle, or nullptr if it is not one of dpy's.
const Config* find_config(DisplayState* ds, GLXFBConfig handle);
// The config a visual stands for (glXGetConfig, glXCreateContext), or nullptr.
const Config* config_for_visual(DisplayState* ds, const XVisualInfo* vis);
// glXGetFBConfigAttrib's answer; false for an unknown attribute.
bool config_attrib(const Config& c, int attribute, int* value);

// Queue an X protocol error the way a server would report it (GLX 1.4 §3.1: errors arrive
// through the Xlib error handler). `glx_code` is a GLXBad* number (>= 0) or -1 to report the
// core X error `core_code`. The handler runs later, in deliver_pending_error, outside the lock.
void report_error(DisplayState* ds, int glx_code, int core_code, XID resource, int minor);
void deliver_pending_error();

// The registry lock of one GLX call; on leaving the call it unlocks and then runs the error
// handler for an error the call queued (handlers may call Xlib or exit).
struct ApiLock {
  std::unique_lock<std::mutex> lock{registry_mutex()};
  ApiLock() = default;
  ApiLock(const ApiLock&) = delete;
  ApiLock& operator=(const ApiLock&) = delete;
  ~ApiLock() {
    lock.unlock();
    deliver_pending_error();
  }
};

// This thread's current GLX context (nullptr when GL calls go elsewhere or nowhere) and the
// display it was made current on (glx_api.cpp).
GlxContext* current_binding(Display** dpy);

// GLX request numbers (glxproto), used as the minor opcode of reported errors.
enum GlxRequest : int {
  kReqCreateContext = 3,
  kReqDestroyContext = 4,
  kReqMakeCurrent = 5,
  kReqIsDirect = 6,
  kReqCopyContext = 10,
  kReqSwapBuffers = 11,
  kReqUseXFont = 12,
  kReqCreateGLXPixmap = 13,
  kReqDestroyGLXPixmap = 15,
  kReqCreatePixmap = 22,
  kReqDestroyPixmap = 23,
  kReqCreateNewContext = 24,
  kReqQueryContext = 25,
  kReqMakeContextCurrent = 26,
  kReqCreatePbuffer = 27,
  kReqDestroyPbuffer = 28,
  kReqGetDrawableAttributes = 29,
  kReqChangeDrawableAttributes = 30,
  kReqCreateWindow = 31,
  kReqDestroyWindow = 32,
  kReqCreateContextAttribsARB = 34,
};

using x11::trap_errors;
using x11::trap_reply_errors;

// A fresh XID from the client's resource range, for GLX drawables and contexts.
XID alloc_xid(Display* dpy);

// Surface management (glx_drawable.cpp).
// Sets up a new surface of `kind` on X drawable `x` (0 for a pbuffer) with config `c`.
void init_surface(Surface& s, DisplayState* ds, SurfaceKind kind, Drawable x, const Config* c);
std::shared_ptr<Surface> find_surface(DisplayState* ds, XID id);
// The display is closing: free the surface's X resources now and detach it from the display
// (a context may still hold it; its buffers are gone).
void orphan_surface(Surface& s);
// (Re)allocate the colour, depth and stencil buffers for the surface's current size.
bool allocate_buffers(Surface& s, int width, int height);
// Re-read the size of a window or pixmap and resize; false if the drawable is gone.
bool refresh_size(Surface& s);
// glXSwapBuffers of a double-buffered window with a spare image: presents without waiting
// for the server and renders on into the spare. False if it cannot (no spare image, or the
// window is gone); the caller then presents and waits.
bool swap_images(Surface& s);
// Describe the surface's buffers in a context's Framebuffer.
void attach(GlxContext* ctx, Surface& s);
// Whether GL renders into a back buffer of the surface (presented by glXSwapBuffers).
bool has_back_buffer(const Surface& s);

// GLX_EXT_swap_control's interval of a drawable (glx_drawable.cpp); reports errors.
void set_swap_interval(DisplayState* ds, GLXDrawable drawable, int interval);

// Presentation (x11_target.h) of a surface that is a window or a pixmap.
inline void present(Surface& s) {
  if (s.kind != SurfaceKind::Pbuffer) x11::present(s);
}
// Whether ctx draws into or reads the front buffer of its double-buffered window.
inline bool uses_front(const GlxContext& ctx) {
  return winsys::uses_front(&ctx);
}
inline bool draws_front(const GlxContext& ctx) {
  return winsys::draws_front(&ctx);
}
// When the next swap of `s` may happen (GLX_EXT_swap_control pacing); records it.
std::chrono::steady_clock::time_point swap_due(Surface& s);

} // namespace pineda::glx
