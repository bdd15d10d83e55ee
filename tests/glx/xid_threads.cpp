// GLX resource ids in a program that called XInitThreads and allocates X ids of its own in
// between (as SDL2 does): Pineda's GLX ids must not take Xlib's prefetched id, which tripped
// Xlib's assertion "_XAllocID: ret != inval_id" in SDL2 programs. Exits 0 when every call
// succeeded. Run under tests/glx/run_with_xvfb.sh.
#include <GL/glx.h>
#include <X11/Xlib.h>

#include <cstdio>

int main() {
  XInitThreads();
  Display* dpy = XOpenDisplay(nullptr);
  if (dpy == nullptr) return 1;
  int attribs[] = {GLX_RGBA, GLX_DOUBLEBUFFER, GLX_DEPTH_SIZE, 16, None};
  XVisualInfo* vi = glXChooseVisual(dpy, DefaultScreen(dpy), attribs);
  if (vi == nullptr) return 1;
  XSetWindowAttributes swa{};
  swa.colormap = XCreateColormap(dpy, RootWindow(dpy, vi->screen), vi->visual, AllocNone);
  int made = 0;
  for (int i = 0; i < 4; ++i) {
    // An application id, then GLX ids, then another application id, in turn.
    Window win = XCreateWindow(dpy, RootWindow(dpy, vi->screen), 0, 0, 32, 32, 0, vi->depth,
                               InputOutput, vi->visual, CWColormap, &swa);
    GLXContext a = glXCreateContext(dpy, vi, nullptr, True);
    GLXContext b = glXCreateContext(dpy, vi, a, True);
    Pixmap pm = XCreatePixmap(dpy, win, 8, 8, static_cast<unsigned>(vi->depth));
    GLXPixmap gp = glXCreateGLXPixmap(dpy, vi, pm);
    if (a != nullptr && b != nullptr && gp != None && glXMakeCurrent(dpy, win, b)) ++made;
    glXMakeCurrent(dpy, None, nullptr);
    glXDestroyGLXPixmap(dpy, gp);
    XFreePixmap(dpy, pm);
    glXDestroyContext(dpy, b);
    glXDestroyContext(dpy, a);
    XDestroyWindow(dpy, win);
  }
  XFree(vi);
  XCloseDisplay(dpy);
  std::printf("xid_threads: %d of 4 rounds\n", made);
  return made == 4 ? 0 : 1;
}
