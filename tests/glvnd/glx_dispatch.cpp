// Pineda's GLX vendor library behind glvnd's libGL.so.1: GLX extension functions outside
// libGLX's static table reach Pineda through dispatch stubs with dynamically assigned slots
// (glXSwapIntervalEXT by drawable, glXSwapIntervalMESA and glXGetSwapIntervalMESA by current
// context), glXCreateContextAttribsARB through libGLX's table, and GL extension functions
// through libGLdispatch's stubs (glBindBufferARB, glXGetProcAddress). Exits 0 when all hold.
// Run under tests/glx/run_with_xvfb.sh with __GLX_VENDOR_LIBRARY_NAME=pineda.
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/glx.h>
#include <GL/glxext.h>
#include <X11/Xlib.h>

#include <cstdio>
#include <cstring>

namespace {

int failures = 0;

void check(bool ok, const char* what) {
  std::printf("%s: %s\n", ok ? "ok" : "FAILED", what);
  if (!ok) ++failures;
}

template <typename F> F proc(const char* name) {
  return reinterpret_cast<F>(glXGetProcAddress(reinterpret_cast<const GLubyte*>(name)));
}

} // namespace

int main() {
  Display* dpy = XOpenDisplay(nullptr);
  if (dpy == nullptr) return 1;
  const int fb_attribs[] = {GLX_DOUBLEBUFFER, True, GLX_DRAWABLE_TYPE, GLX_WINDOW_BIT, None};
  int n = 0;
  GLXFBConfig* configs = glXChooseFBConfig(dpy, DefaultScreen(dpy), fb_attribs, &n);
  if (configs == nullptr || n == 0) return 1;
  XVisualInfo* vi = glXGetVisualFromFBConfig(dpy, configs[0]);
  XSetWindowAttributes swa{};
  swa.colormap = XCreateColormap(dpy, RootWindow(dpy, vi->screen), vi->visual, AllocNone);
  Window win = XCreateWindow(dpy, RootWindow(dpy, vi->screen), 0, 0, 64, 64, 0, vi->depth,
                             InputOutput, vi->visual, CWColormap, &swa);
  GLXWindow glxwin = glXCreateWindow(dpy, configs[0], win, nullptr);

  auto create = proc<PFNGLXCREATECONTEXTATTRIBSARBPROC>("glXCreateContextAttribsARB");
  check(create != nullptr, "glXGetProcAddress(glXCreateContextAttribsARB)");
  const int ctx_attribs[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 1, GLX_CONTEXT_MINOR_VERSION_ARB, 3,
                             None};
  GLXContext ctx =
      create != nullptr ? create(dpy, configs[0], nullptr, True, ctx_attribs) : nullptr;
  check(ctx != nullptr, "glXCreateContextAttribsARB(1.3)");
  check(ctx != nullptr && glXMakeContextCurrent(dpy, glxwin, glxwin, ctx), "glXMakeContextCurrent");
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  check(renderer != nullptr && std::strncmp(renderer, "Pineda", 6) == 0, "GL_RENDERER is Pineda");

  auto swap_ext = proc<PFNGLXSWAPINTERVALEXTPROC>("glXSwapIntervalEXT");
  auto swap_mesa = proc<PFNGLXSWAPINTERVALMESAPROC>("glXSwapIntervalMESA");
  auto get_mesa = proc<PFNGLXGETSWAPINTERVALMESAPROC>("glXGetSwapIntervalMESA");
  check(swap_ext != nullptr && swap_mesa != nullptr && get_mesa != nullptr,
        "glXGetProcAddress of the swap-control functions");
  if (swap_ext != nullptr && get_mesa != nullptr) {
    swap_ext(dpy, glxwin, 3);
    unsigned value = 0;
    glXQueryDrawable(dpy, glxwin, GLX_SWAP_INTERVAL_EXT, &value);
    check(value == 3, "glXSwapIntervalEXT(3) reaches Pineda (GLX_SWAP_INTERVAL_EXT)");
    check(get_mesa() == 3, "glXGetSwapIntervalMESA() == 3");
  }
  if (swap_mesa != nullptr && get_mesa != nullptr) {
    check(swap_mesa(0) == 0, "glXSwapIntervalMESA(0)");
    check(get_mesa() == 0, "glXGetSwapIntervalMESA() == 0");
  }
  // A GL extension function through libGLdispatch: an ARB alias Pineda exports.
  auto gen = proc<PFNGLGENBUFFERSARBPROC>("glGenBuffersARB");
  auto bind = proc<PFNGLBINDBUFFERARBPROC>("glBindBufferARB");
  auto is = proc<PFNGLISBUFFERARBPROC>("glIsBufferARB");
  check(gen != nullptr && bind != nullptr && is != nullptr, "glXGetProcAddress of ARB functions");
  if (gen != nullptr && bind != nullptr && is != nullptr) {
    GLuint buffer = 0;
    gen(1, &buffer);
    bind(GL_ARRAY_BUFFER_ARB, buffer);
    check(buffer != 0 && is(buffer), "glGenBuffersARB/glBindBufferARB/glIsBufferARB");
  }
  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glXSwapBuffers(dpy, glxwin);
  check(glGetError() == GL_NO_ERROR, "no GL error");
  glXMakeContextCurrent(dpy, None, None, nullptr);
  glXDestroyContext(dpy, ctx);
  glXDestroyWindow(dpy, glxwin);
  XDestroyWindow(dpy, win);
  XFree(vi);
  XFree(configs);
  XCloseDisplay(dpy);
  return failures == 0 ? 0 : 1;
}
