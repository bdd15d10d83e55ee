// Blending state (GL 2.1 §4.1.8; BlendFuncSeparate, BlendColor and BlendEquation are core
// since GL 1.4, BlendEquationSeparate since GL 2.0 and EXT_blend_equation_separate).
#include "state/api_util.h"
#include "dispatch.h"

namespace pineda {

namespace {

bool valid_equation(GLenum mode) {
  switch (mode) {
  case GL_FUNC_ADD:
  case GL_FUNC_SUBTRACT:
  case GL_FUNC_REVERSE_SUBTRACT:
  case GL_MIN:
  case GL_MAX:
    return true;
  default:
    return false;
  }
}

bool valid_factor(GLenum f, bool is_src) {
  switch (f) {
  case GL_ZERO:
  case GL_ONE:
  case GL_SRC_COLOR:
  case GL_ONE_MINUS_SRC_COLOR:
  case GL_DST_COLOR:
  case GL_ONE_MINUS_DST_COLOR:
  case GL_SRC_ALPHA:
  case GL_ONE_MINUS_SRC_ALPHA:
  case GL_DST_ALPHA:
  case GL_ONE_MINUS_DST_ALPHA:
  case GL_CONSTANT_COLOR:
  case GL_ONE_MINUS_CONSTANT_COLOR:
  case GL_CONSTANT_ALPHA:
  case GL_ONE_MINUS_CONSTANT_ALPHA:
    return true;
  // GL 2.1 Table 4.2: SRC_ALPHA_SATURATE is a source factor only.
  case GL_SRC_ALPHA_SATURATE:
    return is_src;
  default:
    return false;
  }
}

void set_blend_func(const char* func, GLenum src_rgb, GLenum dst_rgb, GLenum src_a, GLenum dst_a) {
  PINEDA_CTX_OUTSIDE(func);
  if (!valid_factor(src_rgb, true)) return record_error(ctx, GL_INVALID_ENUM, func, src_rgb);
  if (!valid_factor(dst_rgb, false)) return record_error(ctx, GL_INVALID_ENUM, func, dst_rgb);
  if (!valid_factor(src_a, true)) return record_error(ctx, GL_INVALID_ENUM, func, src_a);
  if (!valid_factor(dst_a, false)) return record_error(ctx, GL_INVALID_ENUM, func, dst_a);
  ctx->color_buffer.blend_state.src_rgb = src_rgb, ctx->color_buffer.blend_state.dst_rgb = dst_rgb;
  ctx->color_buffer.blend_state.src_a = src_a, ctx->color_buffer.blend_state.dst_a = dst_a;
  mark_dirty(ctx, kDirtyFragment);
}

} // namespace

namespace exec {

void GLAPIENTRY BlendFunc(GLenum src, GLenum dst) {
  set_blend_func("glBlendFunc", src, dst, src, dst);
}

void GLAPIENTRY BlendFuncSeparate(GLenum src_rgb, GLenum dst_rgb, GLenum src_a, GLenum dst_a) {
  set_blend_func("glBlendFuncSeparate", src_rgb, dst_rgb, src_a, dst_a);
}

void GLAPIENTRY BlendEquation(GLenum mode) {
  PINEDA_CTX_OUTSIDE("glBlendEquation");
  if (!valid_equation(mode)) return record_error(ctx, GL_INVALID_ENUM, "glBlendEquation", mode);
  ctx->color_buffer.blend_state.eq_rgb = ctx->color_buffer.blend_state.eq_a = mode;
  mark_dirty(ctx, kDirtyFragment);
}

// GL 2.1 §4.1.8 (EXT_blend_equation_separate): one equation for RGB, one for alpha.
void GLAPIENTRY BlendEquationSeparate(GLenum mode_rgb, GLenum mode_alpha) {
  PINEDA_CTX_OUTSIDE("glBlendEquationSeparate");
  if (!valid_equation(mode_rgb))
    return record_error(ctx, GL_INVALID_ENUM, "glBlendEquationSeparate", mode_rgb);
  if (!valid_equation(mode_alpha))
    return record_error(ctx, GL_INVALID_ENUM, "glBlendEquationSeparate", mode_alpha);
  ctx->color_buffer.blend_state.eq_rgb = mode_rgb;
  ctx->color_buffer.blend_state.eq_a = mode_alpha;
  mark_dirty(ctx, kDirtyFragment);
}

void GLAPIENTRY BlendColor(GLclampf r, GLclampf g, GLclampf b, GLclampf a) {
  PINEDA_CTX_OUTSIDE("glBlendColor");
  // GL 2.1 §4.1.8: the constant colour is clamped to [0,1] when specified.
  ctx->color_buffer.blend_state.color[0] = clampf01(r);
  ctx->color_buffer.blend_state.color[1] = clampf01(g);
  ctx->color_buffer.blend_state.color[2] = clampf01(b);
  ctx->color_buffer.blend_state.color[3] = clampf01(a);
  mark_dirty(ctx, kDirtyFragment);
}

} // namespace exec
} // namespace pineda
