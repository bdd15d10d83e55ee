// EGL displays (EGL 1.5 §3.2: eglGetDisplay, eglGetPlatformDisplay, eglInitialize,
// eglTerminate), strings (§3.3), errors (§3.1) and eglGetProcAddress (§3.10).
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "dispatch.h"
#include "egl_generated.h"
#include "winsys/egl/egl_internal.h"

// XESetCloseDisplay is declared only here; this header also defines min and max macros.
#include <X11/Xlibint.h>
#undef min
#undef max

namespace pineda::egl {

namespace {

thread_local EGLint t_error = EGL_SUCCESS;

std::vector<std::unique_ptr<EglDisplay>>& displays() {
  // Never destroyed: glvnd loads the library after the application registered its exit
  // handlers, whose EGL calls would otherwise meet destroyed displays.
  static auto* list = new std::vector<std::unique_ptr<EglDisplay>>;
  return *list;
}

bool debug_log() {
  static const bool on = [] {
    const char* v = std::getenv("PINEDA_DEBUG");
    return v != nullptr && v[0] != '\0' && v[0] != '0';
  }();
  return on;
}

constexpr const char* kVendor = "Pineda";
constexpr const char* kVersion = "1.5 Pineda";
constexpr const char* kClientApis = "OpenGL";

// The display for (platform, native, screen), made on first use (§3.2: the same arguments
// give the same handle).
EglDisplay* get_display(Platform platform, void* native, int screen) {
  for (auto& d : displays())
    if (d->platform == platform && d->native == native && d->screen == screen) return d.get();
  auto d = std::make_unique<EglDisplay>();
  d->platform = platform;
  d->native = native;
  d->screen = screen;
  displays().push_back(std::move(d));
  return displays().back().get();
}

// XCloseDisplay hook of an application's display: its EGL display is terminated and every
// surface loses its X resources now, while the connection still works; a context current on
// one renders nowhere until it is bound again (as GLX's displays, glx_config.cpp).
int on_close_display(Display* dpy, XExtCodes*) {
  std::lock_guard<std::mutex> lock(egl_mutex());
  for (auto& d : displays()) {
    if (d->dpy != dpy || d->own_dpy) continue;
    for (EglSurface* s : d->surfaces) {
      for (EglContext* ctx : s->bound)
        winsys::unbind_buffers(ctx);
      x11::release_images(*s);
      s->dpy = nullptr;
    }
    terminate_objects(d.get());
    d->initialized = false;
    d->dpy = nullptr;
    d->close_hooked = nullptr;
  }
  return 0;
}

// Whether an X server can be reached for the default display.
bool x_display_named() {
  const char* name = std::getenv("DISPLAY");
  return name != nullptr && name[0] != '\0';
}

} // namespace

std::mutex& egl_mutex() {
  static std::mutex m;
  return m;
}

void set_error(EGLint error, const char* function) {
  t_error = error;
  if (error != EGL_SUCCESS && function != nullptr && debug_log()) {
    const char* name = egl_enum_name(error);
    std::fprintf(stderr, "pineda: %s: %s\n", function, name != nullptr ? name : "EGL error");
  }
}

EglDisplay* find_display(EGLDisplay handle, const char* function) {
  for (auto& d : displays())
    if (static_cast<EGLDisplay>(d.get()) == handle) return d.get();
  set_error(EGL_BAD_DISPLAY, function);
  return nullptr;
}

EglDisplay* initialized_display(EGLDisplay handle, const char* function) {
  EglDisplay* d = find_display(handle, function);
  if (d != nullptr && !d->initialized) {
    set_error(EGL_NOT_INITIALIZED, function);
    return nullptr;
  }
  return d;
}

EGLDisplay platform_display(EGLenum platform, void* native, const EGLAttrib* attribs,
                            const char* function) {
  std::lock_guard<std::mutex> lock(egl_mutex());
  int screen = -1;
  switch (platform) {
  case EGL_PLATFORM_X11_KHR:
    // EGL_KHR_platform_x11: native is a Display* or EGL_DEFAULT_DISPLAY, which opens the
    // display $DISPLAY names at eglInitialize.
    for (int i = 0; attribs != nullptr && attribs[i] != EGL_NONE; i += 2) {
      if (attribs[i] != EGL_PLATFORM_X11_SCREEN_KHR || attribs[i + 1] < 0)
        return fail(EGL_BAD_ATTRIBUTE, function, EGL_NO_DISPLAY);
      screen = static_cast<int>(attribs[i + 1]);
    }
    break;
  case EGL_PLATFORM_SURFACELESS_MESA:
    // EGL_MESA_platform_surfaceless: native must be EGL_DEFAULT_DISPLAY, no attributes.
    if (native != nullptr) return fail(EGL_BAD_PARAMETER, function, EGL_NO_DISPLAY);
    if (attribs != nullptr && attribs[0] != EGL_NONE)
      return fail(EGL_BAD_ATTRIBUTE, function, EGL_NO_DISPLAY);
    succeed();
    return get_display(Platform::Surfaceless, nullptr, -1);
  case EGL_NONE:
    // eglGetDisplay (glvnd passes EGL_NONE for EGL_DEFAULT_DISPLAY): an X display when one is
    // named or given, no window system otherwise.
    if (native == nullptr && !x_display_named()) {
      succeed();
      return get_display(Platform::Surfaceless, nullptr, -1);
    }
    break;
  default:
    return fail(EGL_BAD_PARAMETER, function, EGL_NO_DISPLAY);
  }
  succeed();
  return get_display(Platform::X11, native, screen);
}

} // namespace pineda::egl

