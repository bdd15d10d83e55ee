// Reduction of RasterState + Framebuffer to the StateKey that selects fragment code.
#include "fragment/state_key.h"

#include "fragment/blend.h"

namespace pineda {

StateKey make_state_key(const RasterState& rs, const Framebuffer& fb) {
  StateKey k;
  // GL 2.1 §4.1.6: with no depth buffer the depth test always passes and nothing is written,
  // which is exactly the disabled path.
  k.depth_test = rs.depth_test && fb.depth != nullptr && fb.depth_bits > 0;
  if (k.depth_test) {
    k.depth_func = depth_func_bits(rs.depth_func);
    k.depth_write = rs.depth_write;
  }
  k.format = fb.color_format;
  k.has_alpha = fb.color_format != ColorFormat::RGB8 && fb.alpha_bits > 0;
  if (fb.color != nullptr) {
    for (int i = 0; i < 4; ++i)
      if (rs.color_write[i]) k.color_mask |= static_cast<uint8_t>(1u << i);
    k.color_mask &= k.all_channels();
  }
  k.alpha_test = rs.alpha_test && rs.alpha_func != GL_ALWAYS;
  k.count_samples = rs.count_samples;
  // GL 2.1 §4.1.5: without a stencil buffer the test always passes and nothing is written.
  // A test that always passes and never writes is the same as no test.
  // Either face's state may decide (§4.1.5, back-facing polygons use the back face's).
  const auto face_acts = [](const StencilFace& f) {
    const bool writes = (f.writemask & 0xffu) != 0 &&
                        (f.fail != GL_KEEP || f.depth_fail != GL_KEEP || f.depth_pass != GL_KEEP);
    return f.func != GL_ALWAYS || writes;
  };
  k.stencil_test = rs.stencil_test && fb.stencil != nullptr && fb.stencil_bits > 0 &&
                   (face_acts(rs.stencil) || face_acts(rs.stencil_back));
  if (rs.logic_op) {
    // GL 2.1 §4.1.10: the logical operation replaces blending; COPY stores the source.
    k.logic_op = k.color_mask != 0 && rs.logic_op_mode != GL_COPY;
  } else if (k.color_mask != 0 && rs.blend && !blend_is_store(rs)) {
    k.blend = true;
    k.blend_over = rs.blend_state.src_rgb == GL_SRC_ALPHA &&
                   rs.blend_state.dst_rgb == GL_ONE_MINUS_SRC_ALPHA &&
                   rs.blend_state.src_a == GL_SRC_ALPHA &&
                   rs.blend_state.dst_a == GL_ONE_MINUS_SRC_ALPHA &&
                   rs.blend_state.eq_rgb == GL_FUNC_ADD && rs.blend_state.eq_a == GL_FUNC_ADD;
  }
  return k;
}

DepthPath StateKey::depth_path() const {
  if (!depth_test) return DepthPath::Off;
  if (depth_write && depth_func == depth_func_bits(GL_LESS)) return DepthPath::LessWrite;
  if (depth_write && depth_func == depth_func_bits(GL_LEQUAL)) return DepthPath::LequalWrite;
  return DepthPath::Generic;
}

ColorPath StateKey::color_path() const {
  if (color_mask == 0) return ColorPath::None;
  return color_mask == all_channels() ? ColorPath::All : ColorPath::Partial;
}

BlendPath StateKey::blend_path() const {
  if (!blend) return BlendPath::Off;
  return blend_over ? BlendPath::Over : BlendPath::Generic;
}

} // namespace pineda
