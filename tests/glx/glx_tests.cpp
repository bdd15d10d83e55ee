// GLX through the real library (libGL.so.1 = Pineda) against a private Xvfb started by
// run_with_xvfb.sh: configs and their sorting, visuals, contexts, windows (double- and
// single-buffered, read back with XGetImage), pixmaps, pbuffers, errors, proc addresses.
// GoogleTest first: Xlib defines a macro None, a name GoogleTest uses for a type.
#include <gtest/gtest.h>

#include <GL/gl.h>
#include <GL/glx.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>

#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

namespace {

// X errors land here instead of ending the program (GLX errors are X errors, GLX 1.4 §3.1).
int g_last_error = 0;
int g_error_count = 0;
int record_error(Display*, XErrorEvent* ev) {
  g_last_error = ev->error_code;
  ++g_error_count;
  return 0;
}

class Glx : public ::testing::Test {
protected:
  void SetUp() override {
    dpy = XOpenDisplay(nullptr);
    ASSERT_NE(dpy, nullptr) << "no X display (run through run_with_xvfb.sh)";
    XSetErrorHandler(record_error);
    g_last_error = 0;
    g_error_count = 0;
    int event_base = 0;
    ASSERT_TRUE(glXQueryExtension(dpy, &error_base, &event_base));
  }
  void TearDown() override {
    if (dpy == nullptr) return;
    glXMakeCurrent(dpy, None, nullptr);
    for (Window w : windows)
      XDestroyWindow(dpy, w);
    XCloseDisplay(dpy);
  }

