// Moving pixels between Pineda's buffers and the X server (GLX and EGL on X11).
//
// Windows and pixmaps render into an XImage in the visual's own pixel layout, so presenting is
// one XShmPutImage (MIT-SHM, when the server offers it and the segment attaches) or XPutImage.
#include "winsys/x11/x11_target.h"

#include <sys/ipc.h>
#include <sys/shm.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <new>

namespace pineda::x11 {

namespace {

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

// Whether images of this depth are stored 32 bits per pixel (Pineda writes 4-byte pixels).
bool depth_is_32bpp(Display* dpy, int depth) {
  int n = 0;
  XPixmapFormatValues* formats = XListPixmapFormats(dpy, &n);
  bool ok = false;
  for (int i = 0; i < n; ++i)
    if (formats[i].depth == depth) ok = formats[i].bits_per_pixel == 32;
  if (formats != nullptr) XFree(formats);
  return ok;
}

// One MIT-SHM image of the target's visual; false (nothing allocated) if any step fails.
bool shm_image(Target& t, int width, int height, XImage*& out, XShmSegmentInfo& info) {
  Display* dpy = t.dpy;
  XImage* img =
      XShmCreateImage(dpy, t.format.visual, static_cast<unsigned>(t.format.depth), ZPixmap, nullptr,
                      &info, static_cast<unsigned>(width), static_cast<unsigned>(height));
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

// The segment of an image of shm_image: XShmCreateImage keeps a pointer to the Target field
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

bool shm_create(Target& t, int width, int height) {
  if (!shm_image(t, width, height, t.image, t.shm_info)) return false;
  t.shm = true;
  // Without the spare image swaps still work, waiting for the server each time.
  if (t.double_buffered && !shm_image(t, width, height, t.spare, t.spare_info)) t.spare = nullptr;
  return true;
}

void free_images(Target& t) {
  if (t.image == nullptr) return;
  if (t.shm) {
    Display* dpy = t.dpy;
    XShmDetach(dpy, &segment(t.image));
    if (t.spare != nullptr) XShmDetach(dpy, &segment(t.spare));
    XSync(dpy, False);
    shm_free(t.spare);
    shm_free(t.image);
    t.shm = false;
  } else {
    XDestroyImage(t.image); // frees the calloc'd pixels too
    t.image = nullptr;
  }
}

// Copies what the X drawable shows into dst_base (rows laid out as t.image).
void pull_into(Target& t, uint8_t* dst_base) {
  Display* dpy = t.dpy;
  XImage* got = nullptr;
  const int err = trap_errors(dpy, [&] {
    got = XGetImage(dpy, t.x_drawable, 0, 0, static_cast<unsigned>(t.width),
                    static_cast<unsigned>(t.height), AllPlanes, ZPixmap);
  });
  if (err != 0 || got == nullptr) {
    if (got != nullptr) XDestroyImage(got);
    return;
  }
  if (got->bits_per_pixel == 32 && got->byte_order == t.image->byte_order) {
    // Only the visual's colour bits come from X; the rest of the word is the alpha channel,
    // which a depth-24 drawable does not store, so GL's alpha survives.
    const uint32_t rgb = static_cast<uint32_t>(t.format.rgb_mask);
    uint32_t keep = ~rgb, take = rgb;
    if (t.image->byte_order != (__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__ ? LSBFirst : MSBFirst)) {
      keep = __builtin_bswap32(keep);
      take = __builtin_bswap32(take);
    }
    for (int y = 0; y < t.height; ++y) {
      auto* dst = reinterpret_cast<uint32_t*>(dst_base + y * t.image->bytes_per_line);
      const auto* src = reinterpret_cast<const uint32_t*>(got->data + y * got->bytes_per_line);
      for (int x = 0; x < t.width; ++x)
        dst[x] = (dst[x] & keep) | (src[x] & take);
    }
  }
  XDestroyImage(got);
}

void put(Target& t, Drawable to, XImage* img) {
  const auto w = static_cast<unsigned>(t.width), h = static_cast<unsigned>(t.height);
  if (t.gc == nullptr) t.gc = XCreateGC(t.dpy, t.x_drawable, 0, nullptr);
  if (t.shm && img == t.image)
    XShmPutImage(t.dpy, to, t.gc, img, 0, 0, 0, 0, w, h, False);
  else
    XPutImage(t.dpy, to, t.gc, img, 0, 0, 0, 0, w, h);
}

} // namespace

bool usable_visual(Display* dpy, const XVisualInfo& v, Format* out) {
  if (v.c_class != TrueColor || (v.depth != 24 && v.depth != 32)) return false;
  const bool lsb = ImageByteOrder(dpy) == LSBFirst;
  ColorFormat color;
  if (v.red_mask == 0xff0000 && v.green_mask == 0xff00 && v.blue_mask == 0xff)
    color = lsb ? ColorFormat::BGRA8 : ColorFormat::ARGB8;
  else if (v.red_mask == 0xff && v.green_mask == 0xff00 && v.blue_mask == 0xff0000 && lsb)
    color = ColorFormat::RGBA8;
  else
    return false;
  if (!depth_is_32bpp(dpy, v.depth)) return false;
  out->visual = v.visual;
  out->visual_id = v.visualid;
  out->depth = v.depth;
  out->color = color;
  out->rgb_mask = v.red_mask | v.green_mask | v.blue_mask;
  return true;
}

bool allocate_images(Target& t, int width, int height, bool use_shm) {
  free_images(t);
  const bool shm = use_shm && t.is_window && shm_create(t, width, height);
  if (!shm) {
    XImage* img =
        XCreateImage(t.dpy, t.format.visual, static_cast<unsigned>(t.format.depth), ZPixmap, 0,
                     nullptr, static_cast<unsigned>(width), static_cast<unsigned>(height), 32, 0);
    if (img == nullptr) return false;
    const size_t bytes = static_cast<size_t>(img->bytes_per_line) * static_cast<size_t>(height);
    img->data = static_cast<char*>(std::calloc(std::max<size_t>(bytes, 1), 1));
    if (img->bits_per_pixel != 32 || img->data == nullptr) {
      XDestroyImage(img);
      return false;
    }
    t.image = img;
  }
  try {
    // A resize leaves the front buffer undefined: it is again what the window shows.
    if (t.double_buffered && t.is_window)
      t.front.assign(static_cast<size_t>(t.image->bytes_per_line) * static_cast<size_t>(height), 0);
  } catch (const std::bad_alloc&) {
    free_images(t);
    return false;
  }
  t.front_stale = true;
  t.width = width;
  t.height = height;
  return true;
}

void release_images(Target& t) {
  if (t.dpy == nullptr) return;
  free_images(t);
  if (t.gc != nullptr) XFreeGC(t.dpy, t.gc);
  t.gc = nullptr;
}

bool geometry(Display* dpy, Drawable d, int* w, int* h, int* depth, int* screen) {
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
  if (screen != nullptr) {
    *screen = -1;
    for (int i = 0; i < ScreenCount(dpy); ++i)
      if (RootWindow(dpy, i) == root) *screen = i;
  }
  return true;
}

void present_async(Target& t) {
  if (t.gc == nullptr) t.gc = XCreateGC(t.dpy, t.x_drawable, 0, nullptr);
  XShmPutImage(t.dpy, t.x_drawable, t.gc, t.image, 0, 0, 0, 0, static_cast<unsigned>(t.width),
               static_cast<unsigned>(t.height), False);
  XFlush(t.dpy);
}

void present(Target& t) {
  if (t.image == nullptr || t.dpy == nullptr) return;
  // Errors are trapped: a window destroyed behind the application's back must not end the
  // program when its last frame is flushed on release. The trap's XSync also keeps the shared
  // segment untouched until the server has read it.
  trap_errors(t.dpy, [&] { put(t, t.x_drawable, t.image); });
}

bool copy_to_pixmap(Target& t, Pixmap pixmap) {
  if (t.image == nullptr || t.dpy == nullptr) return false;
  XImage* img = t.image;
  // A plain image header over the same pixels: XShmPutImage works on the target's own
  // drawable only in this path's bookkeeping, so the copy goes through XPutImage.
  XImage* plain = XCreateImage(t.dpy, t.format.visual, static_cast<unsigned>(t.format.depth),
                               ZPixmap, 0, img->data, static_cast<unsigned>(t.width),
                               static_cast<unsigned>(t.height), 32, img->bytes_per_line);
  if (plain == nullptr) return false;
  const int err = trap_errors(t.dpy, [&] { put(t, pixmap, plain); });
  plain->data = nullptr;
  XDestroyImage(plain);
  return err == 0;
}

void present_front(Target& t) {
  if (!t.is_window || t.front.empty() || t.image == nullptr || t.dpy == nullptr) return;
  const auto w = static_cast<unsigned>(t.width), h = static_cast<unsigned>(t.height);
  // An image header over the front buffer's memory, which has the back image's layout.
  XImage* img =
      XCreateImage(t.dpy, t.format.visual, static_cast<unsigned>(t.format.depth), ZPixmap, 0,
                   reinterpret_cast<char*>(t.front.data()), w, h, 32, t.image->bytes_per_line);
  if (img == nullptr) return;
  trap_errors(t.dpy, [&] { put(t, t.x_drawable, img); });
  img->data = nullptr; // the memory is t.front's
  XDestroyImage(img);
}

void pull_pixmap(Target& t) {
  if (t.is_window || t.image == nullptr || t.dpy == nullptr) return;
  pull_into(t, reinterpret_cast<uint8_t*>(t.image->data));
}

// GLX 1.4 §3.3.10: after a swap the front buffer holds what the window shows.
void pull_front(Target& t) {
  t.front_stale = false;
  if (!t.is_window || t.front.empty() || t.image == nullptr || t.dpy == nullptr) return;
  pull_into(t, t.front.data());
}

bool swap_images(Target& t, int* new_width, int* new_height) {
  if (!t.is_window || !t.shm || t.spare == nullptr || t.dpy == nullptr) return false;
  Display* dpy = t.dpy;
  int w = 0, h = 0;
  // One round trip per swap. Its reply also tells that the server has finished reading the
  // spare image, sent by the previous swap: requests are processed in order.
  if (!geometry(dpy, t.x_drawable, &w, &h, nullptr, nullptr)) return false;
  present_async(t);
  *new_width = w;
  *new_height = h;
  if (w != t.width || h != t.height) {
    // The image just sent must outlive the server's read of it; the caller reallocates.
    XSync(dpy, False);
    return true;
  }
  // The back buffer is left undefined after a swap (GLX 1.4 §3.3.10, EGL 1.5 §3.10.1.1); it
  // is kept as it was, as Mesa does, for programs that redraw only part of each frame. Both
  // copies read the image the server is reading.
  const size_t bytes = static_cast<size_t>(t.image->bytes_per_line) * static_cast<size_t>(t.height);
  std::memcpy(t.spare->data, t.image->data, bytes);
  std::swap(t.image, t.spare);
  return true;
}

void describe_color(Target& t, uint8_t** color, ptrdiff_t* stride, uint8_t** front) {
  // X images are stored top row first; GL's row 0 is the bottom one.
  const ptrdiff_t row = t.image->bytes_per_line;
  const ptrdiff_t last = t.height > 0 ? (t.height - 1) * row : 0;
  *color = reinterpret_cast<uint8_t*>(t.image->data) + last;
  *stride = -row;
  *front = t.is_window && t.double_buffered && !t.front.empty() ? t.front.data() + last : nullptr;
}

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

bool shm_available(Display* dpy) {
  const char* no_shm = std::getenv("PINEDA_GLX_NO_SHM");
  return XShmQueryExtension(dpy) && !(no_shm != nullptr && no_shm[0] != '\0' && no_shm[0] != '0');
}

} // namespace pineda::x11
