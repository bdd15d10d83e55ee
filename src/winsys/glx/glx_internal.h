// GLX implemented on the client side over Xlib. The server needs no GLX support: configs are
// derived from the screen's TrueColor visuals, Pineda renders into its own memory (an XImage in
// the window's pixel format) and presents it with XShmPutImage or XPutImage.
//
// Shared by glx_config.cpp (configs and visuals), glx_drawable.cpp (surfaces and their
// buffers), glx_present.cpp (moving pixels to and from the X server) and glx_api.cpp (the
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

namespace pineda::glx {

// One GLXFBConfig (GLX 1.4 §3.3.3, Table 3.1). Every config is RGBA, renders to windows,
// pixmaps and pbuffers, and is tied to one TrueColor visual.
struct Config {
  int id = 0; // GLX_FBCONFIG_ID
  int screen = 0;
  Visual* visual = nullptr;
  VisualID visual_id = 0;
  int visual_depth = 0; // 24 or 32
  ColorFormat format = ColorFormat::BGRA8;
  unsigned long rgb_mask = 0; // the visual's red|green|blue bits inside a 32-bit pixel
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

// A GLX drawable and the buffers Pineda renders into for it.
struct Surface {
  DisplayState* ds = nullptr;
  SurfaceKind kind = SurfaceKind::Window;
  XID id = 0;          // the GLXDrawable applications name it by
  Drawable x_drawable; // the X window or pixmap; 0 for a pbuffer
  const Config* config = nullptr;
  bool implicit = false; // an X window used directly with glXMakeCurrent
  int width = 0, height = 0;

  // Colour: an XImage in the visual's format (windows and pixmaps) or plain memory (pbuffers).
  XImage* image = nullptr;
  XShmSegmentInfo shm_info{};
  bool shm = false;
  // A double-buffered window presenting through MIT-SHM has a second image: a swap sends the
  // back image to the server without waiting and renders on into this one, so the server's
  // copy overlaps the next frame (swap_images in glx_drawable.cpp). Null without MIT-SHM.
  // Each image keeps pointing at the segment field it was created with (`shm_info` or
  // `spare_info`), whichever of `image` and `spare` it is at the moment.
  XImage* spare = nullptr;
  XShmSegmentInfo spare_info{};
  std::vector<uint8_t> memory;
  // The front colour buffer of a double-buffered window (GLX 1.4 §3.3.10), rows laid out as
  // in `image`, which is the back buffer. While `front_stale`, the front buffer's contents are
  // what the window shows (the last swap) and are fetched from it when GL next uses them; a
  // swap copies the back buffer in only when a context draws into or reads the front, so
  // back-buffer-only rendering costs no copy.
  std::vector<uint8_t> front;
  bool front_stale = true;
  std::vector<uint32_t> depth;
  std::vector<uint8_t> stencil;
  std::vector<int16_t> accum; // RGBA per pixel when the config has an accumulation buffer
  GC gc = nullptr;

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

// Run Xlib calls with errors caught instead of reported; returns the X error code (0: none).
int trap_begin();
int trap_end(Display* dpy);
template <typename F> int trap_errors(Display* dpy, F&& body) {
  trap_begin();
  body();
  return trap_end(dpy);
}
// The same for a body whose last request waits for its reply: the server has processed every
// earlier request by then, so their errors have arrived and no XSync round trip is needed.
int trap_end_replied();
template <typename F> int trap_reply_errors(F&& body) {
  trap_begin();
  body();
  return trap_end_replied();
}

// A fresh XID from the client's resource range, for GLX drawables and contexts.
XID alloc_xid(Display* dpy);

// Surface management (glx_drawable.cpp).
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

// Presentation (glx_present.cpp).
void present(Surface& s);       // our colour buffer -> window or pixmap
void present_async(Surface& s); // the same through MIT-SHM, without waiting for the server
void pull_pixmap(Surface& s);   // pixmap contents -> our colour buffer (X rendering seen by GL)
void present_front(Surface& s); // a double-buffered window's front buffer -> window
void pull_front(Surface& s);    // window contents -> a double-buffered window's front buffer
// Whether ctx draws into or reads the front buffer of its double-buffered window.
bool uses_front(const GlxContext& ctx);
bool draws_front(const GlxContext& ctx); // draws into it (shown at glFlush)
bool shm_create(Surface& s, int width, int height);
void shm_destroy(Surface& s);
// When the next swap of `s` may happen (GLX_EXT_swap_control pacing); records it.
std::chrono::steady_clock::time_point swap_due(Surface& s);

} // namespace pineda::glx
