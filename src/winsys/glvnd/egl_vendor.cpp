// libEGL_pineda.so.0: Pineda's EGL (src/winsys/egl) as a vendor library of glvnd's libEGL
// (glvnd/libeglabi.h), found through a JSON file (50_pineda.json). libEGL owns the entry points
// applications call and dispatches to this library by display; it fetches Pineda's EGL 1.5
// functions and, for libGLdispatch, its GL functions by name. The display extension functions
// Pineda has (EGL_EXT_platform_base's surface functions) are among those libEGL dispatches
// itself, so no dispatch stubs of Pineda's own are needed.
#include <EGL/egl.h>
#include <glvnd/libeglabi.h>

#include <cstring>

#include "dispatch.h"
#include "egl_generated.h"
#include "winsys/egl/egl_internal.h"

namespace {

EGLDisplay get_platform_display(EGLenum platform, void* native, const EGLAttrib* attribs) {
  return pineda::egl::platform_display(platform, native, attribs, "eglGetPlatformDisplay");
}

// Only desktop OpenGL until Pineda has OpenGL ES contexts.
EGLBoolean get_supports_api(EGLenum api) {
  return api == EGL_OPENGL_API ? EGL_TRUE : EGL_FALSE;
}

const char* get_vendor_string(int name) {
  return name == __EGL_VENDOR_STRING_PLATFORM_EXTENSIONS ? pineda::egl::kPlatformExtensions
                                                         : nullptr;
}

// EGL and GL functions by name.
void* get_proc_address(const char* name) {
  if (name == nullptr) return nullptr;
  void* p = pineda::egl::lookup_egl_proc(name);
  return p != nullptr ? p : pineda::lookup_gl_proc(name);
}

void* get_dispatch_address(const char* /*name*/) {
  return nullptr;
}

void set_dispatch_index(const char* /*name*/, int /*index*/) {}

} // namespace

extern "C" __attribute__((visibility("default"))) EGLBoolean
__egl_Main(uint32_t version, const __EGLapiExports* exports, __EGLvendorInfo* /*vendor*/,
           __EGLapiImports* imports) {
  // Any 0.x libEGL from 0.1 on (getVendorString): minor versions only add to the structures.
  if (EGL_VENDOR_ABI_GET_MAJOR_VERSION(version) != EGL_VENDOR_ABI_MAJOR_VERSION ||
      EGL_VENDOR_ABI_GET_MINOR_VERSION(version) < 1)
    return EGL_FALSE;
  // libEGL keeps each thread's bound API (eglBindAPI); contexts are made for that one.
  pineda::egl::set_api_source(exports->getCurrentApi);
  std::memset(imports, 0, sizeof *imports);
  imports->getPlatformDisplay = &get_platform_display;
  imports->getSupportsAPI = &get_supports_api;
  imports->getVendorString = &get_vendor_string;
  imports->getProcAddress = &get_proc_address;
  imports->getDispatchAddress = &get_dispatch_address;
  imports->setDispatchIndex = &set_dispatch_index;
  return EGL_TRUE;
}
