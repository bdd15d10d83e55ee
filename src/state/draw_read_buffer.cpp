// glDrawBuffer (GL 2.1 §4.2.1), glDrawBuffers (GL 2.0 §4.2.1) and glReadBuffer (§4.3.2): which
// colour buffers drawing writes and reading reads, of the window (Context::color_buffers, set
// by the window-system layer) or of the bound framebuffer object (COLOR_ATTACHMENTi,
// ARB_framebuffer_object §4.2.1). framebuffer_object.cpp derives the framebuffers from them.
// The framebuffer area (Table 6.35): the draw framebuffer's configuration for glGet.
#include <GL/glext.h>

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
// left buffer, BACK the back left, RIGHT the front right. FRONT_AND_BACK is not among them.
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

bool is_color_attachment(GLenum buf) {
  return buf >= GL_COLOR_ATTACHMENT0 && buf <= GL_COLOR_ATTACHMENT15;
}

// The error of naming `buf` as a draw or read buffer of the bound framebuffer (`object`: a
// framebuffer object), GL_NO_ERROR when it is allowed. ARB_framebuffer_object §4.2.1, §4.3.2:
// a framebuffer object takes NONE and COLOR_ATTACHMENTi (i < MAX_COLOR_ATTACHMENTS); the
// window's constants there, or COLOR_ATTACHMENTi on the window, are INVALID_OPERATION.
GLenum object_buffer_error(GLenum buf) {
  if (is_color_attachment(buf))
    return buf - GL_COLOR_ATTACHMENT0 < GLenum(kMaxColorAttachments) ? GL_NO_ERROR
                                                                     : GL_INVALID_OPERATION;
  uint32_t set = 0;
  return draw_buffer_set(buf, &set) ? GL_INVALID_OPERATION : GL_INVALID_ENUM;
}

// Table 6.35: the draw framebuffer's configuration (RGBA only, no stereo, no auxiliary
// buffers), and the draw and read buffers (Tables 6.21, 6.23).
bool get_framebuffer(Context& ctx, GLenum pname, QueryValues& out) {
  sync_framebuffers(&ctx);
  const Framebuffer& fb = ctx.fb;
  const bool color = ctx.fbo.draw_binding == 0 ? ctx.window.color != nullptr : fb.color != nullptr;
  if (pname >= GL_DRAW_BUFFER0 && pname < GL_DRAW_BUFFER0 + kMaxDrawBuffers) {
    out.ints({double(ctx.color_buffer.draw_buffers[pname - GL_DRAW_BUFFER0])});
    return true;
  }
  switch (pname) {
  case GL_DRAW_BUFFER:
    out.ints({double(ctx.color_buffer.draw_buffers[0])});
    return true;
  case GL_MAX_DRAW_BUFFERS:
    out.ints({double(kMaxDrawBuffers)});
    return true;
  case GL_RED_BITS:
  case GL_GREEN_BITS:
  case GL_BLUE_BITS:
    out.ints({color ? 8.0 : 0.0});
    return true;
  case GL_ALPHA_BITS:
    out.ints({color ? double(fb.alpha_bits) : 0.0});
    return true;
  case GL_DEPTH_BITS:
    out.ints({fb.depth ? double(fb.depth_bits) : 0.0});
    return true;
  case GL_STENCIL_BITS:
    out.ints({fb.stencil ? double(fb.stencil_bits) : 0.0});
    return true;
  case GL_AUX_BUFFERS:
  case GL_INDEX_BITS:
  case GL_SAMPLE_BUFFERS:
  case GL_SAMPLES:
    out.ints({0});
    return true;
  case GL_RGBA_MODE:
    out.boolean(true);
    return true;
  case GL_INDEX_MODE:
  case GL_STEREO:
    out.boolean(false);
    return true;
  case GL_DOUBLEBUFFER:
    out.boolean(ctx.fbo.draw_binding == 0 && (ctx.color_buffers & kBack) != 0 &&
                ctx.window.front_color != nullptr);
    return true;
  default:
    return false;
  }
}

} // namespace

const StateArea kFramebufferArea = {
    .name = "framebuffer (GL 2.1 §4.2.1, §4.3.2, Tables 6.21, 6.35)",
    .get = get_framebuffer,
};

