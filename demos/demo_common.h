// Shared by the GLFW demos: argument parsing, the window (FPS in the title, ESC quits), the
// headless mode (--frames N --screenshot out.png) with a frame-index clock so that two GL
// implementations render the same pictures, PNG screenshots through glReadPixels + libpng, and
// the small bits of matrix and texture arithmetic GL 1.x leaves to GLU (no GLU here: the demos
// need nothing but libGL and GLFW).
//
// The demos are ordinary programs linked against the system's libGL.so.1: run them on Pineda
// with LD_LIBRARY_PATH=<build>/lib, on Mesa without.
#pragma once

#include "png_write.h"

#include <GL/gl.h>
#include <GLFW/glfw3.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

namespace demo {

constexpr double kPi = 3.14159265358979323846;
// Headless frames advance the animation by a fixed step: frame i shows time i / 60 s.
constexpr double kHeadlessFrameTime = 1.0 / 60.0;

struct Frame {
  int index = 0;     // frames drawn before this one
  double time = 0.0; // animation time in seconds (wall clock in a window, index / 60 headless)
  int width = 0;     // framebuffer size in pixels
  int height = 0;
  bool headless = false;
  int frames = 0; // headless: how many frames are drawn (the last one is frames - 1)
};

// One demo. The runner owns the window and the context; the demo draws.
class App {
public:
  virtual ~App() = default;
  // Called once with the context current, before the first frame.
  virtual void init() {}
  // Draws one frame into the back buffer.
  virtual void draw(const Frame& frame) = 0;
  // Window-mode input (GLFW key codes; positions in window pixels, origin top left).
  virtual void key(int /*key*/) {}
  virtual void mouse_button(int /*button*/, bool /*pressed*/, double /*x*/, double /*y*/) {}
  virtual void cursor(double /*x*/, double /*y*/) {}
  virtual void scroll(double /*dy*/) {}
};

// A demo-specific option: "--name VALUE" (or a bare flag when arg is empty). set() returns
// false when VALUE is not acceptable; the runner then prints the usage.
struct ExtraOption {
  std::string name;
  std::string arg;
  std::string help;
  std::function<bool(const char*)> set;
};

struct Options {
  int frames = 0; // > 0: headless mode
  std::string screenshot;
  int width = 640;
  int height = 480;
  bool verbose = false;
  bool egl = false; // GLFW's EGL context API instead of GLX
};

// ---------------------------------------------------------------------------------------------
// Arithmetic helpers.

struct Vec3 {
  float x = 0, y = 0, z = 0;
};
inline Vec3 operator+(Vec3 a, Vec3 b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline Vec3 operator-(Vec3 a, Vec3 b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline Vec3 operator*(Vec3 a, float s) {
  return {a.x * s, a.y * s, a.z * s};
}
inline float dot(Vec3 a, Vec3 b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline Vec3 normalize(Vec3 a) {
  const float len = std::sqrt(dot(a, a));
  return len > 0.0f ? a * (1.0f / len) : Vec3{0, 0, 1};
}

// gluPerspective's frustum, through glFrustum.
inline void perspective(double fovy_degrees, double aspect, double znear, double zfar) {
  const double top = znear * std::tan(fovy_degrees * kPi / 360.0);
  glFrustum(-top * aspect, top * aspect, -top, top, znear, zfar);
}

// gluLookAt's rotation and translation, multiplied onto the current matrix.
inline void look_at(Vec3 eye, Vec3 center, Vec3 up) {
  const Vec3 f = normalize(center - eye);
  const Vec3 s = normalize(cross(f, up));
  const Vec3 u = cross(s, f);
  const GLfloat m[16] = {s.x, u.x, -f.x, 0, s.y, u.y, -f.y, 0, s.z, u.z, -f.z, 0, 0, 0, 0, 1};
  glMultMatrixf(m);
  glTranslatef(-eye.x, -eye.y, -eye.z);
}

// A small deterministic generator (xorshift32), so every run builds the same scene.
class Rng {
public:
  explicit Rng(std::uint32_t seed) : state_(seed != 0 ? seed : 0x9e3779b9u) {}
  std::uint32_t next_u32() {
    state_ ^= state_ << 13;
    state_ ^= state_ >> 17;
    state_ ^= state_ << 5;
    return state_;
  }
  // Uniform in [0, 1).
  float uniform() { return static_cast<float>(next_u32() >> 8) * (1.0f / 16777216.0f); }
  float range(float lo, float hi) { return lo + (hi - lo) * uniform(); }

private:
  std::uint32_t state_;
};

// Uploads a square RGBA8 image of side `size` (a power of two) with its whole mipmap chain,
// each level a 2x2 box filter of the one above (what gluBuild2DMipmaps does for such sizes).
inline void upload_mipmapped_rgba(int size, std::vector<std::uint8_t> level) {
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  for (int lod = 0;; ++lod) {
    glTexImage2D(GL_TEXTURE_2D, lod, GL_RGBA, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 level.data());
    if (size == 1) break;
    const int half = size / 2;
    std::vector<std::uint8_t> next(static_cast<size_t>(half) * half * 4);
    for (int y = 0; y < half; ++y)
      for (int x = 0; x < half; ++x)
        for (int c = 0; c < 4; ++c) {
          const auto at = [&](int xx, int yy) {
            return static_cast<int>(level[(static_cast<size_t>(yy) * size + xx) * 4 + c]);
          };
          const int sum = at(2 * x, 2 * y) + at(2 * x + 1, 2 * y) + at(2 * x, 2 * y + 1) +
                          at(2 * x + 1, 2 * y + 1);
          next[(static_cast<size_t>(y) * half + x) * 4 + c] =
              static_cast<std::uint8_t>((sum + 2) / 4);
        }
    level = std::move(next);
    size = half;
  }
}

// ---------------------------------------------------------------------------------------------
// Screenshots.

// Reads the back buffer (before the swap) and writes it to `path`.
inline bool screenshot(const std::string& path, int width, int height) {
  std::vector<std::uint8_t> rgba(static_cast<size_t>(width) * height * 4);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  return write_png(path, width, height, rgba);
}

// ---------------------------------------------------------------------------------------------
// Arguments.

namespace detail {

inline void usage(FILE* out, const char* name, const std::vector<ExtraOption>& extra) {
  std::fprintf(out,
               "usage: %s [options]\n"
               "  (no options)        open a window; ESC quits, the title shows the FPS\n"
               "  --frames N          headless: render N frames (frame i at time i/60 s) into a\n"
               "                      hidden window\n"
               "  --screenshot FILE   headless: write the last frame as a PNG (needs --frames)\n"
               "  --size WxH          framebuffer size (default 640x480)\n"
               "  --verbose           print GL_RENDERER, GL_VERSION and GL_VENDOR\n"
               "  --egl               create the context through EGL instead of GLX\n",
               name);
  for (const auto& e : extra) {
    const std::string flag = e.name + (e.arg.empty() ? "" : " " + e.arg);
    std::fprintf(out, "  %-19s %s\n", flag.c_str(), e.help.c_str());
  }
  std::fprintf(out, "  --help              this text\n");
}

inline bool parse_int(const char* text, int lo, int hi, int& out) {
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(text, &end, 10);
  if (errno != 0 || end == text || *end != '\0' || v < lo || v > hi) return false;
  out = static_cast<int>(v);
  return true;
}

} // namespace detail

// Parses the common options and the demo's own. Returns -1 to go on, or an exit status (0 for
// --help, 2 for a bad argument, after a message naming the problem).
inline int parse_args(const char* name, int argc, char** argv, Options& opt,
                      const std::vector<ExtraOption>& extra) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto value = [&](const char* what) -> const char* {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "%s: %s needs %s\n", name, a.c_str(), what);
        return nullptr;
      }
      return argv[++i];
    };
    const auto bad = [&](const char* v, const char* what) {
      std::fprintf(stderr, "%s: %s expects %s, got '%s'\n", name, a.c_str(), what, v);
      detail::usage(stderr, name, extra);
      return 2;
    };
    if (a == "--help" || a == "-h") {
      detail::usage(stdout, name, extra);
      return 0;
    } else if (a == "--frames") {
      const char* v = value("a frame count");
      if (v == nullptr) return 2;
      if (!detail::parse_int(v, 1, 10000000, opt.frames)) return bad(v, "a positive integer");
    } else if (a == "--screenshot") {
      const char* v = value("a file name");
      if (v == nullptr) return 2;
      if (*v == '\0') return bad(v, "a file name");
      opt.screenshot = v;
    } else if (a == "--size") {
      const char* v = value("WxH");
      if (v == nullptr) return 2;
      const std::string s = v;
      const auto x = s.find('x');
      if (x == std::string::npos ||
          !detail::parse_int(s.substr(0, x).c_str(), 1, 8192, opt.width) ||
          !detail::parse_int(s.substr(x + 1).c_str(), 1, 8192, opt.height))
        return bad(v, "WxH with 1 <= W, H <= 8192");
    } else if (a == "--verbose" || a == "-v") {
      opt.verbose = true;
    } else if (a == "--egl") {
      opt.egl = true;
    } else {
      bool found = false;
      for (const auto& e : extra) {
        if (a != e.name) continue;
        found = true;
        const char* v = "";
        if (!e.arg.empty()) {
          v = value(e.arg.c_str());
          if (v == nullptr) return 2;
        }
        if (!e.set(v)) {
          std::fprintf(stderr, "%s: bad value '%s' for %s %s (%s)\n", name, v, a.c_str(),
                       e.arg.c_str(), e.help.c_str());
          return 2;
        }
      }
      if (!found) {
        std::fprintf(stderr, "%s: unknown option '%s'\n", name, a.c_str());
        detail::usage(stderr, name, extra);
        return 2;
      }
    }
  }
  if (!opt.screenshot.empty() && opt.frames == 0) {
    std::fprintf(stderr, "%s: --screenshot needs --frames N (the headless mode)\n", name);
    return 2;
  }
  return -1;
}