  GLXFBConfig choose(std::vector<int> attribs) {
    attribs.push_back(None);
    int n = 0;
    GLXFBConfig* list = glXChooseFBConfig(dpy, DefaultScreen(dpy), attribs.data(), &n);
    if (list == nullptr) return nullptr;
    GLXFBConfig first = list[0];
    XFree(list);
    return first;
  }
  int attrib(GLXFBConfig c, int a) {
    int v = -1;
    EXPECT_EQ(glXGetFBConfigAttrib(dpy, c, a, &v), Success);
    return v;
  }
  Window make_window(GLXFBConfig c, int w, int h) {
    XVisualInfo* vi = glXGetVisualFromFBConfig(dpy, c);
    EXPECT_NE(vi, nullptr);
    Window root = RootWindow(dpy, vi->screen);
    XSetWindowAttributes swa{};
    swa.colormap = XCreateColormap(dpy, root, vi->visual, AllocNone);
    swa.event_mask = StructureNotifyMask;
    Window win =
        XCreateWindow(dpy, root, 0, 0, static_cast<unsigned>(w), static_cast<unsigned>(h), 0,
                      vi->depth, InputOutput, vi->visual, CWColormap | CWEventMask, &swa);
    XFree(vi);
    XMapWindow(dpy, win);
    XEvent ev;
    do
      XNextEvent(dpy, &ev);
    while (ev.type != MapNotify);
    windows.push_back(win);
    return win;
  }
  // Pixel (x, y) of a drawable, X coordinates (row 0 at the top), as 0xRRGGBB.
  unsigned long x_pixel(Drawable d, int x, int y) {
    XImage* img = XGetImage(dpy, d, x, y, 1, 1, AllPlanes, ZPixmap);
    EXPECT_NE(img, nullptr);
    if (img == nullptr) return 0;
    const unsigned long p = XGetPixel(img, 0, 0) & 0xffffff;
    XDestroyImage(img);
    return p;
  }
  // Blue background, a red triangle over the centre.
  static void draw_scene() {
    glClearColor(0, 0, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glColor3f(1, 0, 0);
    glBegin(GL_TRIANGLES);
    glVertex2f(-0.5f, -0.5f);
    glVertex2f(0.5f, -0.5f);
    glVertex2f(0.0f, 0.5f);
    glEnd();
  }

  Display* dpy = nullptr;
  int error_base = 0;
  std::vector<Window> windows;
};

TEST_F(Glx, VersionAndStrings) {
  int major = 0, minor = 0;
  ASSERT_TRUE(glXQueryVersion(dpy, &major, &minor));
  EXPECT_EQ(major, 1);
  EXPECT_EQ(minor, 4);
  EXPECT_STREQ(glXGetClientString(dpy, GLX_VENDOR), "Pineda");
  EXPECT_STREQ(glXQueryServerString(dpy, 0, GLX_VERSION), "1.4");
  const std::string ext = glXQueryExtensionsString(dpy, 0);
  EXPECT_NE(ext.find("GLX_ARB_create_context"), std::string::npos);
  EXPECT_NE(ext.find("GLX_EXT_swap_control"), std::string::npos);
  EXPECT_EQ(glXGetClientString(dpy, 0x1234), nullptr);
}

TEST_F(Glx, ConfigsAndSorting) {
  int n = 0;
  GLXFBConfig* all = glXGetFBConfigs(dpy, DefaultScreen(dpy), &n);
  ASSERT_NE(all, nullptr);
  ASSERT_GT(n, 0);
  // The native first config suits piglit: double-buffered RGBA8, depth 24, stencil 8.
  EXPECT_EQ(attrib(all[0], GLX_DOUBLEBUFFER), True);
  EXPECT_EQ(attrib(all[0], GLX_ALPHA_SIZE), 8);
  EXPECT_EQ(attrib(all[0], GLX_DEPTH_SIZE), 24);
  EXPECT_EQ(attrib(all[0], GLX_STENCIL_SIZE), 8);
  EXPECT_EQ(attrib(all[0], GLX_RENDER_TYPE) & GLX_RGBA_BIT, GLX_RGBA_BIT);
  EXPECT_EQ(attrib(all[0], GLX_DRAWABLE_TYPE), GLX_WINDOW_BIT | GLX_PIXMAP_BIT | GLX_PBUFFER_BIT);
  EXPECT_EQ(attrib(all[0], GLX_X_VISUAL_TYPE), GLX_TRUE_COLOR);
  EXPECT_EQ(attrib(all[0], GLX_ACCUM_RED_SIZE), 0);
  int v = 0;
  EXPECT_EQ(glXGetFBConfigAttrib(dpy, all[0], 0x7777, &v), GLX_BAD_ATTRIBUTE);
  XFree(all);

  // What waffle asks for: the first match has everything requested.
  GLXFBConfig c = choose({GLX_RENDER_TYPE, GLX_RGBA_BIT, GLX_DOUBLEBUFFER, True, GLX_RED_SIZE, 8,
                          GLX_GREEN_SIZE, 8, GLX_BLUE_SIZE, 8, GLX_ALPHA_SIZE, 8, GLX_DEPTH_SIZE,
                          24, GLX_STENCIL_SIZE, 8});
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(attrib(c, GLX_DOUBLEBUFFER), True);
  EXPECT_EQ(attrib(c, GLX_ALPHA_SIZE), 8);
  EXPECT_EQ(attrib(c, GLX_DEPTH_SIZE), 24);
  EXPECT_EQ(attrib(c, GLX_STENCIL_SIZE), 8);

  // GLX 1.4 §3.3.3 with defaults only: single before double (rule 4), smaller buffer (3),
  // larger depth (8), smaller stencil (9).
  c = choose({});
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(attrib(c, GLX_DOUBLEBUFFER), False);
  EXPECT_EQ(attrib(c, GLX_BUFFER_SIZE), 24);
  EXPECT_EQ(attrib(c, GLX_DEPTH_SIZE), 24);
  EXPECT_EQ(attrib(c, GLX_STENCIL_SIZE), 0);

  // GLX_FBCONFIG_ID selects exactly that config.
  const int id = attrib(c, GLX_FBCONFIG_ID);
  GLXFBConfig by_id = choose({GLX_FBCONFIG_ID, id, GLX_DOUBLEBUFFER, True});
  EXPECT_EQ(by_id, c);

  // Unsatisfiable and undefined requests.
  // Accumulation buffers: Mesa's 16 signed bits per channel, on request only (rule 10).
  GLXFBConfig acc = choose({GLX_ACCUM_RED_SIZE, 1});
  ASSERT_NE(acc, nullptr);
  EXPECT_EQ(attrib(acc, GLX_ACCUM_RED_SIZE), 16);
  EXPECT_EQ(attrib(acc, GLX_ACCUM_ALPHA_SIZE), 16);
  EXPECT_EQ(attrib(choose({}), GLX_ACCUM_RED_SIZE), 0);
  EXPECT_EQ(choose({GLX_STEREO, True}), nullptr);
  EXPECT_EQ(choose({0x7777, 1}), nullptr);
}

TEST_F(Glx, ChooseVisualAndGetConfig) {
  int attribs[] = {GLX_RGBA, GLX_DOUBLEBUFFER, GLX_DEPTH_SIZE, 16, GLX_RED_SIZE, 1, None};
  XVisualInfo* vi = glXChooseVisual(dpy, DefaultScreen(dpy), attribs);
  ASSERT_NE(vi, nullptr);
  int v = 0;
  EXPECT_EQ(glXGetConfig(dpy, vi, GLX_USE_GL, &v), Success);
  EXPECT_EQ(v, True);
  EXPECT_EQ(glXGetConfig(dpy, vi, GLX_DOUBLEBUFFER, &v), Success);
  EXPECT_EQ(v, True);
  EXPECT_EQ(glXGetConfig(dpy, vi, GLX_DEPTH_SIZE, &v), Success);
  EXPECT_GE(v, 16);
  EXPECT_EQ(glXGetConfig(dpy, vi, GLX_RGBA, &v), Success);
  EXPECT_EQ(v, True);
  EXPECT_EQ(glXGetConfig(dpy, vi, 0x7777, &v), GLX_BAD_ATTRIBUTE);
  XFree(vi);
  // Colour index (no GLX_RGBA) is not offered.
  int ci[] = {GLX_DOUBLEBUFFER, None};
  EXPECT_EQ(glXChooseVisual(dpy, DefaultScreen(dpy), ci), nullptr);
}

void window_triangle(Display* dpy, Window win, GLXContext ctx) {
  ASSERT_TRUE(glXMakeCurrent(dpy, win, ctx));
  EXPECT_EQ(glXGetCurrentContext(), ctx);
  EXPECT_EQ(glXGetCurrentDrawable(), win);
  EXPECT_EQ(glXGetCurrentDisplay(), dpy);
  GLint vp[4] = {};
  glGetIntegerv(GL_VIEWPORT, vp);
  EXPECT_EQ(vp[2], 64);
  EXPECT_EQ(vp[3], 48);
}

TEST_F(Glx, DoubleBufferedWindow) {
  GLXFBConfig c = choose({GLX_DOUBLEBUFFER, True, GLX_DEPTH_SIZE, 24});
  ASSERT_NE(c, nullptr);
  Window win = make_window(c, 64, 48);
  GLXContext ctx = glXCreateNewContext(dpy, c, GLX_RGBA_TYPE, nullptr, True);
  ASSERT_NE(ctx, nullptr);
  EXPECT_TRUE(glXIsDirect(dpy, ctx));
  window_triangle(dpy, win, ctx);
  GLint buffer = 0;
  glGetIntegerv(GL_DRAW_BUFFER, &buffer);
  EXPECT_EQ(buffer, GL_BACK);
  glXSwapIntervalEXT(dpy, win, 0);
  unsigned int interval = 99;
  glXQueryDrawable(dpy, win, GLX_SWAP_INTERVAL_EXT, &interval);
  EXPECT_EQ(interval, 0u);
  draw_scene();
  glXSwapBuffers(dpy, win);
  EXPECT_EQ(x_pixel(win, 32, 24), 0xff0000ul);
  EXPECT_EQ(x_pixel(win, 1, 1), 0x0000fful);
  EXPECT_EQ(x_pixel(win, 62, 46), 0x0000fful);
  // The triangle's apex is at the top of the window (GL y up, X y down).
  EXPECT_EQ(x_pixel(win, 32, 14), 0xff0000ul);
  EXPECT_EQ(x_pixel(win, 32, 34), 0xff0000ul);
  EXPECT_EQ(x_pixel(win, 20, 14), 0x0000fful);

  // A resize is picked up at the swap; the next frame covers the new size.
  XResizeWindow(dpy, win, 100, 80);
  XSync(dpy, False);
  glXSwapBuffers(dpy, win);
  unsigned int w = 0, h = 0;
  glXQueryDrawable(dpy, win, GLX_WIDTH, &w);
  glXQueryDrawable(dpy, win, GLX_HEIGHT, &h);
  EXPECT_EQ(w, 100u);
  EXPECT_EQ(h, 80u);
  glViewport(0, 0, 100, 80);
  draw_scene();
  glXSwapBuffers(dpy, win);
  EXPECT_EQ(x_pixel(win, 50, 40), 0xff0000ul);
  EXPECT_EQ(x_pixel(win, 98, 78), 0x0000fful);

  ASSERT_TRUE(glXMakeCurrent(dpy, None, nullptr));
  EXPECT_EQ(glXGetCurrentContext(), nullptr);
  EXPECT_EQ(glXGetCurrentDrawable(), static_cast<GLXDrawable>(None));
  glXDestroyContext(dpy, ctx);
  EXPECT_EQ(g_error_count, 0);
}

// GL pixel (x, y) of the current read buffer as 0xRRGGBB.
unsigned long gl_pixel(int x, int y) {
  GLubyte p[4] = {};
  glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
  return (static_cast<unsigned long>(p[0]) << 16) | (static_cast<unsigned long>(p[1]) << 8) | p[2];
}

void clear_to(float r, float g, float b) {
  glClearColor(r, g, b, 1);
  glClear(GL_COLOR_BUFFER_BIT);
}

// A rectangle over window pixels [x0, x1) x [y0, y1) (GL coordinates, projection identity).
void fill_rect(float r, float g, float b, int x0, int y0, int x1, int y1, int w, int h) {
  glColor3f(r, g, b);
  glRectf(2.0f * x0 / w - 1, 2.0f * y0 / h - 1, 2.0f * x1 / w - 1, 2.0f * y1 / h - 1);
}

// Swaps of a double-buffered window under MIT-SHM alternate two images and do not wait for the
// server (glx_drawable.cpp swap_images): each swap must still show its own frame, and the back
// buffer must keep its contents, so a frame that redraws only part of the window shows the rest
// of the previous one. Run with and without MIT-SHM (glx.api and glx.api_no_shm).
TEST_F(Glx, ConsecutiveSwapsShowEachFrameAndKeepTheBackBuffer) {
  GLXFBConfig c = choose({GLX_DOUBLEBUFFER, True});
  ASSERT_NE(c, nullptr);
  const int w = 40, h = 30;
  Window win = make_window(c, w, h);
  GLXContext ctx = glXCreateNewContext(dpy, c, GLX_RGBA_TYPE, nullptr, True);
  ASSERT_NE(ctx, nullptr);
  ASSERT_TRUE(glXMakeCurrent(dpy, win, ctx));
  glXSwapIntervalEXT(dpy, win, 0);
  const float colours[4][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}};
  const unsigned long expect[4] = {0xff0000ul, 0x00ff00ul, 0x0000fful, 0xffff00ul};
  for (int frame = 0; frame < 8; ++frame) {
    const int k = frame % 4;
    clear_to(colours[k][0], colours[k][1], colours[k][2]);
    glXSwapBuffers(dpy, win);
    EXPECT_EQ(x_pixel(win, 5, 5), expect[k]) << "frame " << frame;
    EXPECT_EQ(gl_pixel(5, 5), expect[k]) << "back buffer after swap " << frame;
  }
  // Partial redraws over the kept back buffer: each adds one column of 10 pixels.
  clear_to(0, 0, 0);
  for (int frame = 0; frame < 4; ++frame) {
    fill_rect(colours[frame][0], colours[frame][1], colours[frame][2], 10 * frame, 0,
              10 * frame + 10, h, w, h);
    glXSwapBuffers(dpy, win);
    for (int col = 0; col <= frame; ++col) {
      EXPECT_EQ(x_pixel(win, 10 * col + 5, 15), expect[col]) << "frame " << frame;
    }
    if (frame < 3) {
      EXPECT_EQ(x_pixel(win, 35, 15), 0ul) << "frame " << frame;
    }
  }
  ASSERT_TRUE(glXMakeCurrent(dpy, None, nullptr));
  glXDestroyContext(dpy, ctx);
  EXPECT_EQ(g_error_count, 0);
}

// GL 2.1 §4.2.1, §4.3.2, GLX 1.4 §3.3.10: a double-buffered window has a front and a back
// buffer, each drawable and readable; the swap makes the back buffer's contents the front's.
TEST_F(Glx, FrontAndBackBuffers) {
  GLXFBConfig c = choose({GLX_DOUBLEBUFFER, True});
  ASSERT_NE(c, nullptr);
  Window win = make_window(c, 64, 48);
  GLXContext ctx = glXCreateNewContext(dpy, c, GLX_RGBA_TYPE, nullptr, True);
  ASSERT_TRUE(glXMakeCurrent(dpy, win, ctx));
  glXSwapIntervalEXT(dpy, win, 0);
  GLint buffer = 0;
  glGetIntegerv(GL_READ_BUFFER, &buffer);
  EXPECT_EQ(buffer, GL_BACK);

  // Back red, swap: the window and the front buffer are red.
  clear_to(1, 0, 0);
  glXSwapBuffers(dpy, win);
  EXPECT_EQ(x_pixel(win, 10, 10), 0xff0000ul);
  glReadBuffer(GL_FRONT);
  EXPECT_EQ(gl_pixel(10, 10), 0xff0000ul);

  // Drawing into the back buffer leaves the front (and the window) alone.
  glDrawBuffer(GL_BACK);
  clear_to(0, 1, 0);
  glFinish();
  EXPECT_EQ(gl_pixel(10, 10), 0xff0000ul);
  EXPECT_EQ(x_pixel(win, 10, 10), 0xff0000ul);
  glReadBuffer(GL_BACK);
  EXPECT_EQ(gl_pixel(10, 10), 0x00ff00ul);

  // Drawing into the front buffer shows at glFlush, without a swap; the back keeps green.
  glDrawBuffer(GL_FRONT);
  fill_rect(0, 0, 1, 0, 0, 32, 48, 64, 48);
  glFlush();
  EXPECT_EQ(x_pixel(win, 10, 10), 0x0000fful);
  EXPECT_EQ(x_pixel(win, 50, 10), 0xff0000ul);
  EXPECT_EQ(gl_pixel(10, 10), 0x00ff00ul);
  glReadBuffer(GL_FRONT_LEFT);
  EXPECT_EQ(gl_pixel(10, 10), 0x0000fful);
  EXPECT_EQ(gl_pixel(50, 10), 0xff0000ul);

  // The swap shows the back buffer; the back buffer keeps its contents (Mesa's behaviour).
  glXSwapBuffers(dpy, win);
  EXPECT_EQ(x_pixel(win, 10, 10), 0x00ff00ul);
  glReadBuffer(GL_FRONT);
  EXPECT_EQ(gl_pixel(10, 10), 0x00ff00ul);
  glReadBuffer(GL_BACK_LEFT);
  EXPECT_EQ(gl_pixel(10, 10), 0x00ff00ul);

  // FRONT_AND_BACK: clears and primitives reach both buffers; LEFT is both too.
  glDrawBuffer(GL_FRONT_AND_BACK);
  clear_to(1, 1, 0);
  fill_rect(1, 0, 1, 0, 0, 16, 16, 64, 48);
  glFlush();
  EXPECT_EQ(x_pixel(win, 40, 10), 0xffff00ul);
  EXPECT_EQ(x_pixel(win, 5, 42), 0xff00fful);
  for (GLenum rb : {GL_FRONT, GL_BACK, GL_LEFT}) {
    glReadBuffer(rb);
    EXPECT_EQ(gl_pixel(40, 40), 0xffff00ul) << rb;
    EXPECT_EQ(gl_pixel(5, 5), 0xff00fful) << rb;
  }
  glDrawBuffer(GL_LEFT);
  fill_rect(0, 1, 1, 32, 32, 64, 48, 64, 48);
  glReadBuffer(GL_FRONT);
  EXPECT_EQ(gl_pixel(40, 40), 0x00fffful);
  glReadBuffer(GL_BACK);
  EXPECT_EQ(gl_pixel(40, 40), 0x00fffful);

  // CopyPixels reads the read buffer and writes the draw buffer.
  glDrawBuffer(GL_BACK);
  clear_to(0, 0, 0);
  glDrawBuffer(GL_FRONT);
  clear_to(1, 1, 1);
  glReadBuffer(GL_FRONT);
  glDrawBuffer(GL_BACK);
  glRasterPos2f(0, 0); // window (32, 24)
  glCopyPixels(0, 0, 8, 8, GL_COLOR);
  glReadBuffer(GL_BACK);
  EXPECT_EQ(gl_pixel(34, 26), 0xfffffful);
  EXPECT_EQ(gl_pixel(10, 10), 0x000000ul);

  // glGet and glPushAttrib/glPopAttrib keep the selection.
  glDrawBuffer(GL_FRONT);
  glPushAttrib(GL_COLOR_BUFFER_BIT | GL_PIXEL_MODE_BIT);
  glDrawBuffer(GL_BACK);
  glReadBuffer(GL_FRONT);
  glPopAttrib();
  glGetIntegerv(GL_DRAW_BUFFER, &buffer);
  EXPECT_EQ(buffer, GL_FRONT);
  glGetIntegerv(GL_READ_BUFFER, &buffer);
  EXPECT_EQ(buffer, GL_BACK);
  clear_to(1, 0, 0);
  glReadBuffer(GL_FRONT);
  EXPECT_EQ(gl_pixel(1, 1), 0xff0000ul);
  glReadBuffer(GL_BACK);
  EXPECT_EQ(gl_pixel(1, 1), 0x000000ul);

  // Buffers the window does not have (GL 2.1 §4.2.1, §4.3.2).
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  for (GLenum b : {GL_RIGHT, GL_FRONT_RIGHT, GL_BACK_RIGHT, GL_AUX0}) {
    glDrawBuffer(b);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION)) << b;
    glReadBuffer(b);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION)) << b;
  }
  glReadBuffer(GL_FRONT_AND_BACK);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  glGetIntegerv(GL_DRAW_BUFFER, &buffer);
  EXPECT_EQ(buffer, GL_FRONT);

  ASSERT_TRUE(glXMakeCurrent(dpy, None, nullptr));
  glXDestroyContext(dpy, ctx);
  EXPECT_EQ(g_error_count, 0);
}

