// libFuzzer harness of the EGL API: the input bytes are a program of EGL calls (and a few GL
// calls that render into and read back the current surface) on the surfaceless platform, with
// arbitrary arguments: attribute lists of real and random attributes and values, handles that
// are live objects, destroyed ones, other objects' handles or garbage. Pineda validates every
// handle by lookup and never dereferences one it did not make, so every input must run clean
// under ASan and UBSan; wrong calls must set an EGL error and change nothing.
//
// Linked to Pineda's EGL directly (pineda_egl_static); no X server is needed.
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <iterator>
#include <vector>

#include "fuzz_input.h"

namespace {

using pineda::fuzz::Input;

constexpr int kMaxSurface = 64;

// Attributes EGL calls take, with neighbours and values that matter.
constexpr EGLint kAttribs[] = {EGL_WIDTH,
                               EGL_HEIGHT,
                               EGL_LARGEST_PBUFFER,
                               EGL_TEXTURE_FORMAT,
                               EGL_TEXTURE_TARGET,
                               EGL_MIPMAP_TEXTURE,
                               EGL_GL_COLORSPACE,
                               EGL_VG_ALPHA_FORMAT,
                               EGL_VG_COLORSPACE,
                               EGL_RENDER_BUFFER,
                               EGL_CONFIG_ID,
                               EGL_ALPHA_SIZE,
                               EGL_DEPTH_SIZE,
                               EGL_STENCIL_SIZE,
                               EGL_SAMPLES,
                               EGL_SAMPLE_BUFFERS,
                               EGL_SURFACE_TYPE,
                               EGL_RENDERABLE_TYPE,
                               EGL_CONFORMANT,
                               EGL_LEVEL,
                               EGL_COLOR_BUFFER_TYPE,
                               EGL_CONFIG_CAVEAT,
                               EGL_MATCH_NATIVE_PIXMAP,
                               EGL_NATIVE_VISUAL_TYPE,
                               EGL_TRANSPARENT_TYPE,
                               EGL_MIN_SWAP_INTERVAL,
                               EGL_MAX_SWAP_INTERVAL,
                               EGL_BUFFER_SIZE,
                               EGL_RED_SIZE,
                               EGL_CONTEXT_MAJOR_VERSION,
                               EGL_CONTEXT_MINOR_VERSION,
                               EGL_CONTEXT_OPENGL_PROFILE_MASK,
                               EGL_CONTEXT_OPENGL_DEBUG,
                               EGL_CONTEXT_OPENGL_FORWARD_COMPATIBLE,
                               EGL_CONTEXT_OPENGL_ROBUST_ACCESS,
                               EGL_CONTEXT_OPENGL_RESET_NOTIFICATION_STRATEGY,
                               EGL_CONTEXT_FLAGS_KHR,
                               EGL_SWAP_BEHAVIOR,
                               EGL_MULTISAMPLE_RESOLVE,
                               EGL_MIPMAP_LEVEL,
                               EGL_CONTEXT_CLIENT_TYPE,
                               EGL_SYNC_TYPE,
                               EGL_SYNC_STATUS,
                               EGL_SYNC_CONDITION,
                               EGL_PLATFORM_X11_SCREEN_KHR,
                               0,
                               0x1234};
constexpr EGLint kValues[] = {0,
                              1,
                              2,
                              3,
                              4,
                              5,
                              8,
                              16,
                              24,
                              32,
                              -1,
                              EGL_DONT_CARE,
                              EGL_TRUE,
                              EGL_FALSE,
                              EGL_NONE,
                              EGL_PBUFFER_BIT,
                              EGL_WINDOW_BIT,
                              EGL_OPENGL_BIT,
                              EGL_OPENGL_ES_BIT,
                              EGL_NO_TEXTURE,
                              EGL_TEXTURE_RGB,
                              EGL_TEXTURE_2D,
                              EGL_GL_COLORSPACE_SRGB,
                              EGL_GL_COLORSPACE_LINEAR,
                              EGL_BACK_BUFFER,
                              EGL_SINGLE_BUFFER,
                              EGL_RGB_BUFFER,
                              EGL_LUMINANCE_BUFFER,
                              EGL_SLOW_CONFIG,
                              EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                              EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT,
                              EGL_LOSE_CONTEXT_ON_RESET,
                              EGL_BUFFER_PRESERVED,
                              EGL_BUFFER_DESTROYED,
                              EGL_MULTISAMPLE_RESOLVE_BOX,
                              1 << 20,
                              0x7fffffff,
                              INT32_MIN};
constexpr EGLenum kEnums[] = {EGL_OPENGL_API,    EGL_OPENGL_ES_API,
                              EGL_OPENVG_API,    EGL_NONE,
                              EGL_SYNC_FENCE,    EGL_SYNC_CL_EVENT,
                              EGL_GL_TEXTURE_2D, EGL_DRAW,
                              EGL_READ,          EGL_VENDOR,
                              EGL_VERSION,       EGL_EXTENSIONS,
                              EGL_CLIENT_APIS,   EGL_CORE_NATIVE_ENGINE,
                              EGL_OPENVG_IMAGE,  0x1234};

struct State {
  EGLDisplay dpy = EGL_NO_DISPLAY;
  std::vector<EGLConfig> configs;
  std::vector<EGLSurface> surfaces; // live and destroyed: both are fair arguments
  std::vector<EGLContext> contexts;
  std::vector<EGLSync> syncs;
  std::vector<uint8_t> pixels = std::vector<uint8_t>(kMaxSurface * kMaxSurface * 4);
};

template <typename T, size_t N> T pick(Input& in, const T (&table)[N]) {
  const uint8_t tag = in.u8();
  if (tag < 240) return table[tag % N];
  return static_cast<T>(in.u32());
}

EGLint value(Input& in) {
  const uint8_t tag = in.u8();
  if (tag < 160) return kValues[tag % std::size(kValues)];
  if (tag < 230) return static_cast<EGLint>(tag) - 160;
  return static_cast<EGLint>(in.u32());
}

// An attribute list of up to 6 pairs, EGL_NONE-terminated (EGLint or EGLAttrib).
template <typename T> std::vector<T> attribs(Input& in) {
  std::vector<T> list;
  const int pairs = in.u8() % 7;
  for (int i = 0; i < pairs; ++i) {
    list.push_back(pick(in, kAttribs));
    list.push_back(value(in));
  }
  list.push_back(EGL_NONE);
  return list;
}

// A handle argument: one of the objects made so far (live or not), null, or garbage.
template <typename T> T handle(Input& in, const std::vector<T>& made) {
  const uint8_t tag = in.u8();
  if (tag < 200 && !made.empty()) return made[tag % made.size()];
  if (tag < 230) return T{};
  return reinterpret_cast<T>(static_cast<uintptr_t>(in.u32()) | 1u);
}

EGLDisplay display(Input& in, State& s) {
  const uint8_t tag = in.u8();
  if (tag < 220) return s.dpy;
  if (tag < 240) return EGL_NO_DISPLAY;
  return reinterpret_cast<EGLDisplay>(static_cast<uintptr_t>(in.u32()) | 1u);
}

void op(Input& in, State& s) {
  EGLint n = 0, v = 0;
  EGLAttrib av = 0;
  switch (in.u8() % 24) {
  case 0:
    eglInitialize(display(in, s), &v, &n);
    break;
  case 1:
    eglTerminate(display(in, s));
    break;
  case 2: {
    EGLConfig list[8];
    const auto a = attribs<EGLint>(in);
    if (eglChooseConfig(display(in, s), in.u8() & 1 ? a.data() : nullptr, list, in.u8() % 9, &n))
      for (int i = 0; i < n; ++i)
        s.configs.push_back(list[i]);
    break;
  }
  case 3:
    eglGetConfigAttrib(display(in, s), handle(in, s.configs), pick(in, kAttribs), &v);
    break;
  case 4: {
    const auto a = attribs<EGLint>(in);
    // Keep the size small: a huge pbuffer is a valid request, not a finding.
    std::vector<EGLint> b = a;
    for (size_t i = 0; i + 1 < b.size(); i += 2)
      if (b[i] == EGL_WIDTH || b[i] == EGL_HEIGHT) b[i + 1] = std::clamp(b[i + 1], -2, kMaxSurface);
    EGLSurface surf = eglCreatePbufferSurface(display(in, s), handle(in, s.configs), b.data());
    if (surf != EGL_NO_SURFACE) s.surfaces.push_back(surf);
    break;
  }
  case 5:
    eglDestroySurface(display(in, s), handle(in, s.surfaces));
    break;
  case 6: {
    const auto a = attribs<EGLint>(in);
    EGLContext c =
        eglCreateContext(display(in, s), handle(in, s.configs), handle(in, s.contexts), a.data());
    if (c != EGL_NO_CONTEXT) s.contexts.push_back(c);
    break;
  }
  case 7:
    eglDestroyContext(display(in, s), handle(in, s.contexts));
    break;
  case 8: {
    const EGLSurface d = handle(in, s.surfaces);
    eglMakeCurrent(display(in, s), d, in.u8() & 1 ? d : handle(in, s.surfaces),
                   handle(in, s.contexts));
    break;
  }
  case 9:
    eglQuerySurface(display(in, s), handle(in, s.surfaces), pick(in, kAttribs), &v);
    break;
  case 10:
    eglSurfaceAttrib(display(in, s), handle(in, s.surfaces), pick(in, kAttribs), value(in));
    break;
  case 11:
    eglQueryContext(display(in, s), handle(in, s.contexts), pick(in, kAttribs), &v);
    break;
  case 12:
    eglSwapBuffers(display(in, s), handle(in, s.surfaces));
    break;
  case 13:
    eglSwapInterval(display(in, s), value(in) % 3);
    break;
  case 14:
    eglBindAPI(pick(in, kEnums));
    break;
  case 15:
    eglQueryString(display(in, s), static_cast<EGLint>(pick(in, kEnums)));
    break;
  case 16: {
    const auto a = attribs<EGLAttrib>(in);
    EGLSync sync =
        eglCreateSync(display(in, s), pick(in, kEnums), in.u8() & 1 ? a.data() : nullptr);
    if (sync != EGL_NO_SYNC) s.syncs.push_back(sync);
    break;
  }
  case 17: {
    const EGLSync sync = handle(in, s.syncs);
    switch (in.u8() % 4) {
    case 0:
      eglDestroySync(display(in, s), sync);
      break;
    case 1:
      eglClientWaitSync(display(in, s), sync, value(in), 0);
      break;
    case 2:
      eglWaitSync(display(in, s), sync, value(in));
      break;
    default:
      eglGetSyncAttrib(display(in, s), sync, pick(in, kAttribs), &av);
      break;
    }
    break;
  }
  case 18: {
    const auto a = attribs<EGLAttrib>(in);
    eglCreateImage(display(in, s), handle(in, s.contexts), pick(in, kEnums), nullptr, a.data());
    break;
  }
  case 19:
    switch (in.u8() % 5) {
    case 0:
      eglWaitClient();
      break;
    case 1:
      eglWaitNative(static_cast<EGLint>(pick(in, kEnums)));
      break;
    case 2:
      eglReleaseThread();
      break;
    case 3:
      eglGetCurrentSurface(static_cast<EGLint>(pick(in, kEnums)));
      break;
    default:
      eglGetError();
      break;
    }
    break;
  case 20: {
    // Rendering into whatever is current (possibly nothing, or a surfaceless context).
    glClearColor(in.f(), in.f(), in.f(), in.f());
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < 3; ++i)
      glVertex3f(in.f(), in.f(), in.f());
    glEnd();
    glFlush();
    break;
  }
  case 21: {
    // Read back at most the largest surface the harness makes, into memory sized for it.
    const int w = 1 + in.u8() % kMaxSurface, h = 1 + in.u8() % kMaxSurface;
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(in.i() % kMaxSurface, in.i() % kMaxSurface, w, h, GL_RGBA, GL_UNSIGNED_BYTE,
                 s.pixels.data());
    break;
  }
  case 22: {
    EGLConfig list[4];
    eglGetConfigs(display(in, s), in.u8() & 1 ? list : nullptr, in.u8() % 5, &n);
    break;
  }
  default: {
    const auto a = attribs<EGLint>(in);
    eglCreatePbufferFromClientBuffer(display(in, s), pick(in, kEnums), nullptr,
                                     handle(in, s.configs), a.data());
    eglBindTexImage(display(in, s), handle(in, s.surfaces), value(in));
    break;
  }
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  Input in(data, size);
  State s;
  s.dpy = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (s.dpy == EGL_NO_DISPLAY || !eglInitialize(s.dpy, nullptr, nullptr)) std::abort();
  eglBindAPI(EGL_OPENGL_API);
  for (int steps = 0; steps < 200 && !in.empty(); ++steps)
    op(in, s);
  // Every input ends with nothing current and the display terminated, so that the next starts
  // from the same state (the display handle itself lives on).
  eglMakeCurrent(s.dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglTerminate(s.dpy);
  eglReleaseThread();
  return 0;
}
