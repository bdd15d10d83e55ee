// glXCopyContext (GLX 1.4 §3.3.7), glXUseXFont (§3.3.11) and glXGetProcAddress of the GL
// extension commands (§3.3.12), through the real library against a private Xvfb started by
// run_with_xvfb.sh.
// GoogleTest first: Xlib defines a macro None, a name GoogleTest uses for a type.
#include <gtest/gtest.h>

#include <GL/gl.h>
#include <GL/glx.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>

#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

int g_last_error = 0;
int record_error(Display*, XErrorEvent* ev) {
  g_last_error = ev->error_code;
  return 0;
}

constexpr int kW = 96, kH = 32;

// A window and two contexts of one single-buffered RGBA config.
class GlxExt : public ::testing::Test {
protected:
  void SetUp() override {
    dpy = XOpenDisplay(nullptr);
    ASSERT_NE(dpy, nullptr) << "no X display (run through run_with_xvfb.sh)";
    XSetErrorHandler(record_error);
    g_last_error = 0;
    int event_base = 0;
    ASSERT_TRUE(glXQueryExtension(dpy, &error_base, &event_base));
    const int attribs[] = {
        GLX_RENDER_TYPE, GLX_RGBA_BIT, GLX_DRAWABLE_TYPE, GLX_WINDOW_BIT, GLX_DOUBLEBUFFER,
        False,           None};
    int n = 0;
    GLXFBConfig* list = glXChooseFBConfig(dpy, DefaultScreen(dpy), attribs, &n);
    ASSERT_NE(list, nullptr);
    config = list[0];
    XFree(list);
    XVisualInfo* vi = glXGetVisualFromFBConfig(dpy, config);
    ASSERT_NE(vi, nullptr);
    const Window root = RootWindow(dpy, vi->screen);
    XSetWindowAttributes swa{};
    swa.colormap = XCreateColormap(dpy, root, vi->visual, AllocNone);
    swa.event_mask = StructureNotifyMask;
    win = XCreateWindow(dpy, root, 0, 0, kW, kH, 0, vi->depth, InputOutput, vi->visual,
                        CWColormap | CWEventMask, &swa);
    XFree(vi);
    XMapWindow(dpy, win);
    XEvent ev;
    do
      XNextEvent(dpy, &ev);
    while (ev.type != MapNotify);
    a = glXCreateNewContext(dpy, config, GLX_RGBA_TYPE, nullptr, True);
    b = glXCreateNewContext(dpy, config, GLX_RGBA_TYPE, nullptr, True);
    ASSERT_NE(a, nullptr);
    ASSERT_NE(b, nullptr);
  }
  void TearDown() override {
    if (dpy == nullptr) return;
    glXMakeCurrent(dpy, None, nullptr);
    glXDestroyContext(dpy, a);
    glXDestroyContext(dpy, b);
    XDestroyWindow(dpy, win);
    XCloseDisplay(dpy);
  }

  Display* dpy = nullptr;
  int error_base = 0;
  GLXFBConfig config = nullptr;
  Window win = 0;
  GLXContext a = nullptr, b = nullptr;
};

GLint get_int(GLenum pname) {
  GLint v = 0;
  glGetIntegerv(pname, &v);
  return v;
}

GLint env_mode() {
  GLint v = 0;
  glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &v);
  return v;
}