// A swap made while only the back buffer is in use leaves the front buffer to the window;
// selecting it later reads what the swap showed, not what was drawn since.
TEST_F(Glx, FrontBufferAfterBackOnlySwap) {
  GLXFBConfig c = choose({GLX_DOUBLEBUFFER, True, GLX_DEPTH_SIZE, 24});
  ASSERT_NE(c, nullptr);
  Window win = make_window(c, 64, 48);
  GLXContext ctx = glXCreateNewContext(dpy, c, GLX_RGBA_TYPE, nullptr, True);
  ASSERT_TRUE(glXMakeCurrent(dpy, win, ctx));
  glXSwapIntervalEXT(dpy, win, 0);
  draw_scene();
  glXSwapBuffers(dpy, win);
  clear_to(0, 1, 0);
  glReadBuffer(GL_FRONT);
  EXPECT_EQ(gl_pixel(32, 24), 0xff0000ul);
  EXPECT_EQ(gl_pixel(1, 1), 0x0000fful);
  // glCopyTexImage2D reads the read buffer too.
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 4, 4, 0);
  GLubyte texel[4 * 16] = {};
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  EXPECT_EQ(texel[0], 0);
  EXPECT_EQ(texel[2], 255);
  glDeleteTextures(1, &tex);
  // Depth testing with FRONT_AND_BACK: both buffers see the same depth test results.
  glDrawBuffer(GL_FRONT_AND_BACK);
  glEnable(GL_DEPTH_TEST);
  glClear(GL_DEPTH_BUFFER_BIT);
  clear_to(0, 0, 0);
  // One draw: a white quad, then a red one behind it, hidden in both buffers.
  glBegin(GL_QUADS);
  glColor3f(1, 1, 1);
  glVertex3f(-1, -1, 0);
  glVertex3f(1, -1, 0);
  glVertex3f(1, 1, 0);
  glVertex3f(-1, 1, 0);
  glColor3f(1, 0, 0);
  glVertex3f(-1, -1, 0.5f);
  glVertex3f(1, -1, 0.5f);
  glVertex3f(1, 1, 0.5f);
  glVertex3f(-1, 1, 0.5f);
  glEnd();
  for (GLenum rb : {GL_FRONT, GL_BACK}) {
    glReadBuffer(rb);
    EXPECT_EQ(gl_pixel(20, 20), 0xfffffful) << rb;
  }
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  ASSERT_TRUE(glXMakeCurrent(dpy, None, nullptr));
  // Unbinding flushes front-buffer rendering to the window.
  EXPECT_EQ(x_pixel(win, 20, 20), 0xfffffful);
  glXDestroyContext(dpy, ctx);
  EXPECT_EQ(g_error_count, 0);
}