// ---------------------------------------------------------------------------------------------
// The window and the frame loop.

namespace detail {

inline App* app_of(GLFWwindow* w) {
  return static_cast<App*>(glfwGetWindowUserPointer(w));
}

inline void on_key(GLFWwindow* w, int key, int /*scancode*/, int action, int /*mods*/) {
  if (action != GLFW_PRESS) return;
  if (key == GLFW_KEY_ESCAPE) {
    glfwSetWindowShouldClose(w, GLFW_TRUE);
    return;
  }
  app_of(w)->key(key);
}

inline void on_mouse_button(GLFWwindow* w, int button, int action, int /*mods*/) {
  double x = 0, y = 0;
  glfwGetCursorPos(w, &x, &y);
  app_of(w)->mouse_button(button, action == GLFW_PRESS, x, y);
}

inline void on_cursor(GLFWwindow* w, double x, double y) {
  app_of(w)->cursor(x, y);
}
inline void on_scroll(GLFWwindow* w, double /*dx*/, double dy) {
  app_of(w)->scroll(dy);
}
inline void on_glfw_error(int code, const char* text) {
  std::fprintf(stderr, "GLFW error 0x%x: %s\n", code, text);
}

inline const char* gl_string(GLenum name) {
  const auto* s = reinterpret_cast<const char*>(glGetString(name));
  return s != nullptr ? s : "(null)";
}

} // namespace detail

