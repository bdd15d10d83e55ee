// The OSMesa API (Mesa's osmesa.h semantics): contexts that render into a buffer the
// application owns. The colour buffer is the user's memory itself; depth and stencil buffers
// are owned here and resized with the drawable.
#include <GL/osmesa.h>

#include <cstring>
#include <memory>
#include <new>
#include <vector>

#include "state/api_util.h"
#include "state/context.h"
#include "core/version.h"
#include "dispatch.h"
#include "winsys/common/surface_binding.h"

#define OSMESA_EXPORT extern "C" __attribute__((visibility("default")))

namespace pineda {

namespace {

constexpr GLint kMaxSize = kMaxViewportDim;

struct OSMesaState {
  // A context of its own share group, or of the group of the `sharelist` context (buffer
  // objects and display lists, as Mesa's OSMesa shares them).
  explicit OSMesaState(std::shared_ptr<SharedObjects> objects) : gl(std::move(objects)) {}
  Context gl;
  GLenum format = OSMESA_RGBA;
  int depth_bits = 0;
  int stencil_bits = 0;
  int accum_bits = 0;
  // The drawable bound by OSMesaMakeCurrent.
  void* buffer = nullptr;
  GLenum type = GL_UNSIGNED_BYTE;
  GLint width = 0, height = 0;
  GLint row_length = 0; // OSMESA_ROW_LENGTH, in pixels; 0 means the width
  bool y_up = true;     // OSMESA_Y_UP: row 0 of the user's buffer is the bottom row
  bool color_clamp = true;
  std::vector<uint32_t> depth;
  std::vector<uint8_t> stencil;
  std::vector<int16_t> accum; // 4 values per pixel when accum_bits > 0
};

thread_local OSMesaState* t_current_osmesa = nullptr;

ColorFormat color_format(GLenum format) {
  switch (format) {
  case OSMESA_BGRA:
    return ColorFormat::BGRA8;
  case OSMESA_ARGB:
    return ColorFormat::ARGB8;
  case OSMESA_RGB:
    return ColorFormat::RGB8;
  default:
    return ColorFormat::RGBA8;
  }
}

// Describe the user's buffer to the pipeline (row 0 at the bottom, as GL addresses it).
void attach_surfaces(OSMesaState* s) {
  winsys::SurfaceBuffers b;
  b.width = s->width;
  b.height = s->height;
  b.format = color_format(s->format);
  b.alpha_bits = b.format == ColorFormat::RGB8 ? 0 : 8;
  const ptrdiff_t row_pixels = s->row_length > 0 ? s->row_length : s->width;
  const ptrdiff_t row_bytes = row_pixels * bytes_per_pixel(b.format);
  uint8_t* base = static_cast<uint8_t*>(s->buffer);
  if (s->y_up) {
    b.color = base;
    b.stride = row_bytes;
  } else {
    b.color = base + (s->height - 1) * row_bytes;
    b.stride = -row_bytes;
  }
  b.depth_bits = s->depth_bits;
  b.depth = s->depth_bits > 0 ? s->depth.data() : nullptr;
  b.stencil_bits = s->stencil_bits;
  b.stencil = s->stencil_bits > 0 ? s->stencil.data() : nullptr;
  b.accum_bits = s->accum_bits;
  b.accum = s->accum_bits > 0 ? s->accum.data() : nullptr;
  winsys::bind_buffers(&s->gl, b);
}

OSMesaState* create(GLenum format, GLint depth_bits, GLint stencil_bits, GLint accum_bits,
                    OSMesaState* share) {
  // Pineda renders 8-bit RGBA, BGRA, ARGB and RGB; BGR, 565 and colour index are refused.
  if (format != OSMESA_RGBA && format != OSMESA_BGRA && format != OSMESA_ARGB &&
      format != OSMESA_RGB)
    return nullptr;
  std::shared_ptr<SharedObjects> objects =
      share != nullptr ? share->gl.shared : std::make_shared<SharedObjects>();
  auto* s = new (std::nothrow) OSMesaState(std::move(objects));
  if (s == nullptr) return nullptr;
  s->format = format;
  // Mesa rounds the requested depth up to a supported size: 16, 24 or 32 bits.
  s->depth_bits = depth_bits <= 0 ? 0 : depth_bits <= 16 ? 16 : depth_bits <= 24 ? 24 : 32;
  s->stencil_bits = stencil_bits > 0 ? 8 : 0;
  // Mesa gives a 16-bit signed accumulation buffer for any positive request.
  s->accum_bits = accum_bits > 0 ? 16 : 0;
  return s;
}

} // namespace
} // namespace pineda

using pineda::OSMesaState;

