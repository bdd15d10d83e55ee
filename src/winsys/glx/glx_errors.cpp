// Reporting GLX errors the way a server would (GLX 1.4 §3.1), and XIDs for GLX resources.
#include "winsys/common/swap_pacing.h"
#include "winsys/glx/glx_internal.h"

// _XAllocIDs, LockDisplay and UnlockDisplay; this header also defines min and max macros.
#include <X11/Xlibint.h>
#undef min
#undef max

namespace pineda::glx {

namespace {

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
  // XAllocID hands out Xlib's one prefetched id, which Xlib (over XCB) replaces only after a
  // request of its own; an XAllocID from outside Xlib followed by another allocation (the
  // application's XCreateWindow, or ours) trips its assertion, as SDL2 programs showed.
  // _XAllocIDs asks XCB for fresh ids and leaves the prefetched one alone; it expects the
  // display locked.
  XID id = 0;
  LockDisplay(dpy);
  _XAllocIDs(dpy, &id, 1);
  UnlockDisplay(dpy);
  return id;
}

std::chrono::steady_clock::time_point swap_due(Surface& s) {
  return winsys::swap_due(s.swap_interval, s.last_swap);
}

} // namespace pineda::glx
