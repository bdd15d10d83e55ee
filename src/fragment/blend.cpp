// GL blend state to the fragment stage's dense encoding (GL 2.1 §4.1.8).
#include "fragment/blend.h"

namespace pineda {

BlendFactor blend_factor_from_gl(GLenum factor) {
  switch (factor) {
  case GL_ZERO:
    return BlendFactor::Zero;
  case GL_ONE:
    return BlendFactor::One;
  case GL_SRC_COLOR:
    return BlendFactor::SrcColor;
  case GL_ONE_MINUS_SRC_COLOR:
    return BlendFactor::OneMinusSrcColor;
  case GL_DST_COLOR:
    return BlendFactor::DstColor;
  case GL_ONE_MINUS_DST_COLOR:
    return BlendFactor::OneMinusDstColor;
  case GL_SRC_ALPHA:
    return BlendFactor::SrcAlpha;
  case GL_ONE_MINUS_SRC_ALPHA:
    return BlendFactor::OneMinusSrcAlpha;
  case GL_DST_ALPHA:
    return BlendFactor::DstAlpha;
  case GL_ONE_MINUS_DST_ALPHA:
    return BlendFactor::OneMinusDstAlpha;
  case GL_CONSTANT_COLOR:
    return BlendFactor::ConstColor;
  case GL_ONE_MINUS_CONSTANT_COLOR:
    return BlendFactor::OneMinusConstColor;
  case GL_CONSTANT_ALPHA:
    return BlendFactor::ConstAlpha;
  case GL_ONE_MINUS_CONSTANT_ALPHA:
    return BlendFactor::OneMinusConstAlpha;
  case GL_SRC_ALPHA_SATURATE:
    return BlendFactor::SrcAlphaSaturate;
  default:
    return BlendFactor::One; // the front end rejects other enums with GL_INVALID_ENUM
  }
}

BlendEq blend_eq_from_gl(GLenum eq) {
  switch (eq) {
  case GL_FUNC_SUBTRACT:
    return BlendEq::Subtract;
  case GL_FUNC_REVERSE_SUBTRACT:
    return BlendEq::ReverseSubtract;
  case GL_MIN:
    return BlendEq::Min;
  case GL_MAX:
    return BlendEq::Max;
  default:
    return BlendEq::Add;
  }
}

BlendParams make_blend_params(const RasterState& rs) {
  BlendParams bp;
  bp.src_rgb = blend_factor_from_gl(rs.blend_state.src_rgb);
  bp.dst_rgb = blend_factor_from_gl(rs.blend_state.dst_rgb);
  bp.src_a = blend_factor_from_gl(rs.blend_state.src_a);
  bp.dst_a = blend_factor_from_gl(rs.blend_state.dst_a);
  bp.eq_rgb = blend_eq_from_gl(rs.blend_state.eq_rgb);
  bp.eq_a = blend_eq_from_gl(rs.blend_state.eq_a);
  for (int i = 0; i < 4; ++i) {
    const float c = rs.blend_state.color[i];
    bp.constant[i] = c > 0.0f ? (c < 1.0f ? c : 1.0f) : 0.0f;
  }
  return bp;
}

bool blend_is_store(const RasterState& rs) {
  const auto store_eq = [](GLenum eq, GLenum src, GLenum dst) {
    // MIN and MAX ignore the factors, so only ADD (and SUBTRACT, d*0 subtracted) with
    // ONE, ZERO leave the source unchanged.
    return (eq == GL_FUNC_ADD || eq == GL_FUNC_SUBTRACT) && src == GL_ONE && dst == GL_ZERO;
  };
  return store_eq(rs.blend_state.eq_rgb, rs.blend_state.src_rgb, rs.blend_state.dst_rgb) &&
         store_eq(rs.blend_state.eq_a, rs.blend_state.src_a, rs.blend_state.dst_a);
}

} // namespace pineda