TEST_F(GlxExt, CopyContextCopiesExactlyTheMaskedGroups) {
  ASSERT_TRUE(glXMakeCurrent(dpy, win, a));
  glClearColor(1, 0, 0, 1);              // COLOR_BUFFER_BIT
  glDepthFunc(GL_GREATER);               // DEPTH_BUFFER_BIT
  glLineWidth(3);                        // LINE_BIT
  glEnable(GL_CULL_FACE);                // ENABLE_BIT, POLYGON_BIT
  glListBase(7);                         // LIST_BIT
  glPixelStorei(GL_UNPACK_ALIGNMENT, 2); // client state: never copied
  glXCopyContext(dpy, a, b, GL_COLOR_BUFFER_BIT | GL_LINE_BIT);
  EXPECT_EQ(g_last_error, 0);
  ASSERT_TRUE(glXMakeCurrent(dpy, win, b));
  GLfloat clear[4] = {};
  glGetFloatv(GL_COLOR_CLEAR_VALUE, clear);
  EXPECT_EQ(clear[0], 1.0f);
  EXPECT_EQ(clear[3], 1.0f);
  GLfloat width = 0;
  glGetFloatv(GL_LINE_WIDTH, &width);
  EXPECT_EQ(width, 3.0f);
  EXPECT_EQ(get_int(GL_DEPTH_FUNC), GL_LESS);
  EXPECT_FALSE(glIsEnabled(GL_CULL_FACE));
  EXPECT_EQ(get_int(GL_LIST_BASE), 0);
  EXPECT_EQ(get_int(GL_UNPACK_ALIGNMENT), 4);

  // Neither context current: everything pushable is copied; unknown bits are ignored.
  glXMakeCurrent(dpy, None, nullptr);
  glXCopyContext(dpy, a, b, GL_ALL_ATTRIB_BITS | 0x80000000ul);
  EXPECT_EQ(g_last_error, 0);
  ASSERT_TRUE(glXMakeCurrent(dpy, win, b));
  EXPECT_EQ(get_int(GL_DEPTH_FUNC), GL_GREATER);
  EXPECT_TRUE(glIsEnabled(GL_CULL_FACE));
  EXPECT_EQ(get_int(GL_LIST_BASE), 7);
  EXPECT_EQ(get_int(GL_UNPACK_ALIGNMENT), 4);
  // The copy rendered with: the clear colour came along.
  glClear(GL_COLOR_BUFFER_BIT);
  GLubyte px[4] = {};
  glReadPixels(1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_EQ(px[0], 255);
  EXPECT_EQ(px[2], 0);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(GlxExt, CopyContextErrors) {
  ASSERT_TRUE(glXMakeCurrent(dpy, win, a));
  glLineWidth(5);
  // The destination is current (to this thread): BadAccess, nothing copied.
  glXMakeCurrent(dpy, win, b);
  glXCopyContext(dpy, a, b, GL_LINE_BIT);
  EXPECT_EQ(g_last_error, BadAccess);
  GLfloat width = 0;
  glGetFloatv(GL_LINE_WIDTH, &width);
  EXPECT_EQ(width, 1.0f);
  g_last_error = 0;
  glXCopyContext(dpy, a, reinterpret_cast<GLXContext>(&width), GL_LINE_BIT);
  EXPECT_EQ(g_last_error, error_base + GLXBadContext);
  g_last_error = 0;
  glXCopyContext(dpy, nullptr, a, GL_LINE_BIT);
  EXPECT_EQ(g_last_error, error_base + GLXBadContext);
}

TEST_F(GlxExt, CopyContextWithSharedTextures) {
  GLXContext shared = glXCreateNewContext(dpy, config, GLX_RGBA_TYPE, a, True);
  ASSERT_NE(shared, nullptr);
  ASSERT_TRUE(glXMakeCurrent(dpy, win, a));
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL);
  glXMakeCurrent(dpy, None, nullptr);
  // Same share group: the binding names the same object and is copied.
  glXCopyContext(dpy, a, shared, GL_TEXTURE_BIT);
  // Another share group: the environment is copied, the binding is not.
  glXCopyContext(dpy, a, b, GL_TEXTURE_BIT);
  ASSERT_TRUE(glXMakeCurrent(dpy, win, shared));
  EXPECT_EQ(get_int(GL_TEXTURE_BINDING_2D), static_cast<GLint>(tex));
  EXPECT_EQ(env_mode(), GL_DECAL);
  ASSERT_TRUE(glXMakeCurrent(dpy, win, b));
  EXPECT_EQ(get_int(GL_TEXTURE_BINDING_2D), 0);
  EXPECT_EQ(env_mode(), GL_DECAL);
  glXMakeCurrent(dpy, None, nullptr);
  glXDestroyContext(dpy, shared);
  EXPECT_EQ(g_last_error, 0);
}

// Draws `text` with the lists of glXUseXFont at GL window position (x0, y0) and with
// XDrawString into a 1-bit pixmap at the same place, and returns how many pixels differ; the
// number of lit pixels goes to *lit.
int compare_text(Display* dpy, Window win, Font font, GLuint base, const char* text, int x0, int y0,
                 int* lit) {
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1, 1, 1);
  glRasterPos2i(x0, y0);
  glListBase(base);
  glCallLists(static_cast<GLsizei>(std::strlen(text)), GL_UNSIGNED_BYTE, text);
  std::vector<GLubyte> gl(kW * kH * 4);
  glReadPixels(0, 0, kW, kH, GL_RGBA, GL_UNSIGNED_BYTE, gl.data());

  const Pixmap pix = XCreatePixmap(dpy, win, kW, kH, 1);
  XGCValues values{};
  values.font = font;
  values.foreground = 0;
  GC gc = XCreateGC(dpy, pix, GCFont | GCForeground, &values);
  XFillRectangle(dpy, pix, gc, 0, 0, kW, kH);
  XSetForeground(dpy, gc, 1);
  // GL row y0 is the bitmap row just above the descent, X's baseline row is the first row of
  // the descent: X's baseline is GL row y0 - 1, X row kH - y0.
  XDrawString(dpy, pix, gc, x0, kH - y0, text, static_cast<int>(std::strlen(text)));
  XImage* img = XGetImage(dpy, pix, 0, 0, kW, kH, 1, XYPixmap);
  XFreeGC(dpy, gc);
  XFreePixmap(dpy, pix);
  if (img == nullptr) return -1;
  int differ = 0;
  *lit = 0;
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      const bool x_on = XGetPixel(img, x, kH - 1 - y) != 0;
      const bool gl_on = gl[(y * kW + x) * 4] > 127;
      differ += x_on != gl_on;
      *lit += gl_on;
    }
  }
  XDestroyImage(img);
  return differ;
}