OSMESA_EXPORT OSMesaContext OSMesaCreateContextExt(GLenum format, GLint depthBits,
                                                   GLint stencilBits, GLint accumBits,
                                                   OSMesaContext sharelist) {
  return reinterpret_cast<OSMesaContext>(pineda::create(format, depthBits, stencilBits, accumBits,
                                                        reinterpret_cast<OSMesaState*>(sharelist)));
}

OSMESA_EXPORT OSMesaContext OSMesaCreateContext(GLenum format, OSMesaContext sharelist) {
  return OSMesaCreateContextExt(format, 24, 8, 0, sharelist);
}

OSMESA_EXPORT OSMesaContext OSMesaCreateContextAttribs(const int* attribList,
                                                       OSMesaContext sharelist) {
  GLenum format = OSMESA_RGBA;
  GLint depth = 24, stencil = 8, accum = 0;
  int major = 1, minor = 0;
  for (int i = 0; attribList != nullptr && attribList[i] != 0; i += 2) {
    const int value = attribList[i + 1];
    switch (attribList[i]) {
    case OSMESA_FORMAT:
      format = static_cast<GLenum>(value);
      break;
    case OSMESA_DEPTH_BITS:
      depth = value;
      break;
    case OSMESA_STENCIL_BITS:
      stencil = value;
      break;
    case OSMESA_ACCUM_BITS:
      accum = value;
      break;
    case OSMESA_PROFILE:
      // Only the compatibility profile exists here.
      if (value != OSMESA_COMPAT_PROFILE) return nullptr;
      break;
    case OSMESA_CONTEXT_MAJOR_VERSION:
      major = value;
      break;
    case OSMESA_CONTEXT_MINOR_VERSION:
      minor = value;
      break;
    default:
      return nullptr;
    }
  }
  // The version glGetString(GL_VERSION) reports is the most that can be promised.
  if (major > pineda::kGLVersionMajor ||
      (major == pineda::kGLVersionMajor && minor > pineda::kGLVersionMinor))
    return nullptr;
  return OSMesaCreateContextExt(format, depth, stencil, accum, sharelist);
}

OSMESA_EXPORT void OSMesaDestroyContext(OSMesaContext ctx) {
  auto* s = reinterpret_cast<OSMesaState*>(ctx);
  if (s == nullptr) return;
  if (pineda::t_current_osmesa == s) {
    pineda::t_current_osmesa = nullptr;
    pineda::set_current_context(nullptr);
  }
  delete s;
}

OSMESA_EXPORT GLboolean OSMesaMakeCurrent(OSMesaContext ctx, void* buffer, GLenum type,
                                          GLsizei width, GLsizei height) {
  auto* s = reinterpret_cast<OSMesaState*>(ctx);
  if (s == nullptr && buffer == nullptr) {
    pineda::t_current_osmesa = nullptr;
    pineda::set_current_context(nullptr);
    return GL_TRUE;
  }
  if (s == nullptr || buffer == nullptr || type != GL_UNSIGNED_BYTE || width < 1 || height < 1 ||
      width > pineda::kMaxSize || height > pineda::kMaxSize)
    return GL_FALSE;
  const size_t pixels = static_cast<size_t>(width) * static_cast<size_t>(height);
  try {
    if (s->depth_bits > 0) s->depth.resize(pixels);
    if (s->stencil_bits > 0) s->stencil.resize(pixels);
    if (s->accum_bits > 0) s->accum.resize(4 * pixels);
  } catch (const std::bad_alloc&) {
    return GL_FALSE;
  }
  s->buffer = buffer;
  s->type = type;
  s->width = width;
  s->height = height;
  pineda::attach_surfaces(s);
  // GL 2.1 §2.11.1, §4.1.2: the viewport and the scissor box start as the whole buffer the
  // first time the context is made current; it has a front buffer only.
  pineda::winsys::first_make_current(&s->gl, width, height, false);
  pineda::t_current_osmesa = s;
  pineda::set_current_context(&s->gl);
  return GL_TRUE;
}

OSMESA_EXPORT OSMesaContext OSMesaGetCurrentContext(void) {
  return reinterpret_cast<OSMesaContext>(pineda::t_current_osmesa);
}

OSMESA_EXPORT void OSMesaPixelStore(GLint pname, GLint value) {
  OSMesaState* s = pineda::t_current_osmesa;
  if (s == nullptr) return;
  switch (pname) {
  case OSMESA_ROW_LENGTH:
    if (value < 0) return;
    s->row_length = value;
    break;
  case OSMESA_Y_UP:
    s->y_up = value != 0;
    break;
  default:
    return;
  }
  pineda::attach_surfaces(s);
}