// GL 2.1 §4.2.4: LOAD and ACCUM read the read buffer, RETURN writes every draw buffer.
TEST_F(Glx, AccumulationWithFrontAndBack) {
  GLXFBConfig c = choose({GLX_DOUBLEBUFFER, True, GLX_ACCUM_RED_SIZE, 16});
  ASSERT_NE(c, nullptr);
  Window win = make_window(c, 32, 32);
  GLXContext ctx = glXCreateNewContext(dpy, c, GLX_RGBA_TYPE, nullptr, True);
  ASSERT_TRUE(glXMakeCurrent(dpy, win, ctx));
  glDrawBuffer(GL_FRONT);
  clear_to(1, 0, 0);
  glDrawBuffer(GL_BACK);
  clear_to(0, 0, 1);
  glReadBuffer(GL_FRONT);
  glAccum(GL_LOAD, 1.0f); // red, from the front buffer
  glReadBuffer(GL_BACK);
  glAccum(GL_ACCUM, 1.0f); // plus blue, from the back buffer
  glDrawBuffer(GL_FRONT_AND_BACK);
  glAccum(GL_RETURN, 1.0f);
  glFinish();
  EXPECT_EQ(gl_pixel(5, 5), 0xff00fful);
  glReadBuffer(GL_FRONT);
  EXPECT_EQ(gl_pixel(5, 5), 0xff00fful);
  EXPECT_EQ(x_pixel(win, 5, 5), 0xff00fful);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  ASSERT_TRUE(glXMakeCurrent(dpy, None, nullptr));
  glXDestroyContext(dpy, ctx);
  EXPECT_EQ(g_error_count, 0);
}

