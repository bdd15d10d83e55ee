// The spinning colour cube of osmesa_cube, rendered headless through EGL instead: a pbuffer
// of the surfaceless platform (EGL_MESA_platform_surfaceless, no X server) or, with
// --platform x11, of the X11 platform. An ordinary glvnd program (libEGL, libOpenGL): it runs
// on Pineda through pineda-run and on Mesa without it.
//   egl_cube [--platform surfaceless|x11] [--frames N] [--screenshot out.ppm] [--check]
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "cube_scene.h"

int main(int argc, char** argv) {
  using namespace cube;
  int frames = 300;
  std::string screenshot;
  bool check = false;
  EGLenum platform = EGL_PLATFORM_SURFACELESS_MESA;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--frames") && i + 1 < argc) frames = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--screenshot") && i + 1 < argc) screenshot = argv[++i];
    else if (!std::strcmp(argv[i], "--check")) check = true;
    else if (!std::strcmp(argv[i], "--platform") && i + 1 < argc &&
             (!std::strcmp(argv[i + 1], "x11") || !std::strcmp(argv[i + 1], "surfaceless")))
      platform = !std::strcmp(argv[++i], "x11") ? EGL_PLATFORM_X11_KHR
                                                : EGL_PLATFORM_SURFACELESS_MESA;
    else {
      std::fprintf(stderr,
                   "usage: %s [--platform surfaceless|x11] [--frames N] [--screenshot out.ppm] "
                   "[--check]\n",
                   argv[0]);
      return 2;
    }
  }
  if (frames < 1) frames = 1;
  // EGL_DEFAULT_DISPLAY on the X11 platform opens the display DISPLAY names.
  EGLDisplay dpy = eglGetPlatformDisplay(platform, EGL_DEFAULT_DISPLAY, nullptr);
  const EGLint want[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                         EGL_RED_SIZE,     8,               EGL_DEPTH_SIZE,      24,
                         EGL_NONE};
  EGLConfig config = nullptr;
  EGLint n = 0;
  const EGLint size[] = {EGL_WIDTH, kWidth, EGL_HEIGHT, kHeight, EGL_NONE};
  if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, nullptr, nullptr) ||
      !eglBindAPI(EGL_OPENGL_API) || !eglChooseConfig(dpy, want, &config, 1, &n) || n < 1) {
    std::fprintf(stderr, "egl_cube: no EGL display or config (EGL error 0x%04x)\n", eglGetError());
    return 1;
  }
  EGLSurface surface = eglCreatePbufferSurface(dpy, config, size);
  EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, nullptr);
  if (surface == EGL_NO_SURFACE || ctx == EGL_NO_CONTEXT ||
      !eglMakeCurrent(dpy, surface, surface, ctx)) {
    std::fprintf(stderr, "egl_cube: cannot make a pbuffer context current (EGL error 0x%04x)\n",
                 eglGetError());
    return 1;
  }
  std::printf("renderer: %s\n", reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
  setup();
  const auto t0 = std::chrono::steady_clock::now();
  for (int frame = 0; frame < frames; ++frame)
    draw_frame(frame);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("%d frames in %.3f s (%.1f FPS)\n", frames, secs, frames / secs);
  std::vector<unsigned char> rgba(kWidth * kHeight * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  int status = 0;
  if (!screenshot.empty() && !write_ppm(screenshot, rgba)) {
    std::fprintf(stderr, "egl_cube: cannot write %s\n", screenshot.c_str());
    status = 1;
  }
  if (check && !shows_cube(rgba)) {
    std::fprintf(stderr, "egl_cube: the picture does not show the cube\n");
    status = 1;
  }
  eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroySurface(dpy, surface);
  eglDestroyContext(dpy, ctx);
  eglTerminate(dpy);
  return status;
}
