// libGLX_pineda.so.0: Pineda's GLX as a vendor library of glvnd's libGLX (glvnd/libglxabi.h).
// libGLX owns the GLX entry points applications call; it asks this library for the GLX 1.4
// functions by name (its static table), for the GL functions libGLdispatch fills its dispatch
// table with, and for dispatch stubs of the GLX extension functions outside that table, which
// find the vendor through libGLX and call the implementation in a dynamically assigned slot.
// Everything behind those names is Pineda's GLX (src/winsys/glx), unchanged.
#include <GL/glx.h>
#include <glvnd/libglxabi.h>

#include <atomic>
#include <cstring>

#include "winsys/glx/glx_internal.h"

namespace {

const __GLXapiExports* g_exports = nullptr;

// The GLX extension functions libGLX has no static slot for, with the dispatch index libGLX
// gives each (setDispatchIndex); -1 until it does.
enum DynamicFunction { kSwapIntervalEXT, kSwapIntervalMESA, kGetSwapIntervalMESA, kDynamicCount };
std::atomic<int> g_index[kDynamicCount] = {-1, -1, -1};

template <typename F> F fetch(__GLXvendorInfo* vendor, DynamicFunction f) {
  const int index = g_index[f].load(std::memory_order_acquire);
  if (vendor == nullptr || index < 0) return nullptr;
  return reinterpret_cast<F>(g_exports->fetchDispatchEntry(vendor, index));
}

// The dispatch stubs: the vendor is the drawable's (GLX_EXT_swap_control) or the current
// context's (GLX_MESA_swap_control).
void dispatch_SwapIntervalEXT(Display* dpy, GLXDrawable drawable, int interval) {
  auto* f = fetch<decltype(&glXSwapIntervalEXT)>(g_exports->vendorFromDrawable(dpy, drawable),
                                                 kSwapIntervalEXT);
  if (f != nullptr) f(dpy, drawable, interval);
}

int dispatch_SwapIntervalMESA(unsigned int interval) {
  auto* f =
      fetch<decltype(&glXSwapIntervalMESA)>(g_exports->getCurrentDynDispatch(), kSwapIntervalMESA);
  return f != nullptr ? f(interval) : GLX_BAD_CONTEXT;
}

int dispatch_GetSwapIntervalMESA() {
  auto* f = fetch<decltype(&glXGetSwapIntervalMESA)>(g_exports->getCurrentDynDispatch(),
                                                     kGetSwapIntervalMESA);
  return f != nullptr ? f() : 0;
}

struct DynamicEntry {
  const char* name;
  void* stub;
};
const DynamicEntry kDynamic[kDynamicCount] = {
    {"glXSwapIntervalEXT", reinterpret_cast<void*>(&dispatch_SwapIntervalEXT)},
    {"glXSwapIntervalMESA", reinterpret_cast<void*>(&dispatch_SwapIntervalMESA)},
    {"glXGetSwapIntervalMESA", reinterpret_cast<void*>(&dispatch_GetSwapIntervalMESA)},
};

Bool is_screen_supported(Display* dpy, int screen) {
  using namespace pineda::glx;
  ApiLock api;
  DisplayState* ds = display_state(dpy);
  if (ds == nullptr) return False;
  for (const auto& c : ds->configs)
    if (c->screen == screen) return True;
  return False;
}

// GLX and GL functions by name: Pineda's own glXGetProcAddress answers both.
void* get_proc_address(const GLubyte* name) {
  return reinterpret_cast<void*>(glXGetProcAddressARB(name));
}

void* get_dispatch_address(const GLubyte* name) {
  for (const DynamicEntry& e : kDynamic)
    if (std::strcmp(e.name, reinterpret_cast<const char*>(name)) == 0) return e.stub;
  return nullptr;
}

void set_dispatch_index(const GLubyte* name, int index) {
  for (int i = 0; i < kDynamicCount; ++i)
    if (std::strcmp(kDynamic[i].name, reinterpret_cast<const char*>(name)) == 0)
      g_index[i].store(index, std::memory_order_release);
}

} // namespace

extern "C" __attribute__((visibility("default"))) Bool __glx_Main(uint32_t version,
                                                                  const __GLXapiExports* exports,
                                                                  __GLXvendorInfo* /*vendor*/,
                                                                  __GLXapiImports* imports) {
  // Any 1.x libGLX: minor versions only add to the structures.
  if (GLX_VENDOR_ABI_GET_MAJOR_VERSION(version) != GLX_VENDOR_ABI_MAJOR_VERSION) return False;
  g_exports = exports;
  std::memset(imports, 0, sizeof *imports);
  imports->isScreenSupported = &is_screen_supported;
  imports->getProcAddress = &get_proc_address;
  imports->getDispatchAddress = &get_dispatch_address;
  imports->setDispatchIndex = &set_dispatch_index;
  return True;
}