using namespace pineda::egl;

EGL_EXPORT EGLint EGLAPIENTRY eglGetError(void) {
  const EGLint e = pineda::egl::t_error;
  pineda::egl::t_error = EGL_SUCCESS;
  return e;
}

EGL_EXPORT EGLDisplay EGLAPIENTRY eglGetDisplay(EGLNativeDisplayType display_id) {
  return platform_display(EGL_NONE, display_id, nullptr, "eglGetDisplay");
}

EGL_EXPORT EGLDisplay EGLAPIENTRY eglGetPlatformDisplay(EGLenum platform, void* native_display,
                                                        const EGLAttrib* attrib_list) {
  return platform_display(platform, native_display, attrib_list, "eglGetPlatformDisplay");
}

EGL_EXPORT EGLDisplay EGLAPIENTRY eglGetPlatformDisplayEXT(EGLenum platform, void* native_display,
                                                           const EGLint* attrib_list) {
  // EGL_EXT_platform_base: the same with EGLint attributes.
  std::vector<EGLAttrib> attribs;
  for (int i = 0; attrib_list != nullptr && attrib_list[i] != EGL_NONE; i += 2) {
    attribs.push_back(attrib_list[i]);
    attribs.push_back(attrib_list[i + 1]);
  }
  attribs.push_back(EGL_NONE);
  return platform_display(platform, native_display, attribs.data(), "eglGetPlatformDisplayEXT");
}

EGL_EXPORT EGLBoolean EGLAPIENTRY eglInitialize(EGLDisplay dpy, EGLint* major, EGLint* minor) {
  std::lock_guard<std::mutex> lock(egl_mutex());
  EglDisplay* d = find_display(dpy, "eglInitialize");
  if (d == nullptr) return EGL_FALSE;
  if (!d->initialized) {
    if (d->platform == Platform::X11) {
      d->dpy = static_cast<Display*>(d->native);
      d->own_dpy = d->dpy == nullptr;
      if (d->own_dpy) d->dpy = XOpenDisplay(nullptr);
      if (d->dpy == nullptr) return fail(EGL_NOT_INITIALIZED, "eglInitialize", EGL_FALSE);
      if (d->screen < 0) d->screen = DefaultScreen(d->dpy);
      if (d->screen >= ScreenCount(d->dpy)) {
        if (d->own_dpy) XCloseDisplay(d->dpy);
        d->dpy = nullptr;
        return fail(EGL_NOT_INITIALIZED, "eglInitialize", EGL_FALSE);
      }
      d->shm = x11::shm_available(d->dpy);
      if (!d->own_dpy && d->close_hooked != d->dpy) {
        if (XExtCodes* codes = XAddExtension(d->dpy))
          XESetCloseDisplay(d->dpy, codes->extension, on_close_display);
        d->close_hooked = d->dpy;
      }
    }
    build_configs(d);
    d->initialized = true;
  }
  if (major != nullptr) *major = kEglVersionMajor;
  if (minor != nullptr) *minor = kEglVersionMinor;
  succeed();
  return EGL_TRUE;
}

EGL_EXPORT EGLBoolean EGLAPIENTRY eglTerminate(EGLDisplay dpy) {
  std::lock_guard<std::mutex> lock(egl_mutex());
  EglDisplay* d = find_display(dpy, "eglTerminate");
  if (d == nullptr) return EGL_FALSE;
  if (d->initialized) {
    // §3.2: every handle of the display becomes invalid; objects current to a thread live on
    // until released there.
    terminate_objects(d);
    d->initialized = false;
  }
  succeed();
  return EGL_TRUE;
}

EGL_EXPORT const char* EGLAPIENTRY eglQueryString(EGLDisplay dpy, EGLint name) {
  std::lock_guard<std::mutex> lock(egl_mutex());
  if (dpy == EGL_NO_DISPLAY) {
    // EGL_EXT_client_extensions, and EGL 1.5's version of the client library.
    if (name == EGL_EXTENSIONS) {
      succeed();
      return kClientExtensions;
    }
    if (name == EGL_VERSION) {
      succeed();
      return kVersion;
    }
    return fail(EGL_BAD_DISPLAY, "eglQueryString", static_cast<const char*>(nullptr));
  }
  EglDisplay* d = initialized_display(dpy, "eglQueryString");
  if (d == nullptr) return nullptr;
  const char* s = nullptr;
  switch (name) {
  case EGL_CLIENT_APIS:
    s = kClientApis;
    break;
  case EGL_EXTENSIONS:
    s = kDisplayExtensions;
    break;
  case EGL_VENDOR:
    s = kVendor;
    break;
  case EGL_VERSION:
    s = kVersion;
    break;
  default:
    return fail(EGL_BAD_PARAMETER, "eglQueryString", static_cast<const char*>(nullptr));
  }
  succeed();
  return s;
}

// §3.10, EGL_KHR_get_all_proc_addresses: every EGL and GL function Pineda implements.
EGL_EXPORT __eglMustCastToProperFunctionPointerType EGLAPIENTRY
eglGetProcAddress(const char* procname) {
  succeed();
  if (procname == nullptr) return nullptr;
  void* p = lookup_egl_proc(procname);
  if (p == nullptr) p = pineda::lookup_gl_proc(procname);
  return reinterpret_cast<__eglMustCastToProperFunctionPointerType>(p);
}