TEST_F(GlxExt, UseXFontDrawsWhatXDraws) {
  const Font font = XLoadFont(dpy, "fixed");
  XFontStruct* fs = XQueryFont(dpy, font);
  ASSERT_NE(fs, nullptr);
  ASSERT_TRUE(glXMakeCurrent(dpy, win, a));
  glMatrixMode(GL_PROJECTION);
  glOrtho(0, kW, 0, kH, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  const GLuint base = glGenLists(96);
  glXUseXFont(font, 32, 96, static_cast<int>(base));
  EXPECT_EQ(g_last_error, 0);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  for (GLuint i = 0; i < 96; ++i)
    EXPECT_TRUE(glIsList(base + i)) << i;

  // The raster position moves by each glyph's width metric.
  glRasterPos2i(10, 10);
  glCallList(base + ('A' - 32));
  GLfloat rp[4] = {};
  glGetFloatv(GL_CURRENT_RASTER_POSITION, rp);
  const int advance = fs->per_char != nullptr ? fs->per_char['A' - fs->min_char_or_byte2].width
                                              : fs->max_bounds.width;
  // The start went through the projection: within rounding of 10.
  EXPECT_NEAR(rp[0], 10.0f + static_cast<float>(advance), 1e-4);
  EXPECT_NEAR(rp[1], 10.0f, 1e-4);

  int lit = 0;
  EXPECT_EQ(compare_text(dpy, win, font, base - 32, "Hi, gjy|", 3, 12, &lit), 0);
  EXPECT_GT(lit, 40);
  XFreeFontInfo(nullptr, fs, 1);
  XUnloadFont(dpy, font);
}

TEST_F(GlxExt, UseXFontErrors) {
  // No current context: ignored.
  glXUseXFont(0, 0, 1, 1);
  EXPECT_EQ(g_last_error, 0);
  ASSERT_TRUE(glXMakeCurrent(dpy, win, a));
  glXUseXFont(0x1234567, 32, 4, 1);
  EXPECT_EQ(g_last_error, BadFont);
  EXPECT_FALSE(glIsList(1));
  g_last_error = 0;
  const Font font = XLoadFont(dpy, "fixed");
  glNewList(1, GL_COMPILE);
  glXUseXFont(font, 32, 4, 10);
  glEndList();
  EXPECT_EQ(g_last_error, error_base + GLXBadContextState);
  EXPECT_FALSE(glIsList(10));
  XUnloadFont(dpy, font);
}

// Every command of every extension in GL_EXTENSIONS is found by glXGetProcAddress.
TEST_F(GlxExt, ProcAddressOfEveryAdvertisedExtensionCommand) {
  ASSERT_TRUE(glXMakeCurrent(dpy, win, a));
  std::ifstream in(PINEDA_GL_XML);
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string xml = ss.str();
  ASSERT_FALSE(xml.empty());
  std::istringstream words(reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS)));
  int found = 0;
  for (std::string ext; words >> ext;) {
    const size_t at = xml.find("<extension name=\"" + ext + "\"");
    if (at == std::string::npos || xml[xml.find('>', at) - 1] == '/') continue;
    const size_t end = xml.find("</extension>", at);
    for (size_t c = xml.find("<command name=\"", at); c != std::string::npos && c < end;
         c = xml.find("<command name=\"", c + 1)) {
      const size_t n = c + 15;
      const std::string name = xml.substr(n, xml.find('"', n) - n);
      // Commands of require blocks for OpenGL ES only are not desktop GL's.
      const size_t req = xml.rfind("<require", c);
      if (xml.compare(req, 20, "<require api=\"gles1\"") == 0 ||
          xml.compare(req, 20, "<require api=\"gles2\"") == 0)
        continue;
      EXPECT_NE(glXGetProcAddress(reinterpret_cast<const GLubyte*>(name.c_str())), nullptr)
          << ext << ": " << name;
      ++found;
    }
  }
  EXPECT_GT(found, 130);
  EXPECT_NE(glXGetProcAddress(reinterpret_cast<const GLubyte*>("glXCopyContext")), nullptr);
  EXPECT_NE(glXGetProcAddress(reinterpret_cast<const GLubyte*>("glXUseXFont")), nullptr);
}

} // namespace
