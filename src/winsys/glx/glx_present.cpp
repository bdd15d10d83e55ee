// Moving pixels between Pineda's buffers and the X server, and reporting X errors.
//
// Windows and pixmaps render into an XImage in the visual's own pixel layout, so presenting is
// one XShmPutImage (MIT-SHM, when the server offers it and the segment attaches) or XPutImage.
#include <sys/ipc.h>
#include <sys/shm.h>

#include <cstdlib>
#include <cstring>

#include "winsys/glx/glx_internal.h"

namespace pineda::glx {

namespace {

// ---- error trapping: Xlib's error handler is per process, so traps are serialised ----
std::mutex& trap_mutex() {
  static std::mutex m;
  return m;
}
int g_trapped_code = 0;
XErrorHandler g_saved_handler = nullptr;

int trap_handler(Display*, XErrorEvent* ev) {
  if (g_trapped_code == 0) g_trapped_code = ev->error_code;
  return 0;
}

// ---- queued errors (see report_error) ----
struct PendingError {
  bool set = false;
  Display* dpy = nullptr;
  XErrorEvent event{};
};
thread_local PendingError t_pending;

// Core error codes that stand in for GLX ones when the server has no GLX extension.
int core_equivalent(int glx_code) {
  switch (glx_code) {
  case GLXBadPixmap:
    return BadPixmap;
  case GLXBadDrawable:
  case GLXBadCurrentWindow:
  case GLXBadCurrentDrawable:
  case GLXBadWindow:
  case GLXBadPbuffer:
    return BadDrawable;
  default:
    return BadValue;
  }
}

} // namespace

int trap_begin() {
  trap_mutex().lock();
  g_trapped_code = 0;
  g_saved_handler = XSetErrorHandler(trap_handler);
  return 0;
}

int trap_end(Display* dpy) {
  XSync(dpy, False);
  return trap_end_replied();
}

int trap_end_replied() {
  XSetErrorHandler(g_saved_handler);
  const int code = g_trapped_code;
  trap_mutex().unlock();
  return code;
}

void report_error(DisplayState* ds, int glx_code, int core_code, XID resource, int minor) {
  if (ds == nullptr || t_pending.set) return;
  XErrorEvent& ev = t_pending.event;
  ev = XErrorEvent{};
  ev.type = 0; // X_Error: an error, not an event
  ev.display = ds->dpy;
  ev.resourceid = resource;
  ev.serial = NextRequest(ds->dpy) - 1;
  if (glx_code >= 0)
    ev.error_code = static_cast<unsigned char>(ds->server_glx ? ds->error_base + glx_code
                                                              : core_equivalent(glx_code));
  else
    ev.error_code = static_cast<unsigned char>(core_code);
  ev.request_code = static_cast<unsigned char>(ds->server_glx ? ds->glx_opcode : 0);
  ev.minor_code = static_cast<unsigned char>(minor);
  t_pending.dpy = ds->dpy;
  t_pending.set = true;
}

void deliver_pending_error() {
  if (!t_pending.set) return;
  t_pending.set = false;
  // Xlib has no getter for the handler: swapping it out and back returns it. When the
  // application set none this is Xlib's default handler, which prints and exits, as it would
  // for an error from a server-side GLX.
  XErrorHandler handler = XSetErrorHandler(nullptr);
  XSetErrorHandler(handler);
  if (handler != nullptr) handler(t_pending.dpy, &t_pending.event);
}

XID alloc_xid(Display* dpy) {
  const XID id = XAllocID(dpy);
  // Xlib (over XCB) fetches the next id only when a request follows; two allocations in a row
  // would otherwise trip its assertion. A no-op request is buffered, not a round trip.
  XNoOp(dpy);
  return id;
}

// ---- images ----

namespace {

// One MIT-SHM image of the surface's visual; false (nothing allocated) if any step fails.
bool shm_image(Surface& s, int width, int height, XImage*& out, XShmSegmentInfo& info) {
  Display* dpy = s.ds->dpy;
  const Config& c = *s.config;
  XImage* img =
      XShmCreateImage(dpy, c.visual, static_cast<unsigned>(c.visual_depth), ZPixmap, nullptr, &info,
                      static_cast<unsigned>(width), static_cast<unsigned>(height));
  if (img == nullptr) return false;
  if (img->bits_per_pixel != 32) {
    XDestroyImage(img);
    return false;
  }
  const size_t bytes = static_cast<size_t>(img->bytes_per_line) * static_cast<size_t>(height);
  info.shmid = shmget(IPC_PRIVATE, bytes > 0 ? bytes : 1, IPC_CREAT | 0600);
  if (info.shmid < 0) {
    XDestroyImage(img);
    return false;
  }
  info.shmaddr = static_cast<char*>(shmat(info.shmid, nullptr, 0));
  if (info.shmaddr == reinterpret_cast<char*>(-1)) {
    shmctl(info.shmid, IPC_RMID, nullptr);
    XDestroyImage(img);
    return false;
  }
  img->data = info.shmaddr;
  info.readOnly = False;
  // Attaching fails asynchronously on a remote connection: wait for the verdict.
  Status attached = False;
  const int err = trap_errors(dpy, [&] { attached = XShmAttach(dpy, &info); });
  // Marked for removal now: the segment disappears once both sides detach, even on a crash.
  shmctl(info.shmid, IPC_RMID, nullptr);
  if (err != 0 || !attached) {
    shmdt(info.shmaddr);
    img->data = nullptr;
    XDestroyImage(img);
    return false;
  }
  out = img;
  return true;
}

// The segment of an image of shm_image: XShmCreateImage keeps a pointer to the Surface field
// it was created with, which stays with the image when swaps exchange `image` and `spare`.
XShmSegmentInfo& segment(XImage* img) {
  return *reinterpret_cast<XShmSegmentInfo*>(img->obdata);
}

// Frees an image of shm_image; the server has detached its segment.
void shm_free(XImage*& img) {
  if (img == nullptr) return;
  shmdt(segment(img).shmaddr);
  img->data = nullptr; // not malloc'd: XDestroyImage must not free it
  XDestroyImage(img);
  img = nullptr;
}

} // namespace

bool shm_create(Surface& s, int width, int height) {
  if (!shm_image(s, width, height, s.image, s.shm_info)) return false;
  s.shm = true;
  // Without the spare image swaps still work, waiting for the server each time.
  if (has_back_buffer(s) && !shm_image(s, width, height, s.spare, s.spare_info)) s.spare = nullptr;
  return true;
}

void shm_destroy(Surface& s) {
  if (!s.shm || s.image == nullptr) return;
  Display* dpy = s.ds->dpy;
  XShmDetach(dpy, &segment(s.image));
  if (s.spare != nullptr) XShmDetach(dpy, &segment(s.spare));
  XSync(dpy, False);
  shm_free(s.spare);
  shm_free(s.image);
  s.shm = false;
}

void present_async(Surface& s) {
  Display* dpy = s.ds->dpy;
  if (s.gc == nullptr) s.gc = XCreateGC(dpy, s.x_drawable, 0, nullptr);
  XShmPutImage(dpy, s.x_drawable, s.gc, s.image, 0, 0, 0, 0, static_cast<unsigned>(s.width),
               static_cast<unsigned>(s.height), False);
  XFlush(dpy);
}

void present(Surface& s) {
  if (s.kind == SurfaceKind::Pbuffer || s.image == nullptr || s.ds == nullptr) return;
  Display* dpy = s.ds->dpy;
  const auto w = static_cast<unsigned>(s.width), h = static_cast<unsigned>(s.height);
  // Errors are trapped: a window destroyed behind GLX's back must not end the program when
  // its last frame is flushed on release. The trap's XSync also keeps the shared segment
  // untouched until the server has read it.
  trap_errors(dpy, [&] {
    if (s.gc == nullptr) s.gc = XCreateGC(dpy, s.x_drawable, 0, nullptr);
    if (s.shm)
      XShmPutImage(dpy, s.x_drawable, s.gc, s.image, 0, 0, 0, 0, w, h, False);
    else
      XPutImage(dpy, s.x_drawable, s.gc, s.image, 0, 0, 0, 0, w, h);
  });
}

void present_front(Surface& s) {
  if (s.kind != SurfaceKind::Window || s.front.empty() || s.image == nullptr || s.ds == nullptr)
    return;
  Display* dpy = s.ds->dpy;
  const Config& c = *s.config;
  const auto w = static_cast<unsigned>(s.width), h = static_cast<unsigned>(s.height);
  // An image header over the front buffer's memory, which has the back image's layout.
  XImage* img =
      XCreateImage(dpy, c.visual, static_cast<unsigned>(c.visual_depth), ZPixmap, 0,
                   reinterpret_cast<char*>(s.front.data()), w, h, 32, s.image->bytes_per_line);
  if (img == nullptr) return;
  trap_errors(dpy, [&] {
    if (s.gc == nullptr) s.gc = XCreateGC(dpy, s.x_drawable, 0, nullptr);
    XPutImage(dpy, s.x_drawable, s.gc, img, 0, 0, 0, 0, w, h);
  });
  img->data = nullptr; // the memory is s.front's
  XDestroyImage(img);
}

namespace {

// Copies what the X drawable shows into dst_base (rows laid out as s.image).
void pull_into(Surface& s, uint8_t* dst_base) {
  Display* dpy = s.ds->dpy;
  XImage* got = nullptr;
  const int err = trap_errors(dpy, [&] {
    got = XGetImage(dpy, s.x_drawable, 0, 0, static_cast<unsigned>(s.width),
                    static_cast<unsigned>(s.height), AllPlanes, ZPixmap);
  });
  if (err != 0 || got == nullptr) {
    if (got != nullptr) XDestroyImage(got);
    return;
  }
  if (got->bits_per_pixel == 32 && got->byte_order == s.image->byte_order) {
    // Only the visual's colour bits come from X; the rest of the word is the alpha channel,
    // which a depth-24 drawable does not store, so GL's alpha survives.
    const uint32_t rgb = static_cast<uint32_t>(s.config->rgb_mask);
    uint32_t keep = ~rgb, take = rgb;
    if (s.image->byte_order != (__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__ ? LSBFirst : MSBFirst)) {
      keep = __builtin_bswap32(keep);
      take = __builtin_bswap32(take);
    }
    for (int y = 0; y < s.height; ++y) {
      auto* dst = reinterpret_cast<uint32_t*>(dst_base + y * s.image->bytes_per_line);
      const auto* src = reinterpret_cast<const uint32_t*>(got->data + y * got->bytes_per_line);
      for (int x = 0; x < s.width; ++x)
        dst[x] = (dst[x] & keep) | (src[x] & take);
    }
  }
  XDestroyImage(got);
}

} // namespace

void pull_pixmap(Surface& s) {
  if (s.kind != SurfaceKind::Pixmap || s.image == nullptr || s.ds == nullptr) return;
  pull_into(s, reinterpret_cast<uint8_t*>(s.image->data));
}

// GLX 1.4 §3.3.10: after a swap the front buffer holds what the window shows.
void pull_front(Surface& s) {
  s.front_stale = false;
  if (s.kind != SurfaceKind::Window || s.front.empty() || s.image == nullptr || s.ds == nullptr)
    return;
  pull_into(s, s.front.data());
}

// GLX_EXT_swap_control: without a real vertical retrace, swaps are paced to a virtual 60 Hz
// display: a swap with interval n > 0 happens no sooner than n periods after the previous one.
// Returns when the swap may happen; the caller sleeps until then outside the registry lock.
std::chrono::steady_clock::time_point swap_due(Surface& s) {
  using clock = std::chrono::steady_clock;
  const auto now = clock::now();
  auto due = now;
  if (s.swap_interval > 0 && s.last_swap != clock::time_point{}) {
    const auto next = s.last_swap + std::chrono::microseconds(16667) * s.swap_interval;
    if (next > now) due = next;
  }
  s.last_swap = due;
  return due;
}

} // namespace pineda::glx
