// Waits for a top-level X window whose title contains TEXT, prints the title and sends it the
// ESC key (a KeyPress and a KeyRelease through XSendEvent), which closes a demo in window mode.
// With X and Y, first moves the pointer there (window pixels) and clicks the left button.
//   x_escape TEXT [SECONDS [PID [X Y]]]
// Exit status 0 when the window was found and the key sent, 1 when no such window appeared
// within SECONDS (default 20; the titles seen are printed) or process PID (the program expected
// to open the window) ended first, 2 when the display cannot be opened.
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <X11/keysym.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <csignal>
#include <set>
#include <string>
#include <thread>

#include <sys/types.h>

namespace {

// The first top-level window (a child of the root: there is no window manager) with TEXT in
// its WM_NAME.
Window find_window(Display* dpy, const char* text, std::set<std::string>& seen,
                   std::string& title) {
  Window root_return = 0, parent = 0;
  Window* children = nullptr;
  unsigned count = 0;
  Window found = 0;
  if (XQueryTree(dpy, DefaultRootWindow(dpy), &root_return, &parent, &children, &count) == 0)
    return 0;
  for (unsigned i = 0; i < count && found == 0; ++i) {
    char* name = nullptr;
    if (XFetchName(dpy, children[i], &name) == 0 || name == nullptr) continue;
    seen.insert(name);
    if (std::strstr(name, text) != nullptr) {
      found = children[i];
      title = name;
    }
    XFree(name);
  }
  if (children != nullptr) XFree(children);
  return found;
}

void send_click(Display* dpy, Window w, int x, int y) {
  // The pointer itself moves (the program may ask the server where it is), then the button.
  XWarpPointer(dpy, None, w, 0, 0, 0, 0, x, y);
  XSync(dpy, False);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  for (const int type : {ButtonPress, ButtonRelease}) {
    XButtonEvent ev;
    std::memset(&ev, 0, sizeof ev);
    ev.type = type;
    ev.display = dpy;
    ev.window = w;
    ev.root = DefaultRootWindow(dpy);
    ev.time = CurrentTime;
    ev.x = x;
    ev.y = y;
    ev.same_screen = True;
    ev.button = Button1;
    ev.state = type == ButtonRelease ? Button1Mask : 0;
    XSendEvent(dpy, w, True, type == ButtonPress ? ButtonPressMask : ButtonReleaseMask,
               reinterpret_cast<XEvent*>(&ev));
  }
  XSync(dpy, False);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
}

void send_key(Display* dpy, Window w, int type, unsigned keycode) {
  XKeyEvent ev;
  std::memset(&ev, 0, sizeof ev);
  ev.type = type;
  ev.display = dpy;
  ev.window = w;
  ev.root = DefaultRootWindow(dpy);
  ev.subwindow = None;
  ev.time = CurrentTime;
  ev.same_screen = True;
  ev.keycode = keycode;
  XSendEvent(dpy, w, True, type == KeyPress ? KeyPressMask : KeyReleaseMask,
             reinterpret_cast<XEvent*>(&ev));
}

} // namespace

int main(int argc, char** argv) {
  if (argc < 2 || argc > 6 || argc == 5) {
    std::fprintf(stderr, "usage: x_escape TEXT [SECONDS [PID [X Y]]]\n");
    return 2;
  }
  const double seconds = argc >= 3 ? std::atof(argv[2]) : 20.0;
  const pid_t pid = argc >= 4 ? static_cast<pid_t>(std::atol(argv[3])) : 0;
  Display* dpy = XOpenDisplay(nullptr);
  if (dpy == nullptr) {
    std::fprintf(stderr, "x_escape: cannot open the display\n");
    return 2;
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  std::set<std::string> seen;
  std::string title;
  Window w = 0;
  while ((w = find_window(dpy, argv[1], seen, title)) == 0 &&
         std::chrono::steady_clock::now() < deadline && (pid <= 0 || kill(pid, 0) == 0))
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  if (w == 0) {
    std::fprintf(stderr,
                 "x_escape: no window titled \"...%s...\" within %.0f s (or the program ended "
                 "first); titles seen:\n",
                 argv[1], seconds);
    for (const auto& s : seen)
      std::fprintf(stderr, "  \"%s\"\n", s.c_str());
    XCloseDisplay(dpy);
    return 1;
  }
  std::printf("x_escape: window title \"%s\"\n", title.c_str());
  if (argc == 6) send_click(dpy, w, std::atoi(argv[4]), std::atoi(argv[5]));
  const unsigned keycode = XKeysymToKeycode(dpy, XK_Escape);
  send_key(dpy, w, KeyPress, keycode);
  send_key(dpy, w, KeyRelease, keycode);
  XFlush(dpy);
  XCloseDisplay(dpy);
  return 0;
}
