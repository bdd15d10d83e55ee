// egl_scene KIND OUT.png: renders one small scene through EGL into a surface of KIND and writes
// what the surface holds as a PNG, so that the same program on Pineda and on Mesa can be
// compared (tests/egl/CMakeLists.txt). An ordinary program linked with glvnd's libEGL and
// libOpenGL; which EGL vendor runs it is the environment's choice.
//   window      an X window, read back from the X server after eglSwapBuffers
//   pixmap      an X pixmap, read back from the X server after glFinish
//   pbuffer     a pbuffer of the X11 platform, read with glReadPixels
//   surfaceless a pbuffer of the surfaceless platform (no X server), read with glReadPixels
// Prints the EGL vendor and GL_RENDERER; exits 1 on any failure.
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "png_write.h"

namespace {

constexpr int kWidth = 160, kHeight = 120;

int die(const char* what) {
  std::fprintf(stderr, "egl_scene: %s failed (EGL error 0x%04x)\n", what, eglGetError());
  return 1;
}

// Overlapping smooth-shaded triangles with depth testing, a lit sphere-like fan and a blended
// quad: rasterization, interpolation, lighting, depth and blending in one picture.
void draw() {
  glViewport(0, 0, kWidth, kHeight);
  glClearColor(0.1f, 0.2f, 0.3f, 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-1, 1, -0.75, 0.75, 1.5, 10);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(0, 0, -4);
  glBegin(GL_TRIANGLES);
  glColor3f(1, 0, 0);
  glVertex3f(-1.5f, -1, 0.5f);
  glColor3f(0, 1, 0);
  glVertex3f(1.2f, -0.8f, -0.5f);
  glColor3f(0, 0, 1);
  glVertex3f(0, 1.3f, 0);
  glColor3f(1, 1, 0);
  glVertex3f(-1.2f, 0.9f, -0.6f);
  glColor3f(0, 1, 1);
  glVertex3f(1.4f, 0.6f, 0.6f);
  glColor3f(1, 0, 1);
  glVertex3f(0.2f, -1.2f, 0.1f);
  glEnd();
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_NORMALIZE);
  const GLfloat light[] = {1, 1, 2, 0};
  glLightfv(GL_LIGHT0, GL_POSITION, light);
  const GLfloat mat[] = {0.8f, 0.7f, 0.2f, 1};
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, mat);
  glPushMatrix();
  glTranslatef(0.9f, -0.3f, 0.8f);
  for (int i = 0; i < 8; ++i) {
    const float a0 = static_cast<float>(i) / 8 * 3.14159265f,
                a1 = static_cast<float>(i + 1) / 8 * 3.14159265f;
    glBegin(GL_QUAD_STRIP);
    for (int j = 0; j <= 16; ++j) {
      const float b = static_cast<float>(j) / 16 * 6.2831853f;
      for (float a : {a0, a1}) {
        const float x = std::sin(a) * std::cos(b), y = std::cos(a), z = std::sin(a) * std::sin(b);
        glNormal3f(x, y, z);
        glVertex3f(0.45f * x, 0.45f * y, 0.45f * z);
      }
    }
    glEnd();
  }
  glPopMatrix();
  glDisable(GL_LIGHTING);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glColor4f(1, 1, 1, 0.4f);
  glRectf(-1.8f, -0.2f, -0.2f, 0.4f);
  glDisable(GL_BLEND);
  glFinish();
}