OSMESA_EXPORT void OSMesaGetIntegerv(GLint pname, GLint* value) {
  OSMesaState* s = pineda::t_current_osmesa;
  if (value == nullptr) return;
  switch (pname) {
  case OSMESA_WIDTH:
    *value = s ? s->width : 0;
    break;
  case OSMESA_HEIGHT:
    *value = s ? s->height : 0;
    break;
  case OSMESA_FORMAT:
    *value = s ? static_cast<GLint>(s->format) : 0;
    break;
  case OSMESA_TYPE:
    *value = s ? static_cast<GLint>(s->type) : 0;
    break;
  case OSMESA_ROW_LENGTH:
    *value = s ? s->row_length : 0;
    break;
  case OSMESA_Y_UP:
    *value = s ? (s->y_up ? 1 : 0) : 0;
    break;
  case OSMESA_MAX_WIDTH:
  case OSMESA_MAX_HEIGHT:
    *value = pineda::kMaxSize;
    break;
  default:
    break;
  }
}

OSMESA_EXPORT GLboolean OSMesaGetDepthBuffer(OSMesaContext ctx, GLint* width, GLint* height,
                                             GLint* bytesPerValue, void** buffer) {
  auto* s = reinterpret_cast<OSMesaState*>(ctx);
  if (s == nullptr || s->depth_bits == 0 || s->depth.empty()) {
    if (width) *width = 0;
    if (height) *height = 0;
    if (bytesPerValue) *bytesPerValue = 0;
    if (buffer) *buffer = nullptr;
    return GL_FALSE;
  }
  // Depth values are stored one per 32-bit word, scaled to the depth buffer's bit count.
  if (width) *width = s->width;
  if (height) *height = s->height;
  if (bytesPerValue) *bytesPerValue = 4;
  if (buffer) *buffer = s->depth.data();
  return GL_TRUE;
}

OSMESA_EXPORT GLboolean OSMesaGetColorBuffer(OSMesaContext ctx, GLint* width, GLint* height,
                                             GLint* format, void** buffer) {
  auto* s = reinterpret_cast<OSMesaState*>(ctx);
  if (s == nullptr || s->buffer == nullptr) {
    if (width) *width = 0;
    if (height) *height = 0;
    if (format) *format = 0;
    if (buffer) *buffer = nullptr;
    return GL_FALSE;
  }
  if (width) *width = s->width;
  if (height) *height = s->height;
  if (format) *format = static_cast<GLint>(s->format);
  if (buffer) *buffer = s->buffer;
  return GL_TRUE;
}

// Mesa: clamping applies to float colour buffers. Pineda's buffers are 8-bit unsigned, where
// colours are always clamped, so the flag is recorded and has nothing further to change.
OSMESA_EXPORT void OSMesaColorClamp(GLboolean enable) {
  if (OSMesaState* s = pineda::t_current_osmesa) s->color_clamp = enable != GL_FALSE;
}

namespace {
struct OSMesaProc {
  const char* name;
  OSMESAproc proc;
};
const OSMesaProc kOSMesaProcs[] = {
    {"OSMesaCreateContext", reinterpret_cast<OSMESAproc>(&OSMesaCreateContext)},
    {"OSMesaCreateContextExt", reinterpret_cast<OSMESAproc>(&OSMesaCreateContextExt)},
    {"OSMesaCreateContextAttribs", reinterpret_cast<OSMESAproc>(&OSMesaCreateContextAttribs)},
    {"OSMesaDestroyContext", reinterpret_cast<OSMESAproc>(&OSMesaDestroyContext)},
    {"OSMesaMakeCurrent", reinterpret_cast<OSMESAproc>(&OSMesaMakeCurrent)},
    {"OSMesaGetCurrentContext", reinterpret_cast<OSMESAproc>(&OSMesaGetCurrentContext)},
    {"OSMesaPixelStore", reinterpret_cast<OSMESAproc>(&OSMesaPixelStore)},
    {"OSMesaGetIntegerv", reinterpret_cast<OSMESAproc>(&OSMesaGetIntegerv)},
    {"OSMesaGetDepthBuffer", reinterpret_cast<OSMESAproc>(&OSMesaGetDepthBuffer)},
    {"OSMesaGetColorBuffer", reinterpret_cast<OSMESAproc>(&OSMesaGetColorBuffer)},
    {"OSMesaColorClamp", reinterpret_cast<OSMESAproc>(&OSMesaColorClamp)},
    {"OSMesaGetProcAddress", reinterpret_cast<OSMESAproc>(&OSMesaGetProcAddress)},
};
} // namespace

OSMESA_EXPORT OSMESAproc OSMesaGetProcAddress(const char* funcName) {
  if (funcName == nullptr) return nullptr;
  for (const OSMesaProc& p : kOSMesaProcs)
    if (std::strcmp(p.name, funcName) == 0) return p.proc;
  return reinterpret_cast<OSMESAproc>(pineda::lookup_gl_proc(funcName));
}