// Runs a demo: parses the arguments, opens the window (hidden when headless) and loops.
// Returns the process exit status.
inline int run(const char* name, int argc, char** argv, App& app,
               const std::vector<ExtraOption>& extra = {}) {
  Options opt;
  if (const int status = parse_args(name, argc, argv, opt, extra); status >= 0) return status;
  const bool headless = opt.frames > 0;

  glfwSetErrorCallback(detail::on_glfw_error);
  if (glfwInit() != GLFW_TRUE) {
    std::fprintf(stderr, "%s: glfwInit failed (is DISPLAY set?)\n", name);
    return 1;
  }
  glfwWindowHint(GLFW_DEPTH_BITS, 24);
  // EGL on X11 (EGL_KHR_platform_x11) with a desktop OpenGL context, as GLFW makes it.
  if (opt.egl) glfwWindowHint(GLFW_CONTEXT_CREATION_API, GLFW_EGL_CONTEXT_API);
  glfwWindowHint(GLFW_RESIZABLE, headless ? GLFW_FALSE : GLFW_TRUE);
  glfwWindowHint(GLFW_VISIBLE, headless ? GLFW_FALSE : GLFW_TRUE);
  GLFWwindow* window = glfwCreateWindow(opt.width, opt.height, name, nullptr, nullptr);
  if (window == nullptr) {
    std::fprintf(stderr, "%s: cannot create a %dx%d window with an OpenGL context\n", name,
                 opt.width, opt.height);
    glfwTerminate();
    return 1;
  }
  glfwSetWindowUserPointer(window, &app);
  glfwSetKeyCallback(window, detail::on_key);
  glfwSetMouseButtonCallback(window, detail::on_mouse_button);
  glfwSetCursorPosCallback(window, detail::on_cursor);
  glfwSetScrollCallback(window, detail::on_scroll);
  glfwMakeContextCurrent(window);
  // Headless frames are not paced to a display; in a window the FPS shows the renderer's speed.
  glfwSwapInterval(0);

  const std::string renderer = detail::gl_string(GL_RENDERER);
  if (opt.verbose) {
    std::printf("GL_RENDERER: %s\nGL_VERSION: %s\nGL_VENDOR: %s\n", renderer.c_str(),
                detail::gl_string(GL_VERSION), detail::gl_string(GL_VENDOR));
    std::fflush(stdout);
  }
  app.init();

  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  auto fps_start = start;
  int fps_frames = 0;
  int status = 0;
  for (int index = 0; headless ? index < opt.frames : !glfwWindowShouldClose(window); ++index) {
    Frame frame;
    frame.index = index;
    frame.headless = headless;
    frame.frames = opt.frames;
    frame.time = headless ? index * kHeadlessFrameTime
                          : std::chrono::duration<double>(clock::now() - start).count();
    glfwGetFramebufferSize(window, &frame.width, &frame.height);
    app.draw(frame);
    if (headless && index == opt.frames - 1 && !opt.screenshot.empty()) {
      glFinish();
      if (!screenshot(opt.screenshot, frame.width, frame.height)) status = 1;
    }
    glfwSwapBuffers(window);
    glfwPollEvents();
    ++fps_frames;
    const double elapsed = std::chrono::duration<double>(clock::now() - fps_start).count();
    if (!headless && elapsed >= 0.5) {
      char title[256];
      std::snprintf(title, sizeof title, "%s - %.1f FPS - %s", name, fps_frames / elapsed,
                    renderer.c_str());
      glfwSetWindowTitle(window, title);
      fps_start = clock::now();
      fps_frames = 0;
    }
  }
  if (const GLenum err = glGetError(); err != GL_NO_ERROR) {
    std::fprintf(stderr, "%s: GL error 0x%04x\n", name, err);
    status = 1;
  }
  if (headless) {
    const double seconds = std::chrono::duration<double>(clock::now() - start).count();
    std::printf("%s: %d frames in %.2f s = %.1f FPS\n", name, opt.frames, seconds,
                seconds > 0 ? opt.frames / seconds : 0.0);
  }
  glfwDestroyWindow(window);
  glfwTerminate();
  return status;
}

} // namespace demo
