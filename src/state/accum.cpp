// glAccum and glClearAccum (GL 2.1 §4.2.4), and the accumulation part of glClear (§4.2.3).
// The arithmetic is in framebuffer/accum.cpp.
#include <algorithm>
#include <cstdint>

#include "state/api_util.h"
#include "dispatch.h"
#include "framebuffer/accum.h"
#include "state/area.h"

namespace pineda {

namespace {

// The framebuffer, narrowed by the scissor box when the scissor test is on: Accum and the
// accumulation clear both honour the scissor (GL 2.1 §4.2.3, §4.2.4, as Mesa does).
AccumRect accum_rect(const Context* ctx) {
  AccumRect r{0, 0, ctx->fb.width, ctx->fb.height};
  if (ctx->scissor.test) {
    const GLint* s = ctx->scissor.box;
    r.x0 = std::max(r.x0, s[0]);
    r.y0 = std::max(r.y0, s[1]);
    r.x1 = static_cast<int>(std::min<int64_t>(r.x1, int64_t{s[0]} + s[2]));
    r.y1 = static_cast<int>(std::min<int64_t>(r.y1, int64_t{s[1]} + s[3]));
  }
  return r;
}

float clamp_signed(float v) {
  if (!(v == v)) return 0.0f; // NaN: the result is open (GL 2.1 §2.1.1); 0 keeps it finite
  return v > -1.0f ? (v < 1.0f ? v : 1.0f) : -1.0f;
}

} // namespace

void accum_clear(Context* ctx) {
  if (ctx->fb.accum == nullptr) return; // GL 2.1 §4.2.3: no such buffer, no effect
  accum_fill(ctx->fb, ctx->accum.clear, accum_rect(ctx));
}

namespace {

bool get_accum(Context& ctx, GLenum pname, QueryValues& out) {
  switch (pname) {
  // GL 2.1 Table 6.34: 16 signed bits per channel, as Mesa allocates for any request.
  case GL_ACCUM_RED_BITS:
  case GL_ACCUM_GREEN_BITS:
  case GL_ACCUM_BLUE_BITS:
  case GL_ACCUM_ALPHA_BITS:
    out.ints({ctx.fb.accum != nullptr ? double(ctx.fb.accum_bits) : 0.0});
    return true;
  case GL_ACCUM_CLEAR_VALUE:
    out.normalized(ctx.accum.clear, 4);
    return true;
  default:
    return false;
  }
}

constexpr AttribGroup kAccumGroups[] = {
    member_group<&Context::accum>(GL_ACCUM_BUFFER_BIT, 0),
};

} // namespace

const StateArea kAccumArea = {
    .name = "accumulation buffer (GL 2.1 §4.2.4, Table 6.22)",
    .get = get_accum,
    .groups = kAccumGroups,
};

namespace exec {

void GLAPIENTRY Accum(GLenum op, GLfloat value) {
  PINEDA_CTX_OUTSIDE("glAccum");
  switch (op) {
  case GL_ACCUM:
  case GL_LOAD:
  case GL_RETURN:
  case GL_MULT:
  case GL_ADD:
    break;
  default:
    return record_error(ctx, GL_INVALID_ENUM, "glAccum", op);
  }
  // GL 2.1 §4.2.4: INVALID_OPERATION without an accumulation buffer.
  if (ctx->fb.accum == nullptr) return record_error(ctx, GL_INVALID_OPERATION, "glAccum");
  // §5.2, §5.3: no framebuffer updates in SELECT and FEEDBACK mode.
  if (!draw_framebuffer_ready(ctx, "glAccum") || !read_framebuffer_ready(ctx, "glAccum")) return;
  if (!render_mode_is_render(ctx) || ctx->fb.color == nullptr) return;
  // RETURN writes the colour buffers selected for drawing through the colour mask
  // (§4.2.4); with the draw buffer NONE there are none.
  bool write[4];
  for (int k = 0; k < 4; ++k)
    write[k] = ctx->color_buffer.color_mask[k];
  // §4.2.4: LOAD and ACCUM read the read buffer; RETURN writes every draw buffer.
  if (op != GL_RETURN) {
    if (ctx->read_fb.color == nullptr) return;
    Framebuffer source = ctx->read_fb;
    source.accum = ctx->fb.accum;
    return accum_apply(source, op, value, accum_rect(ctx), write);
  }
  accum_apply(ctx->fb, op, value, accum_rect(ctx), write);
  for (int i = 0; i < ctx->fb.more_count; ++i) {
    Framebuffer other = ctx->fb.with_color(ctx->fb.more[i]);
    accum_apply(other, op, value, accum_rect(ctx), write);
  }
}

void GLAPIENTRY ClearAccum(GLfloat r, GLfloat g, GLfloat b, GLfloat a) {
  PINEDA_CTX_OUTSIDE("glClearAccum");
  // Table 6.22: ACCUM_CLEAR_VALUE is clamped to [-1, 1].
  ctx->accum.clear[0] = clamp_signed(r);
  ctx->accum.clear[1] = clamp_signed(g);
  ctx->accum.clear[2] = clamp_signed(b);
  ctx->accum.clear[3] = clamp_signed(a);
}

} // namespace exec
} // namespace pineda
