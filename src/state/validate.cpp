// Validation: derive the back end's plain RasterState and the composite matrix from the GL
// state, only for the groups marked dirty since the last draw.
#include <glm/matrix.hpp>

#include "core/context.h"
#include "geometry/geometry.h"
#include "geometry/light_eval.h"
#include "state/raster_modes_hooks.h"

namespace pineda {

void validate_texpipe(Context* ctx, uint32_t dirty); // validate_texpipe.cpp

void validate_state(Context* ctx) {
  // Texture objects change without the context's dirty bits (share groups): the sampler
  // snapshots are redone when the share group's generation moved (validate_texpipe.cpp).
  if (ctx->texpipe.any_target_enabled &&
      ctx->shared->texture_generation != ctx->texpipe.seen_generation)
    ctx->dirty |= kDirtyTexture;
  const uint32_t dirty = ctx->dirty;
  if (dirty == 0) return;
  RasterState& rs = ctx->raster;

  if (dirty & kDirtyTransform) {
    ctx->mvp = ctx->projection.top() * ctx->modelview.top();
  }
  if (dirty & kDirtyViewport) {
    rs.viewport.x = static_cast<float>(ctx->vp_x);
    rs.viewport.y = static_cast<float>(ctx->vp_y);
    rs.viewport.w = static_cast<float>(ctx->vp_w);
    rs.viewport.h = static_cast<float>(ctx->vp_h);
    rs.viewport.near = static_cast<float>(ctx->depth_near);
    rs.viewport.far = static_cast<float>(ctx->depth_far);
  }
  if (dirty & (kDirtyClipPlanes | kDirtyTransform)) {
    // GL 2.1 §2.12: a point is inside a user plane when dot(plane_eye, eye) >= 0. With
    // clip = P * eye that equals dot(plane_eye * P^-1, clip), so the test moves to clip space
    // and eye coordinates are never computed.
    rs.user_clip_mask = 0;
    const glm::dmat4 inv_p = glm::inverse(glm::dmat4(ctx->projection.top()));
    for (int i = 0; i < kMaxClipPlanes; ++i) {
      if (!ctx->clip_enabled[i]) continue;
      const double* e = ctx->clip_plane[i];
      const glm::dvec4 c = glm::dvec4(e[0], e[1], e[2], e[3]) * inv_p;
      for (int k = 0; k < 4; ++k) rs.user_planes[i][k] = static_cast<float>(c[k]);
      rs.user_clip_mask |= 1u << i;
    }
  }
  if (dirty & kDirtyPolygon) {
    rs.cull_enabled = ctx->cull_enabled;
    rs.cull_face = ctx->cull_face;
    rs.front_face = ctx->front_face;
    rs.polygon_mode[0] = ctx->polygon_mode[0];
    rs.polygon_mode[1] = ctx->polygon_mode[1];
    rs.flat = ctx->shade_model == GL_FLAT;
  }
  if (dirty & (kDirtyFragment | kDirtyFramebuffer)) {
    // GL 2.1 §4.1.6: without a depth buffer the depth test always passes and nothing is
    // written, which is the same as the test being off.
    rs.depth_test = ctx->depth_test && ctx->fb.depth != nullptr;
    rs.depth_func = ctx->depth_func;
    rs.depth_write = ctx->depth_mask;
    // GL 2.1 §4.2.1: with the draw buffer NONE no colour is written.
    const bool draws_color = ctx->draw_buffer != GL_NONE;
    for (int i = 0; i < 4; ++i) rs.color_write[i] = ctx->color_mask[i] && draws_color;
    rs.blend = ctx->blend;
    rs.blend_src_rgb = ctx->blend_src_rgb;
    rs.blend_dst_rgb = ctx->blend_dst_rgb;
    rs.blend_src_a = ctx->blend_src_a;
    rs.blend_dst_a = ctx->blend_dst_a;
    rs.blend_eq_rgb = ctx->blend_eq_rgb;
    rs.blend_eq_a = ctx->blend_eq_a;
    for (int i = 0; i < 4; ++i) rs.blend_color[i] = ctx->blend_color[i];
    rs.scissor_test = ctx->scissor_test;
    for (int i = 0; i < 4; ++i) rs.scissor[i] = ctx->scissor_box[i];
    rs.alpha_test = ctx->alpha_test;
    rs.alpha_func = ctx->alpha_func;
    rs.alpha_ref = ctx->alpha_ref;
    // GL 2.1 §4.1.5: without a stencil buffer the test always passes and writes nothing.
    rs.stencil_test = ctx->stencil_test && ctx->fb.stencil != nullptr;
    rs.stencil_func = ctx->stencil_func;
    rs.stencil_ref = ctx->stencil_ref;
    rs.stencil_value_mask = ctx->stencil_value_mask;
    rs.stencil_fail = ctx->stencil_fail;
    rs.stencil_depth_fail = ctx->stencil_depth_fail;
    rs.stencil_depth_pass = ctx->stencil_depth_pass;
    rs.stencil_writemask = ctx->stencil_writemask;
    rs.logic_op = ctx->color_logic_op;
    rs.logic_op_mode = ctx->logic_op;
  }
  if (dirty & (kDirtyLighting | kDirtyTransform)) {
    // GL 2.1 §2.14.1: light positions are already in eye space; the normal matrix and the
    // per-light constants depend on the model-view matrix.
    const LightingState& ls = ctx->lighting;
    if (ls.enabled)
      setup_lighting(ctx->lighting.setup, ls, ctx->modelview.top(), ctx->normalize,
                     ctx->rescale_normal);
    // §2.14.1: back colours are computed and selected only with two-sided lighting on.
    rs.two_sided = ls.enabled && ls.two_side;
  }
  // An active occlusion query makes the fragment stage count (GL 2.1 §4.1.7, query.cpp).
  if (dirty & kDirtyRenderMode) rs.count_samples = ctx->queries.active != 0;
  // Points, lines, polygon stipple and offset (raster_modes.cpp); the offset's depth step
  // depends on the framebuffer's depth bits.
  if (dirty & (kDirtyRasterMode | kDirtyFramebuffer)) derive_raster_modes(ctx, rs.modes);
  // Texturing and fog: per-vertex and per-fragment setups, live attribute count.
  validate_texpipe(ctx, dirty);
  ctx->dirty = 0;
  ++ctx->raster_serial; // the draw cache (transform.cpp) is stale
}

} // namespace pineda
