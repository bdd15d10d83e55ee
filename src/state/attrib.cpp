// glPushAttrib / glPopAttrib (GL 2.1 §6.1.14 "Saving and Restoring State"): the server
// attribute stack. Each group is the state whose "attribute" column in the GL 2.1 state tables
// names it, restricted to the state Pineda has. Groups accepted but saving nothing yet, and
// what each must grow to cover as the state is implemented (§6.1.14, Table 6.2). LINE_BIT,
// POINT_BIT, POLYGON_STIPPLE_BIT and the stipple, smooth and offset state of POLYGON_BIT are
// saved and restored by raster_modes.cpp (save_raster_modes / restore_raster_modes); FOG_BIT and
// the environment, coordinate generation, enables and active unit of TEXTURE_BIT by texenv.cpp;
// EVAL_BIT and the evaluator enables of ENABLE_BIT by eval.cpp.
//   POINT_BIT also: sprite enables and coordinate origin once point sprites exist.
//   TEXTURE_BIT: bindings and texture object parameters (Tables 6.16-6.18); the environment,
//     coordinate generation, enables and active unit are saved by texenv.cpp.
// The current index (CURRENT_BIT), index clear value and write mask (COLOR_BUFFER_BIT) and
// MULTISAMPLE_BIT with the multisample enables of ENABLE_BIT are saved by multisample.cpp
// (misc_save_attrib / misc_restore_attrib); EVAL_BIT and the evaluator enables by eval.cpp.
#include "core/api_util.h"
#include "dispatch.h"
#include "state/attrib.h"
#include "state/draw_read_buffer.h"
#include "state/raster_modes_hooks.h"

#include <algorithm>
#include <array>

