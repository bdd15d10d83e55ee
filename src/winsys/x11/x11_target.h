// The X11 presentation path GLX and EGL share: Pineda renders a window or pixmap into an
// XImage in the visual's own pixel layout and moves it to the server with XShmPutImage
// (MIT-SHM) or XPutImage; X rendering into a pixmap is read back with XGetImage.
#pragma once

#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <X11/extensions/XShm.h>

#include <cstdint>
#include <vector>

#include "framebuffer/framebuffer.h"

namespace pineda::x11 {

// The pixel layout of one TrueColor visual with 8-bit channels stored in 32-bit pixels.
struct Format {
  Visual* visual = nullptr;
  VisualID visual_id = 0;
  int depth = 0; // 24 or 32
  ColorFormat color = ColorFormat::BGRA8;
  unsigned long rgb_mask = 0; // the visual's red|green|blue bits inside a 32-bit pixel
};

// Whether Pineda can render into drawables of this visual: 8-bit channels that Pineda's colour
// formats name, in 32-bit pixels. Sets *out when it can.
bool usable_visual(Display* dpy, const XVisualInfo& v, Format* out);

// A window or pixmap and the images Pineda renders into for it.
struct Target {
  Display* dpy = nullptr; // null once the surface is orphaned (connection closed)
  Drawable x_drawable = 0;
  Format format;
  bool is_window = true;
  // A double-buffered window: `image` is the back buffer; `front` holds the front buffer
  // (GLX 1.4 §3.3.10) in the same row layout. While `front_stale`, the front buffer's contents
  // are what the window shows and are fetched from it when GL next uses them.
  bool double_buffered = false;
  int width = 0, height = 0;

  XImage* image = nullptr;
  XShmSegmentInfo shm_info{};
  bool shm = false;
  // With MIT-SHM a double-buffered window has a second image: a swap sends the back image to
  // the server without waiting and rendering goes on in this one (swap_images). Each image
  // keeps pointing at the segment field it was created with (`shm_info` or `spare_info`).
  XImage* spare = nullptr;
  XShmSegmentInfo spare_info{};
  std::vector<uint8_t> front;
  bool front_stale = true;
  GC gc = nullptr;
};

// (Re)creates the images at the new size (MIT-SHM for windows when `use_shm`), and the front
// buffer of a double-buffered window. False (nothing allocated) if it cannot.
bool allocate_images(Target& t, int width, int height, bool use_shm);
// Frees the images and the GC (the drawable itself belongs to the application).
void release_images(Target& t);

// Geometry of an X drawable, errors trapped; false if it is not one. `screen` (optional) is
// the number of the screen whose root it is on, or -1.
bool geometry(Display* dpy, Drawable d, int* w, int* h, int* depth, int* screen);

void present(Target& t);       // the colour image -> window or pixmap, waiting for the server
void present_async(Target& t); // the same through MIT-SHM, without waiting
void present_front(Target& t); // a double-buffered window's front buffer -> window
void pull_pixmap(Target& t);   // pixmap contents -> the colour image (X rendering seen by GL)
void pull_front(Target& t);    // window contents -> a double-buffered window's front buffer
// A double-buffered window's swap with a spare image: presents without waiting for the server
// and renders on into the spare (its contents copied, as Mesa keeps the back buffer). Returns
// false if it cannot (no spare image, window gone). The window's size is returned; when it
// differs from the target's, nothing was swapped and the caller reallocates its buffers.
bool swap_images(Target& t, int* new_width, int* new_height);
// Copies the colour image into another pixmap of the same depth (eglCopyBuffers).
bool copy_to_pixmap(Target& t, Pixmap pixmap);

// The colour buffers of the target in Framebuffer terms: `color` is the image (bottom row
// first, negative stride), `front` the front buffer of a double-buffered window or nullptr.
void describe_color(Target& t, uint8_t** color, ptrdiff_t* stride, uint8_t** front);

// Run Xlib calls with errors caught instead of reported; returns the X error code (0: none).
// Xlib's error handler is per process, so traps are serialised.
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

// MIT-SHM present and not disabled by PINEDA_GLX_NO_SHM.
bool shm_available(Display* dpy);

} // namespace pineda::x11
