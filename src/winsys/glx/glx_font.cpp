// glXUseXFont (GLX 1.4 §3.3.11): display lists of glBitmap calls made from the glyphs of an X
// font. Each glyph is drawn by the X server into a 1-bit pixmap and read back with XGetImage,
// so the bitmaps are exactly what XDrawString draws.
#include <GL/gl.h>

#include <algorithm>
#include <vector>

#include "dispatch.h"
#include "winsys/glx/glx_internal.h"

#define GLX_EXPORT extern "C" __attribute__((visibility("default")))

namespace pineda::glx {

namespace {

// One glyph's list: a glBitmap, or nothing for a glyph the font does not define.
struct Glyph {
  bool defined = false;
  int width = 0, height = 0;
  float xorig = 0, yorig = 0, xmove = 0;
  std::vector<GLubyte> bits; // rows bottom to top, MSB first, each row padded to a byte
};

// The metrics of character `c`, or nullptr when the font has no such glyph (outside its
// ranges, or all-zero metrics, which X uses for nonexistent characters).
const XCharStruct* char_metrics(const XFontStruct* fs, unsigned c) {
  const unsigned byte1 = c >> 8, byte2 = c & 0xffu;
  if (byte1 < fs->min_byte1 || byte1 > fs->max_byte1 || byte2 < fs->min_char_or_byte2 ||
      byte2 > fs->max_char_or_byte2)
    return nullptr;
  if (fs->per_char == nullptr) return &fs->max_bounds; // every glyph has the same metrics
  const unsigned columns = fs->max_char_or_byte2 - fs->min_char_or_byte2 + 1;
  const XCharStruct* m =
      &fs->per_char[(byte1 - fs->min_byte1) * columns + (byte2 - fs->min_char_or_byte2)];
  const bool empty = m->width == 0 && m->lbearing == 0 && m->rbearing == 0 && m->ascent == 0 &&
                     m->descent == 0 && m->attributes == 0;
  return empty ? nullptr : m;
}

// §3.3.11: width rbearing-lbearing, height ascent+descent, xorig -lbearing, yorig descent,
// xmove the width metric, ymove zero; the bits are what the server draws for the glyph.
Glyph render_glyph(Display* dpy, Drawable root, Font font, const XFontStruct* fs, unsigned c) {
  Glyph g;
  const XCharStruct* m = char_metrics(fs, c);
  if (m == nullptr) return g;
  g.defined = true;
  g.width = std::max(0, m->rbearing - m->lbearing);
  g.height = std::max(0, m->ascent + m->descent);
  g.xorig = static_cast<float>(-m->lbearing);
  g.yorig = static_cast<float>(m->descent);
  g.xmove = static_cast<float>(m->width);
  if (g.width == 0 || g.height == 0) {
    g.width = g.height = 0;
    return g;
  }
  const auto w = static_cast<unsigned>(g.width), h = static_cast<unsigned>(g.height);
  const Pixmap pix = XCreatePixmap(dpy, root, w, h, 1);
  XGCValues values{};
  values.font = font;
  values.foreground = 0;
  GC gc = XCreateGC(dpy, pix, GCFont | GCForeground, &values);
  XFillRectangle(dpy, pix, gc, 0, 0, w, h);
  XSetForeground(dpy, gc, 1);
  XChar2b ch{static_cast<unsigned char>(c >> 8), static_cast<unsigned char>(c & 0xffu)};
  XDrawString16(dpy, pix, gc, -m->lbearing, m->ascent, &ch, 1);
  XImage* img = XGetImage(dpy, pix, 0, 0, w, h, 1, XYPixmap);
  XFreeGC(dpy, gc);
  XFreePixmap(dpy, pix);
  const size_t stride = (w + 7) / 8;
  g.bits.assign(stride * h, 0);
  if (img == nullptr) return g;
  // X rows run top to bottom, glBitmap's bottom to top (GL 2.1 §3.7).
  for (unsigned y = 0; y < h; ++y) {
    GLubyte* row = &g.bits[(h - 1 - y) * stride];
    for (unsigned x = 0; x < w; ++x)
      if (XGetPixel(img, static_cast<int>(x), static_cast<int>(y)) != 0)
        row[x / 8] |= static_cast<GLubyte>(0x80u >> (x % 8));
  }
  XDestroyImage(img);
  return g;
}

} // namespace
} // namespace pineda::glx

using namespace pineda::glx;

GLX_EXPORT void glXUseXFont(Font font, int first, int count, int listBase) {
  std::vector<Glyph> glyphs;
  {
    ApiLock api;
    Display* dpy = nullptr;
    GlxContext* ctx = current_binding(&dpy);
    // "glXUseXFont is ignored if there is no current GLX rendering context."
    if (ctx == nullptr || dpy == nullptr) return;
    DisplayState* ds = display_state(dpy);
    XFontStruct* fs = nullptr;
    if (trap_errors(dpy, [&] { fs = XQueryFont(dpy, font); }) != 0 || fs == nullptr) {
      report_error(ds, -1, BadFont, font, kReqUseXFont);
      return;
    }
    if (ctx->dlist.list != nullptr) {
      XFreeFontInfo(nullptr, fs, 1);
      report_error(ds, GLXBadContextState, 0, 0, kReqUseXFont);
      return;
    }
    const Drawable root = RootWindow(dpy, ctx->config->screen);
    trap_errors(dpy, [&] {
      for (int i = 0; i < count; ++i)
        glyphs.push_back(render_glyph(dpy, root, font, fs, static_cast<unsigned>(first + i)));
    });
    XFreeFontInfo(nullptr, fs, 1);
  }
  // The lists are made through the GL API (outside the GLX lock: GL calls may need it), with
  // the default unpack state so the bitmaps read as built.
  glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
  glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_FALSE);
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  static const GLubyte kNoBits = 0;
  for (size_t i = 0; i < glyphs.size(); ++i) {
    const Glyph& g = glyphs[i];
    glNewList(static_cast<GLuint>(listBase) + static_cast<GLuint>(i), GL_COMPILE);
    // "If a glyph is not defined, then an empty display list is constructed for it."
    if (g.defined)
      glBitmap(g.width, g.height, g.xorig, g.yorig, g.xmove, 0.0f,
               g.bits.empty() ? &kNoBits : g.bits.data());
    glEndList();
  }
  glPopClientAttrib();
  // "glXUseXFont performs an implicit glFlush."
  glFlush();
}
