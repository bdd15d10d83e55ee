// glDrawBuffer (GL 2.1 §4.2.1) and glReadBuffer (§4.3.2): which of the context's colour
// buffers drawing writes and glReadPixels reads. The buffers a context has are
// Context::color_buffers, set by the window-system layer. The framebuffer area (Table 6.35):
// the framebuffer's configuration for glGet.
#include <algorithm>

#include "state/api_util.h"
#include "dispatch.h"
#include "state/area.h"
#include "state/draw_read_buffer.h"

namespace pineda {

namespace {

constexpr uint32_t kFront = kColorBufferFrontLeft | kColorBufferFrontRight;
constexpr uint32_t kBack = kColorBufferBackLeft | kColorBufferBackRight;
constexpr uint32_t kLeft = kColorBufferFrontLeft | kColorBufferBackLeft;
constexpr uint32_t kRight = kColorBufferFrontRight | kColorBufferBackRight;

// The buffers a DrawBuffer constant indicates (GL 2.1 table 4.4). False for enums that are
// not such constants. AUXi names an auxiliary buffer, and Pineda has none (AUX_BUFFERS is 0),
// so it indicates no buffer the context has.
bool draw_buffer_set(GLenum buf, uint32_t* set) {
  switch (buf) {
  case GL_FRONT_LEFT:
    *set = kColorBufferFrontLeft;
    return true;
  case GL_FRONT_RIGHT:
    *set = kColorBufferFrontRight;
    return true;
  case GL_BACK_LEFT:
    *set = kColorBufferBackLeft;
    return true;
  case GL_BACK_RIGHT:
    *set = kColorBufferBackRight;
    return true;
  case GL_FRONT:
    *set = kFront;
    return true;
  case GL_BACK:
    *set = kBack;
    return true;
  case GL_LEFT:
    *set = kLeft;
    return true;
  case GL_RIGHT:
    *set = kRight;
    return true;
  case GL_FRONT_AND_BACK:
    *set = kFront | kBack;
    return true;
  case GL_AUX0:
  case GL_AUX1:
  case GL_AUX2:
  case GL_AUX3:
    *set = 0;
    return true;
  default:
    return false;
  }
}

// The one buffer a ReadBuffer constant names (GL 2.1 §4.3.2): FRONT and LEFT are the front
// left buffer, BACK the back left, RIGHT the front right. FRONT_AND_BACK and NONE are not
// among the GL 2.1 constants.
bool read_buffer_named(GLenum src, uint32_t* buffer) {
  switch (src) {
  case GL_FRONT_LEFT:
  case GL_FRONT:
  case GL_LEFT:
    *buffer = kColorBufferFrontLeft;
    return true;
  case GL_FRONT_RIGHT:
  case GL_RIGHT:
    *buffer = kColorBufferFrontRight;
    return true;
  case GL_BACK_LEFT:
  case GL_BACK:
    *buffer = kColorBufferBackLeft;
    return true;
  case GL_BACK_RIGHT:
    *buffer = kColorBufferBackRight;
    return true;
  case GL_AUX0:
  case GL_AUX1:
  case GL_AUX2:
  case GL_AUX3:
    *buffer = 0;
    return true;
  default:
    return false;
  }
}

// Table 6.35: the framebuffer's configuration (RGBA visuals only, no stereo, no auxiliary
// buffers).
bool get_framebuffer(Context& ctx, GLenum pname, QueryValues& out) {
  const Framebuffer& fb = ctx.fb;
  switch (pname) {
  case GL_RED_BITS:
  case GL_GREEN_BITS:
  case GL_BLUE_BITS:
    out.ints({fb.color ? 8.0 : 0.0});
    return true;
  case GL_ALPHA_BITS:
    out.ints({fb.color ? double(fb.alpha_bits) : 0.0});
    return true;
  case GL_DEPTH_BITS:
    out.ints({fb.depth ? double(fb.depth_bits) : 0.0});
    return true;
  case GL_STENCIL_BITS:
    out.ints({fb.stencil ? double(fb.stencil_bits) : 0.0});
    return true;
  case GL_AUX_BUFFERS:
  case GL_INDEX_BITS:
    out.ints({0});
    return true;
  case GL_RGBA_MODE:
    out.boolean(true);
    return true;
  case GL_INDEX_MODE:
  case GL_DOUBLEBUFFER:
  case GL_STEREO:
    out.boolean(false);
    return true;
  default:
    return false;
  }
}

// After the draw buffer (COLOR_BUFFER_BIT) or the read buffer (PIXEL_MODE_BIT) was restored.
uint32_t buffers_restored(Context& ctx, GLbitfield mask) {
  if ((mask & (GL_COLOR_BUFFER_BIT | GL_PIXEL_MODE_BIT)) != 0) select_color_buffers(&ctx);
  return 0;
}

} // namespace

const StateArea kFramebufferArea = {
    .name = "framebuffer (GL 2.1 §4.2.1, §4.3.2, Tables 6.21, 6.35)",
    .get = get_framebuffer,
    .restored = buffers_restored,
};

void select_color_buffers(Context* ctx) {
  Framebuffer& fb = ctx->fb;
  if (fb.front_color == nullptr || fb.back_color == nullptr) return;
  uint32_t set = 0;
  if (ctx->color_buffer.draw_buffer == GL_NONE ||
      !draw_buffer_set(ctx->color_buffer.draw_buffer, &set))
    set = kBack;
  set &= ctx->color_buffers;
  // GL 2.1 §4.2.1: fragments go to every buffer the draw buffer indicates; the back buffer is
  // the primary target so that BACK-only drawing costs one pass.
  const bool front = (set & kFront) != 0, back = (set & kBack) != 0;
  fb.color = back || !front ? fb.back_color : fb.front_color;
  fb.color_also = front && back ? fb.front_color : nullptr;
  uint32_t rb = 0;
  if (!read_buffer_named(ctx->pixel.read_buffer, &rb)) rb = kColorBufferBackLeft;
  fb.read_color = (rb & kFront) != 0 ? fb.front_color : fb.back_color;
  if ((front || fb.read_color == fb.front_color) && ctx->front_selected != nullptr)
    ctx->front_selected(ctx);
  mark_dirty(ctx, kDirtyFramebuffer);
}

namespace exec {

void GLAPIENTRY DrawBuffer(GLenum buf) {
  PINEDA_CTX_OUTSIDE("glDrawBuffer");
  if (buf != GL_NONE) {
    uint32_t set = 0;
    if (!draw_buffer_set(buf, &set)) return record_error(ctx, GL_INVALID_ENUM, "glDrawBuffer", buf);
    // GL 2.1 §4.2.1: a constant other than NONE that indicates none of the context's colour
    // buffers is INVALID_OPERATION.
    if ((set & ctx->color_buffers) == 0)
      return record_error(ctx, GL_INVALID_OPERATION, "glDrawBuffer", buf);
  }
  ctx->color_buffer.draw_buffer = buf;
  select_color_buffers(ctx);
  mark_dirty(ctx, kDirtyFragment);
}

void GLAPIENTRY ReadBuffer(GLenum src) {
  PINEDA_CTX_OUTSIDE("glReadBuffer");
  uint32_t buffer = 0;
  if (!read_buffer_named(src, &buffer))
    return record_error(ctx, GL_INVALID_ENUM, "glReadBuffer", src);
  // GL 2.1 §4.3.2: a missing buffer is INVALID_OPERATION.
  if ((buffer & ctx->color_buffers) == 0)
    return record_error(ctx, GL_INVALID_OPERATION, "glReadBuffer", src);
  ctx->pixel.read_buffer = src;
  select_color_buffers(ctx);
}

} // namespace exec
} // namespace pineda