TEST_F(Glx, GlxWindowAndSingleBuffer) {
  GLXFBConfig c = choose({GLX_DOUBLEBUFFER, False});
  ASSERT_NE(c, nullptr);
  Window win = make_window(c, 64, 48);
  GLXWindow gw = glXCreateWindow(dpy, c, win, nullptr);
  ASSERT_NE(gw, static_cast<GLXWindow>(None));
  GLXContext ctx = glXCreateNewContext(dpy, c, GLX_RGBA_TYPE, nullptr, True);
  ASSERT_TRUE(glXMakeContextCurrent(dpy, gw, gw, ctx));
  EXPECT_EQ(glXGetCurrentReadDrawable(), gw);
  GLint buffer = 0;
  glGetIntegerv(GL_DRAW_BUFFER, &buffer);
  EXPECT_EQ(buffer, GL_FRONT);
  // A single-buffered window has no back buffer (GL 2.1 §4.2.1, §4.3.2).
  for (GLenum b : {GL_BACK, GL_BACK_LEFT, GL_RIGHT, GL_AUX0}) {
    glDrawBuffer(b);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION)) << b;
    glReadBuffer(b);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION)) << b;
  }
  // FRONT_AND_BACK and LEFT name the front buffer, which exists.
  glDrawBuffer(GL_FRONT_AND_BACK);
  glDrawBuffer(GL_LEFT);
  glDrawBuffer(GL_FRONT);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  draw_scene();
  // Single-buffered: glFinish shows the rendering without a swap.
  glFinish();
  EXPECT_EQ(x_pixel(win, 32, 24), 0xff0000ul);
  EXPECT_EQ(x_pixel(win, 1, 1), 0x0000fful);
  int value = 0;
  EXPECT_EQ(glXQueryContext(dpy, ctx, GLX_FBCONFIG_ID, &value), Success);
  EXPECT_EQ(value, attrib(c, GLX_FBCONFIG_ID));
  EXPECT_EQ(glXQueryContext(dpy, ctx, GLX_RENDER_TYPE, &value), Success);
  EXPECT_EQ(value, GLX_RGBA_TYPE);
  glXSelectEvent(dpy, gw, GLX_PBUFFER_CLOBBER_MASK);
  unsigned long mask = 0;
  glXGetSelectedEvent(dpy, gw, &mask);
  EXPECT_EQ(mask, static_cast<unsigned long>(GLX_PBUFFER_CLOBBER_MASK));
  ASSERT_TRUE(glXMakeContextCurrent(dpy, None, None, nullptr));
  glXDestroyWindow(dpy, gw);
  glXDestroyContext(dpy, ctx);
  EXPECT_EQ(g_error_count, 0);
}

