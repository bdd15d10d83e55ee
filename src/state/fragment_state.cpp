// State of the per-fragment tests and the logical operation (GL 2.1 §4.1.2 scissor, §4.1.4
// alpha test, §4.1.5 stencil test, §4.1.10 logical operation) and the stencil write mask
// (§4.2.2). The enables live in enable.cpp, the queries in get.cpp; validate.cpp copies the
// values into the RasterState.
#include "core/api_util.h"
#include "dispatch.h"

namespace pineda {

namespace {

// NEVER, LESS, EQUAL, LEQUAL, GREATER, NOTEQUAL, GEQUAL, ALWAYS: the comparison functions of
// the alpha and stencil tests (GL 2.1 §4.1.4, §4.1.5).
bool is_compare_func(GLenum func) { return func >= GL_NEVER && func <= GL_ALWAYS; }

// KEEP, ZERO, REPLACE, INCR, DECR, INVERT (GL 2.1 §4.1.5) and INCR_WRAP, DECR_WRAP (GL 1.4).
bool is_stencil_op(GLenum op) {
  switch (op) {
  case GL_KEEP:
  case GL_ZERO:
  case GL_REPLACE:
  case GL_INCR:
  case GL_DECR:
  case GL_INVERT:
  case GL_INCR_WRAP:
  case GL_DECR_WRAP: return true;
  default: return false;
  }
}

} // namespace

namespace exec {

void GLAPIENTRY Scissor(GLint x, GLint y, GLsizei width, GLsizei height) {
  PINEDA_CTX_OUTSIDE("glScissor");
  // GL 2.1 §4.1.2: a negative width or height is INVALID_VALUE.
  if (width < 0 || height < 0) return record_error(ctx, GL_INVALID_VALUE, "glScissor");
  ctx->scissor_box[0] = x;
  ctx->scissor_box[1] = y;
  ctx->scissor_box[2] = width;
  ctx->scissor_box[3] = height;
  mark_dirty(ctx, kDirtyFragment);
}

void GLAPIENTRY AlphaFunc(GLenum func, GLclampf ref) {
  PINEDA_CTX_OUTSIDE("glAlphaFunc");
  if (!is_compare_func(func)) return record_error(ctx, GL_INVALID_ENUM, "glAlphaFunc", func);
  ctx->alpha_func = func;
  // GL 2.1 §4.1.4: the reference is clamped to [0, 1] when specified.
  ctx->alpha_ref = clampf01(ref);
  mark_dirty(ctx, kDirtyFragment);
}

void GLAPIENTRY StencilFunc(GLenum func, GLint ref, GLuint mask) {
  PINEDA_CTX_OUTSIDE("glStencilFunc");
  if (!is_compare_func(func)) return record_error(ctx, GL_INVALID_ENUM, "glStencilFunc", func);
  ctx->stencil_func = func;
  // Kept as given: the clamp to [0, 2^s - 1] (GL 2.1 §4.1.5) depends on the stencil buffer
  // and is applied where the value is used or queried.
  ctx->stencil_ref = ref;
  ctx->stencil_value_mask = mask;
  mark_dirty(ctx, kDirtyFragment);
}

void GLAPIENTRY StencilOp(GLenum sfail, GLenum dpfail, GLenum dppass) {
  PINEDA_CTX_OUTSIDE("glStencilOp");
  for (GLenum op : {sfail, dpfail, dppass})
    if (!is_stencil_op(op)) return record_error(ctx, GL_INVALID_ENUM, "glStencilOp", op);
  ctx->stencil_fail = sfail;
  ctx->stencil_depth_fail = dpfail;
  ctx->stencil_depth_pass = dppass;
  mark_dirty(ctx, kDirtyFragment);
}

void GLAPIENTRY StencilMask(GLuint mask) {
  PINEDA_CTX_OUTSIDE("glStencilMask");
  // GL 2.1 §4.2.2: the low s bits are the mask; the value is kept whole, as given.
  ctx->stencil_writemask = mask;
  mark_dirty(ctx, kDirtyFragment);
}

void GLAPIENTRY LogicOp(GLenum opcode) {
  PINEDA_CTX_OUTSIDE("glLogicOp");
  // GL 2.1 table 4.3: CLEAR..SET are sixteen consecutive enums.
  if (opcode < GL_CLEAR || opcode > GL_SET)
    return record_error(ctx, GL_INVALID_ENUM, "glLogicOp", opcode);
  ctx->logic_op = opcode;
  mark_dirty(ctx, kDirtyFragment);
}

} // namespace exec
} // namespace pineda