namespace exec {

void GLAPIENTRY DrawBuffer(GLenum buf) {
  PINEDA_CTX_OUTSIDE("glDrawBuffer");
  if (ctx->fbo.draw_binding != 0) {
    const GLenum err = buf == GL_NONE ? GL_NO_ERROR : object_buffer_error(buf);
    if (err != GL_NO_ERROR) return record_error(ctx, err, "glDrawBuffer", buf);
  } else if (buf != GL_NONE) {
    uint32_t set = 0;
    if (!draw_buffer_set(buf, &set))
      return record_error(ctx, is_color_attachment(buf) ? GL_INVALID_OPERATION : GL_INVALID_ENUM,
                          "glDrawBuffer", buf);
    // GL 2.1 §4.2.1: a constant other than NONE that indicates none of the context's colour
    // buffers is INVALID_OPERATION.
    if ((set & ctx->color_buffers) == 0)
      return record_error(ctx, GL_INVALID_OPERATION, "glDrawBuffer", buf);
  }
  // GL 2.0 §4.2.1: DrawBuffer sets DRAW_BUFFER0 and makes the others NONE.
  GLenum* db = ctx->color_buffer.draw_buffers;
  db[0] = buf;
  std::fill(db + 1, db + kMaxDrawBuffers, GLenum(GL_NONE));
  framebuffers_changed(ctx);
  mark_dirty(ctx, kDirtyFragment);
  if (ctx->fbo.draw_binding == 0 && buf != GL_NONE && ctx->front_selected != nullptr) {
    uint32_t set = 0;
    draw_buffer_set(buf, &set);
    if ((set & kFront) != 0 && ctx->window.back_color != nullptr) ctx->front_selected(ctx);
  }
}

void GLAPIENTRY DrawBuffers(GLsizei n, const GLenum* bufs) {
  PINEDA_CTX_OUTSIDE("glDrawBuffers");
  if (n < 0 || n > kMaxDrawBuffers) return record_error(ctx, GL_INVALID_VALUE, "glDrawBuffers");
  if (n > 0 && bufs == nullptr) return;
  const bool object = ctx->fbo.draw_binding != 0;
  uint32_t seen = 0;
  bool front = false;
  for (GLsizei i = 0; i < n; ++i) {
    const GLenum b = bufs[i];
    if (b == GL_NONE) continue;
    if (object) {
      const GLenum err = object_buffer_error(b);
      if (err != GL_NO_ERROR) return record_error(ctx, err, "glDrawBuffers", b);
    } else {
      // GL 2.0 §4.2.1: each buffer of bufs is one buffer (Table 4.5): FRONT, BACK, LEFT,
      // RIGHT and FRONT_AND_BACK, which name several, are INVALID_ENUM here; a buffer the
      // context lacks is INVALID_OPERATION.
      uint32_t set = 0;
      if (!draw_buffer_set(b, &set) || b == GL_FRONT || b == GL_BACK || b == GL_LEFT ||
          b == GL_RIGHT || b == GL_FRONT_AND_BACK)
        return record_error(ctx, is_color_attachment(b) ? GL_INVALID_OPERATION : GL_INVALID_ENUM,
                            "glDrawBuffers", b);
      if ((set & ctx->color_buffers) == 0)
        return record_error(ctx, GL_INVALID_OPERATION, "glDrawBuffers", b);
      front = front || (set & kFront) != 0;
    }
    // A buffer named twice (other than NONE) is INVALID_OPERATION.
    const uint32_t bit = object ? 1u << (b - GL_COLOR_ATTACHMENT0) : 1u << (b & 31u);
    const bool twice = object ? (seen & bit) != 0 : std::find(bufs, bufs + i, b) != bufs + i;
    if (twice) return record_error(ctx, GL_INVALID_OPERATION, "glDrawBuffers", b);
    seen |= bit;
  }
  GLenum* db = ctx->color_buffer.draw_buffers;
  for (int i = 0; i < kMaxDrawBuffers; ++i)
    db[i] = i < n ? bufs[i] : GLenum(GL_NONE);
  framebuffers_changed(ctx);
  mark_dirty(ctx, kDirtyFragment);
  if (front && ctx->window.back_color != nullptr && ctx->front_selected != nullptr)
    ctx->front_selected(ctx);
}

void GLAPIENTRY ReadBuffer(GLenum src) {
  PINEDA_CTX_OUTSIDE("glReadBuffer");
  if (ctx->fbo.read_binding != 0) {
    const GLenum err = src == GL_NONE ? GL_NO_ERROR : object_buffer_error(src);
    if (err != GL_NO_ERROR) return record_error(ctx, err, "glReadBuffer", src);
  } else {
    // GL 2.1 §4.3.2: NONE is not a window's read buffer (a framebuffer object's may be NONE).
    uint32_t buffer = 0;
    if (!read_buffer_named(src, &buffer))
      return record_error(ctx, is_color_attachment(src) ? GL_INVALID_OPERATION : GL_INVALID_ENUM,
                          "glReadBuffer", src);
    // GL 2.1 §4.3.2: a missing buffer is INVALID_OPERATION.
    if ((buffer & ctx->color_buffers) == 0)
      return record_error(ctx, GL_INVALID_OPERATION, "glReadBuffer", src);
  }
  ctx->pixel.read_buffer = src;
  framebuffers_changed(ctx);
  if (ctx->fbo.read_binding == 0 && ctx->window.back_color != nullptr &&
      ctx->front_selected != nullptr) {
    uint32_t buffer = 0;
    if (read_buffer_named(src, &buffer) && (buffer & kFront) != 0) ctx->front_selected(ctx);
  }
}

} // namespace exec
} // namespace pineda