TEST_F(Glx, Pixmap) {
  GLXFBConfig c = choose({GLX_DRAWABLE_TYPE, GLX_PIXMAP_BIT, GLX_DEPTH_SIZE, 16});
  ASSERT_NE(c, nullptr);
  XVisualInfo* vi = glXGetVisualFromFBConfig(dpy, c);
  ASSERT_NE(vi, nullptr);
  Pixmap pm =
      XCreatePixmap(dpy, RootWindow(dpy, vi->screen), 64, 48, static_cast<unsigned>(vi->depth));
  XFree(vi);
  // X draws first: a green square that GL must see after binding (GLX 1.4 §3.3.9).
  GC gc = XCreateGC(dpy, pm, 0, nullptr);
  XSetForeground(dpy, gc, 0x00ff00);
  XFillRectangle(dpy, pm, gc, 0, 0, 64, 48);
  GLXPixmap gp = glXCreatePixmap(dpy, c, pm, nullptr);
  ASSERT_NE(gp, static_cast<GLXPixmap>(None));
  GLXContext ctx = glXCreateNewContext(dpy, c, GLX_RGBA_TYPE, nullptr, True);
  ASSERT_TRUE(glXMakeCurrent(dpy, gp, ctx));
  GLubyte px[4] = {};
  glReadPixels(5, 5, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_EQ(px[0], 0);
  EXPECT_EQ(px[1], 255);
  EXPECT_EQ(px[2], 0);
  draw_scene();
  glFinish();
  EXPECT_EQ(x_pixel(pm, 32, 24), 0xff0000ul);
  EXPECT_EQ(x_pixel(pm, 1, 1), 0x0000fful);
  // X draws again; glXWaitX makes it visible to GL.
  XFillRectangle(dpy, pm, gc, 0, 0, 8, 8);
  glXWaitX();
  glReadPixels(2, 45, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_EQ(px[1], 255);
  EXPECT_EQ(px[2], 0);
  ASSERT_TRUE(glXMakeCurrent(dpy, None, nullptr));
  glXDestroyPixmap(dpy, gp);
  glXDestroyContext(dpy, ctx);
  XFreeGC(dpy, gc);
  XFreePixmap(dpy, pm);
  EXPECT_EQ(g_error_count, 0);
}

TEST_F(Glx, GlxPixmapFromVisual) {
  int attribs[] = {GLX_RGBA, GLX_RED_SIZE, 8, None};
  XVisualInfo* vi = glXChooseVisual(dpy, DefaultScreen(dpy), attribs);
  ASSERT_NE(vi, nullptr);
  Pixmap pm =
      XCreatePixmap(dpy, RootWindow(dpy, vi->screen), 32, 32, static_cast<unsigned>(vi->depth));
  GLXPixmap gp = glXCreateGLXPixmap(dpy, vi, pm);
  GLXContext ctx = glXCreateContext(dpy, vi, nullptr, True);
  ASSERT_NE(ctx, nullptr);
  ASSERT_TRUE(glXMakeCurrent(dpy, gp, ctx));
  glClearColor(1, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glXWaitGL();
  EXPECT_EQ(x_pixel(pm, 16, 16), 0xffff00ul);
  ASSERT_TRUE(glXMakeCurrent(dpy, None, nullptr));
  glXDestroyGLXPixmap(dpy, gp);
  glXDestroyContext(dpy, ctx);
  XFreePixmap(dpy, pm);
  XFree(vi);
  EXPECT_EQ(g_error_count, 0);
}

TEST_F(Glx, Pbuffer) {
  GLXFBConfig c = choose({GLX_DRAWABLE_TYPE, GLX_PBUFFER_BIT, GLX_ALPHA_SIZE, 8});
  ASSERT_NE(c, nullptr);
  const int attribs[] = {GLX_PBUFFER_WIDTH, 40, GLX_PBUFFER_HEIGHT, 30, None};
  GLXPbuffer pb = glXCreatePbuffer(dpy, c, attribs);
  ASSERT_NE(pb, static_cast<GLXPbuffer>(None));
  unsigned int w = 0, h = 0, id = 0;
  glXQueryDrawable(dpy, pb, GLX_WIDTH, &w);
  glXQueryDrawable(dpy, pb, GLX_HEIGHT, &h);
  glXQueryDrawable(dpy, pb, GLX_FBCONFIG_ID, &id);
  EXPECT_EQ(w, 40u);
  EXPECT_EQ(h, 30u);
  EXPECT_EQ(static_cast<int>(id), attrib(c, GLX_FBCONFIG_ID));
  GLXContext ctx = glXCreateNewContext(dpy, c, GLX_RGBA_TYPE, nullptr, True);
  ASSERT_TRUE(glXMakeContextCurrent(dpy, pb, pb, ctx));
  draw_scene();
  GLubyte px[4] = {};
  glReadPixels(20, 15, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_EQ(px[0], 255);
  EXPECT_EQ(px[2], 0);
  glReadPixels(1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_EQ(px[2], 255);
  EXPECT_EQ(px[3], 255);
  ASSERT_TRUE(glXMakeContextCurrent(dpy, None, None, nullptr));
  glXDestroyPbuffer(dpy, pb);
  glXDestroyContext(dpy, ctx);
  EXPECT_EQ(g_error_count, 0);
}

TEST_F(Glx, AccumulationBufferInAPbuffer) {
  GLXFBConfig c = choose({GLX_DRAWABLE_TYPE, GLX_PBUFFER_BIT, GLX_ACCUM_RED_SIZE, 16});
  ASSERT_NE(c, nullptr);
  const int attribs[] = {GLX_PBUFFER_WIDTH, 16, GLX_PBUFFER_HEIGHT, 16, None};
  GLXPbuffer pb = glXCreatePbuffer(dpy, c, attribs);
  GLXContext ctx = glXCreateNewContext(dpy, c, GLX_RGBA_TYPE, nullptr, True);
  ASSERT_TRUE(glXMakeContextCurrent(dpy, pb, pb, ctx));
  GLint bits = 0;
  glGetIntegerv(GL_ACCUM_RED_BITS, &bits);
  EXPECT_EQ(bits, 16);
  // GL 2.1 §4.2.4: half of red plus half of blue, returned.
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glAccum(GL_LOAD, 0.5f);
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glAccum(GL_ACCUM, 0.5f);
  glAccum(GL_RETURN, 1.0f);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  GLubyte px[4] = {};
  glReadPixels(3, 3, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
  EXPECT_NEAR(px[0], 127, 1);
  EXPECT_EQ(px[1], 0);
  EXPECT_NEAR(px[2], 127, 1);
  ASSERT_TRUE(glXMakeContextCurrent(dpy, None, None, nullptr));
  glXDestroyPbuffer(dpy, pb);
  glXDestroyContext(dpy, ctx);
  EXPECT_EQ(g_error_count, 0);
}

TEST_F(Glx, CreateContextAttribs) {
  GLXFBConfig c = choose({});
  ASSERT_NE(c, nullptr);
  const int v11[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 1, GLX_CONTEXT_MINOR_VERSION_ARB, 1, None};
  GLXContext ctx = glXCreateContextAttribsARB(dpy, c, nullptr, True, v11);
  EXPECT_NE(ctx, nullptr);
  EXPECT_EQ(g_error_count, 0);
  glXDestroyContext(dpy, ctx);
  // GL 2.0 and 2.1, what glGetString(GL_VERSION) claims, are given.
  for (const int minor : {0, 1}) {
    const int v2[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 2, GLX_CONTEXT_MINOR_VERSION_ARB, minor, None};
    GLXContext ok = glXCreateContextAttribsARB(dpy, c, nullptr, True, v2);
    EXPECT_NE(ok, nullptr) << "2." << minor;
    glXDestroyContext(dpy, ok);
  }
  EXPECT_EQ(g_error_count, 0);
  // Beyond what glGetString(GL_VERSION) claims: GLXBadFBConfig.
  const int v30[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 3, GLX_CONTEXT_MINOR_VERSION_ARB, 0, None};
  EXPECT_EQ(glXCreateContextAttribsARB(dpy, c, nullptr, True, v30), nullptr);
  XSync(dpy, False);
  EXPECT_EQ(g_error_count, 1);
  const int v33[] = {GLX_CONTEXT_MAJOR_VERSION_ARB,
                     3,
                     GLX_CONTEXT_MINOR_VERSION_ARB,
                     3,
                     GLX_CONTEXT_PROFILE_MASK_ARB,
                     GLX_CONTEXT_CORE_PROFILE_BIT_ARB,
                     None};
  EXPECT_EQ(glXCreateContextAttribsARB(dpy, c, nullptr, True, v33), nullptr);
  XSync(dpy, False);
  EXPECT_EQ(g_error_count, 2);
  // A version that does not exist: BadMatch.
  const int v17[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 1, GLX_CONTEXT_MINOR_VERSION_ARB, 7, None};
  EXPECT_EQ(glXCreateContextAttribsARB(dpy, c, nullptr, True, v17), nullptr);
  EXPECT_EQ(g_last_error, BadMatch);
  const int bad[] = {0x7777, 1, None};
  EXPECT_EQ(glXCreateContextAttribsARB(dpy, c, nullptr, True, bad), nullptr);
  EXPECT_EQ(g_last_error, BadValue);
}

TEST_F(Glx, ShareLists) {
  GLXFBConfig c = choose({GLX_DRAWABLE_TYPE, GLX_PBUFFER_BIT});
  const int attribs[] = {GLX_PBUFFER_WIDTH, 8, GLX_PBUFFER_HEIGHT, 8, None};
  GLXPbuffer pb = glXCreatePbuffer(dpy, c, attribs);
  GLXContext a = glXCreateNewContext(dpy, c, GLX_RGBA_TYPE, nullptr, True);
  GLXContext b = glXCreateNewContext(dpy, c, GLX_RGBA_TYPE, a, True);
  GLXContext alone = glXCreateNewContext(dpy, c, GLX_RGBA_TYPE, nullptr, True);
  ASSERT_TRUE(glXMakeContextCurrent(dpy, pb, pb, a));
  GLuint name = 0;
  glGenBuffers(1, &name);
  glBindBuffer(GL_ARRAY_BUFFER, name);
  ASSERT_TRUE(glIsBuffer(name));
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glTranslatef(3, 0, 0);
  glEndList();
  // §3.3.7: a context created with a share list sees the group's objects (buffer objects
  // and display lists); others do not.
  ASSERT_TRUE(glXMakeContextCurrent(dpy, pb, pb, b));
  EXPECT_TRUE(glIsBuffer(name));
  EXPECT_TRUE(glIsList(list));
  glCallList(list);
  GLfloat m[16] = {};
  glGetFloatv(GL_MODELVIEW_MATRIX, m);
  EXPECT_EQ(m[12], 3.0f);
  ASSERT_TRUE(glXMakeContextCurrent(dpy, pb, pb, alone));
  EXPECT_FALSE(glIsBuffer(name));
  EXPECT_FALSE(glIsList(list));
  // The group outlives the context that created it.
  glXMakeContextCurrent(dpy, None, None, nullptr);
  glXDestroyContext(dpy, a);
  ASSERT_TRUE(glXMakeContextCurrent(dpy, pb, pb, b));
  EXPECT_TRUE(glIsBuffer(name));
  glXMakeContextCurrent(dpy, None, None, nullptr);
  glXDestroyContext(dpy, b);
  glXDestroyContext(dpy, alone);
  glXDestroyPbuffer(dpy, pb);
  EXPECT_EQ(g_error_count, 0);
}

TEST_F(Glx, Errors) {
  GLXFBConfig c = choose({});
  GLXContext ctx = glXCreateNewContext(dpy, c, GLX_RGBA_TYPE, nullptr, True);
  ASSERT_NE(ctx, nullptr);
  // A drawable that does not exist.
  EXPECT_FALSE(glXMakeCurrent(dpy, 0x7fffff, ctx));
  EXPECT_GE(g_error_count, 1);
  // A context without drawables.
  g_error_count = 0;
  EXPECT_FALSE(glXMakeContextCurrent(dpy, None, None, ctx));
  EXPECT_EQ(g_last_error, BadMatch);
  // A window of another visual is BadMatch.
  Window win = make_window(c, 16, 16);
  GLXFBConfig other = nullptr;
  int n = 0;
  GLXFBConfig* all = glXGetFBConfigs(dpy, DefaultScreen(dpy), &n);
  for (int i = 0; i < n && other == nullptr; ++i)
    if (attrib(all[i], GLX_VISUAL_ID) != attrib(c, GLX_VISUAL_ID)) other = all[i];
  XFree(all);
  if (other != nullptr) {
    GLXContext ctx2 = glXCreateNewContext(dpy, other, GLX_RGBA_TYPE, nullptr, True);
    g_last_error = 0;
    EXPECT_FALSE(glXMakeCurrent(dpy, win, ctx2));
    EXPECT_EQ(g_last_error, BadMatch);
    glXDestroyContext(dpy, ctx2);
  }
  // A context current in another thread cannot be made current here (BadAccess).
  ASSERT_TRUE(glXMakeCurrent(dpy, win, ctx));
  g_last_error = 0;
  std::thread([&] { EXPECT_FALSE(glXMakeCurrent(dpy, win, ctx)); }).join();
  EXPECT_EQ(g_last_error, BadAccess);
  // Destroying a current context defers the destruction; it stays usable until released.
  glXDestroyContext(dpy, ctx);
  EXPECT_EQ(glXGetCurrentContext(), ctx);
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_TRUE(glXMakeCurrent(dpy, None, nullptr));
  // GL commands without a current context do nothing.
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(Glx, ProcAddress) {
  EXPECT_EQ(glXGetProcAddressARB(reinterpret_cast<const GLubyte*>("glXSwapBuffers")),
            reinterpret_cast<__GLXextFuncPtr>(&glXSwapBuffers));
  EXPECT_EQ(glXGetProcAddress(reinterpret_cast<const GLubyte*>("glClear")),
            reinterpret_cast<__GLXextFuncPtr>(&glClear));
  EXPECT_NE(glXGetProcAddress(reinterpret_cast<const GLubyte*>("glXCreateContextAttribsARB")),
            nullptr);
  EXPECT_EQ(glXGetProcAddress(reinterpret_cast<const GLubyte*>("glNoSuchThing")), nullptr);
}

} // namespace
