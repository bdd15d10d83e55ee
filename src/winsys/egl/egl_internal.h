// EGL 1.5 on Pineda: displays on the X11 platform (EGL_KHR_platform_x11, presenting through
// the X11 path GLX uses, src/winsys/x11) and the surfaceless platform
// (EGL_MESA_platform_surfaceless: pbuffers only), OpenGL contexts (EGL_KHR_create_context).
//
// Shared by egl_display.cpp (displays, strings, errors, proc addresses), egl_config.cpp
// (configs, eglChooseConfig's selection and sorting), egl_surface.cpp (surfaces, swaps) and
// egl_context.cpp (contexts, the current state, syncs and images). The entry points carry
// the standard names; the glvnd vendor library (src/winsys/glvnd/egl_vendor.cpp) hands them
// to libEGL by name and exports none of them.
#pragma once

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <chrono>
#include <memory>
#include <mutex>
#include <thread>
#include <unordered_set>
#include <vector>

#include "state/context.h"
#include "winsys/common/surface_binding.h"
#include "winsys/x11/x11_target.h"

#define EGL_EXPORT extern "C" __attribute__((visibility("default")))

namespace pineda::egl {

namespace x11 = pineda::x11;
namespace winsys = pineda::winsys;

struct EglDisplay;

// One EGLConfig (EGL 1.5 §3.4, Table 3.1). RGBA, OpenGL only, no multisampling yet.
struct EglConfig {
  EglDisplay* display = nullptr;
  EGLint id = 0; // EGL_CONFIG_ID
  x11::Format x; // the visual behind window and pixmap surfaces; x.visual null: none
  ColorFormat format = ColorFormat::RGBA8; // how Pineda stores its colour buffers
  EGLint alpha = 0, depth = 0, stencil = 0;
  EGLint samples = 0, sample_buffers = 0;
  EGLint surface_type = EGL_PBUFFER_BIT;
  EGLint native_visual_id = 0;
  EGLint native_visual_type = EGL_NONE;
  bool native_renderable = false;
};

enum class Platform { X11, Surfaceless };

// An EGLDisplay: one per platform and native display (and X11 screen), never freed, so a
// handle stays recognisable after eglTerminate (EGL 1.5 §3.2).
struct EglDisplay {
  Platform platform = Platform::Surfaceless;
  void* native = nullptr; // the application's Display*, or null for EGL_DEFAULT_DISPLAY
  int screen = -1;        // EGL_PLATFORM_X11_SCREEN_KHR; -1: the display's default screen
  Display* dpy = nullptr; // the connection in use while initialized
  bool own_dpy = false;   // opened by eglInitialize (EGL_DEFAULT_DISPLAY)
  bool initialized = false;
  bool shm = false;
  Display* close_hooked = nullptr; // the connection whose XCloseDisplay hook is set
  std::vector<std::unique_ptr<EglConfig>> configs;
  // Surfaces, also those destroyed while current (freed when released).
  std::unordered_set<struct EglSurface*> surfaces;
  std::unordered_set<struct EglContext*> contexts;
  std::unordered_set<struct EglSync*> syncs;
};

// An EGLSurface. Windows and pixmaps render into the X11 images of x11::Target; pbuffers (and
// every surface of the surfaceless platform) into `memory`.
struct EglSurface : x11::Target {
  EglDisplay* display = nullptr;
  EGLint type = EGL_PBUFFER_BIT; // EGL_WINDOW_BIT, EGL_PIXMAP_BIT or EGL_PBUFFER_BIT
  const EglConfig* config = nullptr;
  std::vector<uint8_t> memory;
  std::vector<uint32_t> depth;
  std::vector<uint8_t> stencil;
  EGLint render_buffer = EGL_BACK_BUFFER; // EGL_RENDER_BUFFER (§3.5.1)
  EGLint swap_behavior = EGL_BUFFER_DESTROYED;
  EGLint multisample_resolve = EGL_MULTISAMPLE_RESOLVE_DEFAULT;
  EGLint texture_format = EGL_NO_TEXTURE, texture_target = EGL_NO_TEXTURE;
  EGLint mipmap_texture = EGL_FALSE, mipmap_level = 0;
  EGLint largest = EGL_FALSE;
  int swap_interval = 1;
  std::chrono::steady_clock::time_point last_swap{};
  std::vector<struct EglContext*> bound; // contexts current on it (draw surface)
  bool destroy_pending = false;          // eglDestroySurface while current: freed on release
};

// An EGLContext: the GL state plus EGL bookkeeping (§3.7).
struct EglContext final : Context {
  EglContext() = default;
  explicit EglContext(std::shared_ptr<SharedObjects> objects) : Context(std::move(objects)) {}
  EglDisplay* display = nullptr;
  const EglConfig* config = nullptr;
  EGLint major = 1, minor = 0;
  EglSurface* draw = nullptr;
  EglSurface* read = nullptr;
  bool is_current = false;
  std::thread::id thread{};
  bool destroy_pending = false; // eglDestroyContext while current: freed on release
};

// A fence sync (§3.8.1). Pineda renders synchronously: a fence is signaled when it is made.
struct EglSync {
  EglDisplay* display = nullptr;
  EGLenum type = EGL_SYNC_FENCE;
};

// The lock around all EGL bookkeeping.
std::mutex& egl_mutex();

// ---- errors (§3.1): the calling thread's last error ----
// Records `error` as the result of the current call (logged with PINEDA_DEBUG=1) and returns
// `result`, so that a failing entry point can `return fail(EGL_BAD_MATCH, EGL_FALSE)`.
void set_error(EGLint error, const char* function);
template <typename T> T fail(EGLint error, const char* function, T result) {
  set_error(error, function);
  return result;
}
// The call succeeded.
inline void succeed() {
  set_error(EGL_SUCCESS, nullptr);
}

// ---- displays (egl_display.cpp) ----
// The display behind a handle, or nullptr (EGL_BAD_DISPLAY is set).
EglDisplay* find_display(EGLDisplay handle, const char* function);
// The same, also requiring it to be initialized (EGL_NOT_INITIALIZED).
EglDisplay* initialized_display(EGLDisplay handle, const char* function);
// eglGetPlatformDisplay for X11, surfaceless and the default platform (EGL_NONE).
EGLDisplay platform_display(EGLenum platform, void* native, const EGLAttrib* attribs,
                            const char* function);

// ---- configs (egl_config.cpp) ----
void build_configs(EglDisplay* d);
const EglConfig* find_config(EglDisplay* d, EGLConfig handle);
// eglGetConfigAttrib's answer; false for an unknown attribute.
bool config_attrib(const EglConfig& c, EGLint attribute, EGLint* value);

// ---- surfaces (egl_surface.cpp) ----
EglSurface* find_surface(EglDisplay* d, EGLSurface handle);
// Frees a surface that no context is current on; otherwise marks it to be freed on release.
void destroy_surface(EglDisplay* d, EglSurface* s);
// ctx no longer draws to s: a surface destroyed meanwhile is freed once nothing is bound to it.
void release_surface(EglContext* ctx, EglSurface* s);
// Describes the surface's buffers to a context; refreshes a window's size first.
void attach(EglContext* ctx, EglSurface& s);
// A window's new size (EGL 1.5 §3.10.1: picked up at eglMakeCurrent and eglSwapBuffers); false
// if the window is gone.
bool refresh_size(EglSurface& s);
bool has_back_buffer(const EglSurface& s);
// glFlush on a context whose draw surface is shown without a swap: presents it.
void flush_front(EglContext* ctx);

// ---- contexts (egl_context.cpp) ----
EglContext* find_context(EglDisplay* d, EGLContext handle);
// This thread's current EGL context, or nullptr.
EglContext* current();
// Frees every object of a display being terminated (current ones when they are released).
void terminate_objects(EglDisplay* d);
// The client API bound on this thread: glvnd's libEGL keeps it when the library runs as a
// vendor (set_api_source), Pineda otherwise.
EGLenum bound_api();
void set_api_source(EGLenum (*get_current_api)());

} // namespace pineda::egl