namespace pineda {

// Texture units and fog (src/state/texenv.cpp): the parts of CURRENT_BIT, ENABLE_BIT,
// TEXTURE_BIT and FOG_BIT that live in Context::texpipe; restore returns the dirty bits.
void texpipe_save_attrib(const Context* c, GLbitfield mask, TexPipeAttrib& f);
uint32_t texpipe_restore_attrib(Context* c, GLbitfield mask, const TexPipeAttrib& f);
// Evaluators (src/state/eval.cpp): EVAL_BIT and the evaluator enables of ENABLE_BIT.
void eval_save_attrib(const Context* c, GLbitfield mask, EvalAttrib& f);
void eval_restore_attrib(Context* c, GLbitfield mask, const EvalAttrib& f);

namespace {

constexpr size_t kEnableCount = kMaxClipPlanes + kMaxLights + 14;
static_assert(kEnableCount <= sizeof(AttribFrame::Enables::flag));

// Every server-side enable flag, which ENABLE_BIT saves (GL 2.1 §6.1.14: "enable" in the
// attribute column of any table).
std::array<bool*, kEnableCount> enable_flags(Context* ctx) {
  std::array<bool*, kEnableCount> f{};
  size_t n = 0;
  for (int i = 0; i < kMaxClipPlanes; ++i)
    f[n++] = &ctx->clip_enabled[i];
  for (int i = 0; i < kMaxLights; ++i)
    f[n++] = &ctx->lighting.light[i].enabled;
  for (bool* b : {&ctx->cull_enabled, &ctx->lighting.enabled, &ctx->lighting.color_material,
                  &ctx->lighting.color_sum, &ctx->depth_test, &ctx->blend, &ctx->scissor_test,
                  &ctx->alpha_test, &ctx->stencil_test, &ctx->color_logic_op, &ctx->index_logic_op,
                  &ctx->dither, &ctx->normalize, &ctx->rescale_normal})
    f[n++] = b;
  return f;
}

template <typename T, size_t N> void copy_array(T (&dst)[N], const T (&src)[N]) {
  std::copy(src, src + N, dst);
}

void save(const Context* c, AttribFrame& f) {
  const GLbitfield m = f.mask;
  if (m & GL_CURRENT_BIT) {
    copy_array(f.current.color, c->cur_color);
    copy_array(f.current.color2, c->cur_color2);
    copy_array(f.current.normal, c->cur_normal);
    for (int u = 0; u < kMaxTexUnits; ++u)
      copy_array(f.current.tex[u], c->cur_tex[u]);
    f.current.edge = c->cur_edge;
    f.current.raster = c->raster_pos;
  }
  if (m & GL_ENABLE_BIT) {
    const auto flags = enable_flags(const_cast<Context*>(c));
    for (size_t i = 0; i < flags.size(); ++i)
      f.enables.flag[i] = *flags[i];
  }
  if (m & GL_POLYGON_BIT) {
    f.polygon.cull_enabled = c->cull_enabled;
    f.polygon.cull_face = c->cull_face;
    f.polygon.front_face = c->front_face;
    copy_array(f.polygon.polygon_mode, c->polygon_mode);
  }
  if (m & GL_LIGHTING_BIT) {
    const LightingState& ls = c->lighting;
    AttribFrame::Lighting& l = f.lighting;
    l.enabled = ls.enabled;
    l.local_viewer = ls.local_viewer;
    l.two_side = ls.two_side;
    l.color_material = ls.color_material;
    copy_array(l.light, ls.light);
    copy_array(l.material, ls.material);
    copy_array(l.model_ambient, ls.model_ambient);
    l.color_control = ls.color_control;
    l.color_material_face = ls.color_material_face;
    l.color_material_mode = ls.color_material_mode;
    l.shade_model = c->shade_model;
  }
  if (m & GL_DEPTH_BUFFER_BIT)
    f.depth = {c->depth_test, c->depth_mask, c->depth_func, c->clear_depth};
  if (m & GL_COLOR_BUFFER_BIT) {
    AttribFrame::ColorBuffer& cb = f.color;
    cb.alpha_test = c->alpha_test;
    cb.alpha_func = c->alpha_func;
    cb.alpha_ref = c->alpha_ref;
    cb.blend = c->blend;
    cb.blend_src_rgb = c->blend_src_rgb;
    cb.blend_dst_rgb = c->blend_dst_rgb;
    cb.blend_src_a = c->blend_src_a;
    cb.blend_dst_a = c->blend_dst_a;
    cb.blend_eq_rgb = c->blend_eq_rgb;
    cb.blend_eq_a = c->blend_eq_a;
    copy_array(cb.blend_color, c->blend_color);
    cb.dither = c->dither;
    cb.color_logic_op = c->color_logic_op;
    cb.index_logic_op = c->index_logic_op;
    cb.logic_op = c->logic_op;
    cb.draw_buffer = c->draw_buffer;
    copy_array(cb.color_mask, c->color_mask);
    copy_array(cb.clear_color, c->clear_color);
  }
  if (m & GL_STENCIL_BUFFER_BIT) {
    f.stencil = {c->stencil_test,       c->stencil_func,       c->stencil_fail,
                 c->stencil_depth_fail, c->stencil_depth_pass, c->stencil_ref,
                 c->clear_stencil,      c->stencil_value_mask, c->stencil_writemask};
  }
  if (m & GL_SCISSOR_BIT) {
    f.scissor.test = c->scissor_test;
    copy_array(f.scissor.box, c->scissor_box);
  }
  if (m & GL_VIEWPORT_BIT)
    f.viewport = {c->vp_x, c->vp_y, c->vp_w, c->vp_h, c->depth_near, c->depth_far};
  if (m & GL_TRANSFORM_BIT) {
    f.transform.matrix_mode = c->matrix_mode;
    for (int i = 0; i < kMaxClipPlanes; ++i)
      copy_array(f.transform.clip_plane[i], c->clip_plane[i]);
    copy_array(f.transform.clip_enabled, c->clip_enabled);
    f.transform.normalize = c->normalize;
    f.transform.rescale_normal = c->rescale_normal;
  }
  if (m & GL_HINT_BIT) {
    f.hints = {c->hint_perspective,        c->hint_point_smooth, c->hint_line_smooth,
               c->hint_polygon_smooth,     c->hint_fog,          c->hint_generate_mipmap,
               c->hint_texture_compression};
  }
  if (m & GL_FOG_BIT) f.color_sum = c->lighting.color_sum;
  if (m & GL_PIXEL_MODE_BIT) {
    f.read_buffer = c->read_buffer;
    const PixelTransfer& x = c->pixel_transfer;
    AttribFrame::PixelMode& p = f.pixel;
    p.map_color = x.map_color;
    p.map_stencil = x.map_stencil;
    p.index_shift = x.index_shift;
    p.index_offset = x.index_offset;
    copy_array(p.scale, x.scale);
    copy_array(p.bias, x.bias);
    p.depth_scale = x.depth_scale;
    p.depth_bias = x.depth_bias;
    p.zoom_x = x.zoom_x;
    p.zoom_y = x.zoom_y;
  }
  if (m & GL_TEXTURE_BIT) save_texture_attrib(c, f.texture_objects);
  texpipe_save_attrib(c, m, f.texpipe);
  save_raster_modes(c, f.raster_modes);
  if (m & GL_ACCUM_BUFFER_BIT) copy_array(f.accum_clear, c->accum.clear);
  if (m & GL_LIST_BIT) f.list_base = c->dlist.base;
  misc_save_attrib(c, m, f.misc); // colour index, multisample (multisample.cpp)
  eval_save_attrib(c, m, f.eval);
}

// Restore the groups of `f` and return the derived state they invalidate.
uint32_t restore(Context* c, const AttribFrame& f) {
  const GLbitfield m = f.mask;
  uint32_t dirty = 0;
  if (m & GL_CURRENT_BIT) {
    copy_array(c->cur_color, f.current.color);
    copy_array(c->cur_color2, f.current.color2);
    copy_array(c->cur_normal, f.current.normal);
    for (int u = 0; u < kMaxTexUnits; ++u)
      copy_array(c->cur_tex[u], f.current.tex[u]);
    c->cur_edge = f.current.edge;
    c->raster_pos = f.current.raster;
  }
  if (m & GL_ENABLE_BIT) {
    const auto flags = enable_flags(c);
    for (size_t i = 0; i < flags.size(); ++i)
      *flags[i] = f.enables.flag[i];
    dirty |= kDirtyClipPlanes | kDirtyLighting | kDirtyPolygon | kDirtyFragment;
  }
  if (m & GL_POLYGON_BIT) {
    c->cull_enabled = f.polygon.cull_enabled;
    c->cull_face = f.polygon.cull_face;
    c->front_face = f.polygon.front_face;
    copy_array(c->polygon_mode, f.polygon.polygon_mode);
    dirty |= kDirtyPolygon;
  }
  if (m & GL_LIGHTING_BIT) {
    LightingState& ls = c->lighting;
    const AttribFrame::Lighting& l = f.lighting;
    ls.enabled = l.enabled;
    ls.local_viewer = l.local_viewer;
    ls.two_side = l.two_side;
    ls.color_material = l.color_material;
    copy_array(ls.light, l.light);
    copy_array(ls.material, l.material);
    copy_array(ls.model_ambient, l.model_ambient);
    ls.color_control = l.color_control;
    ls.color_material_face = l.color_material_face;
    ls.color_material_mode = l.color_material_mode;
    c->shade_model = l.shade_model;
    dirty |= kDirtyLighting | kDirtyPolygon;
  }
  if (m & GL_DEPTH_BUFFER_BIT) {
    c->depth_test = f.depth.test;
    c->depth_mask = f.depth.mask;
    c->depth_func = f.depth.func;
    c->clear_depth = f.depth.clear;
    dirty |= kDirtyFragment;
  }
  if (m & GL_COLOR_BUFFER_BIT) {
    const AttribFrame::ColorBuffer& cb = f.color;
    c->alpha_test = cb.alpha_test;
    c->alpha_func = cb.alpha_func;
    c->alpha_ref = cb.alpha_ref;
    c->blend = cb.blend;
    c->blend_src_rgb = cb.blend_src_rgb;
    c->blend_dst_rgb = cb.blend_dst_rgb;
    c->blend_src_a = cb.blend_src_a;
    c->blend_dst_a = cb.blend_dst_a;
    c->blend_eq_rgb = cb.blend_eq_rgb;
    c->blend_eq_a = cb.blend_eq_a;
    copy_array(c->blend_color, cb.blend_color);
    c->dither = cb.dither;
    c->color_logic_op = cb.color_logic_op;
    c->index_logic_op = cb.index_logic_op;
    c->logic_op = cb.logic_op;
    c->draw_buffer = cb.draw_buffer;
    select_color_buffers(c); // src/state/draw_read_buffer.cpp
    copy_array(c->color_mask, cb.color_mask);
    copy_array(c->clear_color, cb.clear_color);
    dirty |= kDirtyFragment;
  }
  if (m & GL_STENCIL_BUFFER_BIT) {
    const AttribFrame::Stencil& s = f.stencil;
    c->stencil_test = s.test;
    c->stencil_func = s.func;
    c->stencil_fail = s.fail;
    c->stencil_depth_fail = s.depth_fail;
    c->stencil_depth_pass = s.depth_pass;
    c->stencil_ref = s.ref;
    c->clear_stencil = s.clear;
    c->stencil_value_mask = s.value_mask;
    c->stencil_writemask = s.writemask;
    dirty |= kDirtyFragment;
  }
  if (m & GL_SCISSOR_BIT) {
    c->scissor_test = f.scissor.test;
    copy_array(c->scissor_box, f.scissor.box);
    dirty |= kDirtyFragment;
  }
  if (m & GL_VIEWPORT_BIT) {
    c->vp_x = f.viewport.x;
    c->vp_y = f.viewport.y;
    c->vp_w = f.viewport.w;
    c->vp_h = f.viewport.h;
    c->depth_near = f.viewport.near;
    c->depth_far = f.viewport.far;
    dirty |= kDirtyViewport;
  }
  if (m & GL_TRANSFORM_BIT) {
    c->matrix_mode = f.transform.matrix_mode;
    for (int i = 0; i < kMaxClipPlanes; ++i)
      copy_array(c->clip_plane[i], f.transform.clip_plane[i]);
    copy_array(c->clip_enabled, f.transform.clip_enabled);
    c->normalize = f.transform.normalize;
    c->rescale_normal = f.transform.rescale_normal;
    dirty |= kDirtyClipPlanes | kDirtyLighting;
  }
  if (m & GL_HINT_BIT) {
    c->hint_perspective = f.hints.perspective;
    c->hint_point_smooth = f.hints.point_smooth;
    c->hint_line_smooth = f.hints.line_smooth;
    c->hint_polygon_smooth = f.hints.polygon_smooth;
    c->hint_fog = f.hints.fog;
    c->hint_generate_mipmap = f.hints.generate_mipmap;
    c->hint_texture_compression = f.hints.texture_compression;
    dirty |= kDirtyFog; // the fog hint picks per-vertex or per-fragment fog
  }
  if (m & GL_FOG_BIT) {
    c->lighting.color_sum = f.color_sum;
    dirty |= kDirtyLighting;
  }
  if (m & GL_PIXEL_MODE_BIT) {
    c->read_buffer = f.read_buffer;
    select_color_buffers(c);
    PixelTransfer& x = c->pixel_transfer;
    const AttribFrame::PixelMode& p = f.pixel;
    x.map_color = p.map_color;
    x.map_stencil = p.map_stencil;
    x.index_shift = p.index_shift;
    x.index_offset = p.index_offset;
    copy_array(x.scale, p.scale);
    copy_array(x.bias, p.bias);
    x.depth_scale = p.depth_scale;
    x.depth_bias = p.depth_bias;
    x.zoom_x = p.zoom_x;
    x.zoom_y = p.zoom_y;
    dirty |= kDirtyPixel;
  }
  if (m & GL_TEXTURE_BIT) restore_texture_attrib(c, f.texture_objects); // marks kDirtyTexture
  dirty |= texpipe_restore_attrib(c, m, f.texpipe);
  dirty |= restore_raster_modes(c, f.raster_modes, m);
  if (m & GL_ACCUM_BUFFER_BIT) copy_array(c->accum.clear, f.accum_clear);
  if (m & GL_LIST_BIT) c->dlist.base = f.list_base;
  misc_restore_attrib(c, m, f.misc); // no derived state: no effect on rendering
  eval_restore_attrib(c, m, f.eval); // no derived state depends on it
  // GL 2.1 §2.14.3: while COLOR_MATERIAL is enabled the tracked material properties follow
  // the current colour, whichever of the two was restored.
  if ((m & (GL_CURRENT_BIT | GL_LIGHTING_BIT | GL_ENABLE_BIT)) && c->lighting.color_material) {
    update_color_material(c);
    dirty |= kDirtyLighting;
  }
  return dirty;
}

} // namespace

void copy_attrib_groups(const Context* src, Context* dst, GLbitfield mask) {
  AttribFrame f;
  f.mask = mask;
  save(src, f);
  // GLX 1.4 §3.3.7: "texture objects cannot be copied"; across share groups a name means
  // another object, so dst's own bindings and parameters are what it keeps.
  if ((mask & GL_TEXTURE_BIT) && src->shared != dst->shared)
    save_texture_attrib(dst, f.texture_objects);
  mark_dirty(dst, restore(dst, f));
}

namespace exec {

// §6.1.14: PushAttrib saves the groups in `mask` (bits of no group are ignored); a full stack
// is STACK_OVERFLOW and the command has no other effect.
void GLAPIENTRY PushAttrib(GLbitfield mask) {
  PINEDA_CTX_OUTSIDE("glPushAttrib");
  if (ctx->attrib_stack.size() >= kAttribStackDepth)
    return record_error(ctx, GL_STACK_OVERFLOW, "glPushAttrib");
  AttribFrame f;
  f.mask = mask;
  save(ctx, f);
  ctx->attrib_stack.push_back(f);
}

// §6.1.14: PopAttrib restores the groups the matching PushAttrib saved; an empty stack is
// STACK_UNDERFLOW and the command has no other effect.
void GLAPIENTRY PopAttrib() {
  PINEDA_CTX_OUTSIDE("glPopAttrib");
  if (ctx->attrib_stack.empty()) return record_error(ctx, GL_STACK_UNDERFLOW, "glPopAttrib");
  mark_dirty(ctx, restore(ctx, ctx->attrib_stack.back()));
  ctx->attrib_stack.pop_back();
}

} // namespace exec
} // namespace pineda