bool write_from_gl(const char* path) {
  std::vector<std::uint8_t> rgba(static_cast<size_t>(kWidth) * kHeight * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  return demo::write_png(path, kWidth, kHeight, rgba);
}

// An X drawable's pixels as bottom-up RGBA (png_write's order).
bool write_from_x(Display* x, Drawable d, const char* path) {
  XImage* img = XGetImage(x, d, 0, 0, kWidth, kHeight, AllPlanes, ZPixmap);
  if (img == nullptr) return false;
  std::vector<std::uint8_t> rgba(static_cast<size_t>(kWidth) * kHeight * 4);
  for (int y = 0; y < kHeight; ++y)
    for (int px = 0; px < kWidth; ++px) {
      const unsigned long p = XGetPixel(img, px, y);
      std::uint8_t* o = &rgba[(static_cast<size_t>(kHeight - 1 - y) * kWidth + px) * 4];
      o[0] = static_cast<std::uint8_t>((p & img->red_mask) >> __builtin_ctzl(img->red_mask));
      o[1] = static_cast<std::uint8_t>((p & img->green_mask) >> __builtin_ctzl(img->green_mask));
      o[2] = static_cast<std::uint8_t>((p & img->blue_mask) >> __builtin_ctzl(img->blue_mask));
      o[3] = 255;
    }
  XDestroyImage(img);
  return demo::write_png(path, kWidth, kHeight, rgba);
}

} // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: egl_scene window|pixmap|pbuffer|surfaceless OUT.png\n");
    return 2;
  }
  const std::string kind = argv[1];
  const char* out = argv[2];
  const bool surfaceless = kind == "surfaceless";
  Display* x = nullptr;
  EGLDisplay dpy;
  if (surfaceless) {
    dpy = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  } else {
    x = XOpenDisplay(nullptr);
    if (x == nullptr) return die("XOpenDisplay");
    dpy = eglGetPlatformDisplay(EGL_PLATFORM_X11_KHR, x, nullptr);
  }
  if (dpy == EGL_NO_DISPLAY) return die("eglGetPlatformDisplay");
  if (!eglInitialize(dpy, nullptr, nullptr)) return die("eglInitialize");
  if (!eglBindAPI(EGL_OPENGL_API)) return die("eglBindAPI");
  const EGLint type = kind == "window"   ? EGL_WINDOW_BIT
                      : kind == "pixmap" ? EGL_PIXMAP_BIT
                                         : EGL_PBUFFER_BIT;
  const EGLint want[] = {EGL_SURFACE_TYPE, type,         EGL_RENDERABLE_TYPE,
                         EGL_OPENGL_BIT,   EGL_RED_SIZE, 8,
                         EGL_DEPTH_SIZE,   24,           EGL_NONE};
  EGLConfig config = nullptr;
  EGLint n = 0;
  if (!eglChooseConfig(dpy, want, &config, 1, &n) || n < 1) return die("eglChooseConfig");
  EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, nullptr);
  if (ctx == EGL_NO_CONTEXT) return die("eglCreateContext");
  EGLSurface surface = EGL_NO_SURFACE;
  Drawable drawable = 0;
  if (type == EGL_PBUFFER_BIT) {
    const EGLint a[] = {EGL_WIDTH, kWidth, EGL_HEIGHT, kHeight, EGL_NONE};
    surface = eglCreatePbufferSurface(dpy, config, a);
  } else {
    EGLint visual_id = 0;
    eglGetConfigAttrib(dpy, config, EGL_NATIVE_VISUAL_ID, &visual_id);
    XVisualInfo tmpl{};
    tmpl.visualid = static_cast<VisualID>(visual_id);
    int count = 0;
    XVisualInfo* vi = XGetVisualInfo(x, VisualIDMask, &tmpl, &count);
    if (vi == nullptr) return die("XGetVisualInfo");
    if (type == EGL_WINDOW_BIT) {
      XSetWindowAttributes swa{};
      swa.colormap = XCreateColormap(x, DefaultRootWindow(x), vi->visual, AllocNone);
      swa.border_pixel = 0;
      Window win = XCreateWindow(x, DefaultRootWindow(x), 0, 0, kWidth, kHeight, 0, vi->depth,
                                 InputOutput, vi->visual, CWColormap | CWBorderPixel, &swa);
      XMapWindow(x, win);
      XSync(x, False);
      drawable = win;
      surface = eglCreatePlatformWindowSurface(dpy, config, &win, nullptr);
    } else {
      Pixmap pm =
          XCreatePixmap(x, DefaultRootWindow(x), kWidth, kHeight, static_cast<unsigned>(vi->depth));
      drawable = pm;
      surface = eglCreatePlatformPixmapSurface(dpy, config, &pm, nullptr);
    }
    XFree(vi);
  }
  if (surface == EGL_NO_SURFACE) return die("creating the surface");
  if (!eglMakeCurrent(dpy, surface, surface, ctx)) return die("eglMakeCurrent");
  std::printf("EGL_VENDOR: %s\nGL_RENDERER: %s\n", eglQueryString(dpy, EGL_VENDOR),
              reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
  draw();
  bool ok = false;
  if (type == EGL_WINDOW_BIT) {
    if (!eglSwapBuffers(dpy, surface)) return die("eglSwapBuffers");
    XSync(x, False);
    ok = write_from_x(x, drawable, out);
  } else if (type == EGL_PIXMAP_BIT) {
    eglWaitClient();
    XSync(x, False);
    ok = write_from_x(x, drawable, out);
  } else {
    ok = write_from_gl(out);
  }
  if (glGetError() != GL_NO_ERROR) return die("rendering (a GL error)");
  eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroySurface(dpy, surface);
  eglDestroyContext(dpy, ctx);
  eglTerminate(dpy);
  if (x != nullptr) XCloseDisplay(x);
  return ok ? 0 : 1;
}
