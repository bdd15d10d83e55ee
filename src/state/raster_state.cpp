// The back end's RasterState (core/raster_state.h) derived from the attribute groups: the one
// place that writes it, for the parts whose groups changed since the last draw.
#include <algorithm>

#include <glm/matrix.hpp>

#include "state/context.h"
#include "state/program_draw.h"
#include "state/validate.h"

namespace pineda {

namespace {

// Points, lines, polygon stipple and offset (GL 2.1 §3.3-§3.5).
void derive_raster_modes(const Context& ctx, RasterModes& m) {
  const PointGroup& point = ctx.point;
  const LineGroup& line = ctx.line;
  const PolygonGroup& polygon = ctx.polygon;
  m.line_width = std::clamp(line.width, 1.0f, kMaxLineWidth);
  m.line_smooth = line.smooth;
  m.line_stipple = line.stipple;
  m.line_stipple_factor = line.stipple_repeat;
  m.line_stipple_pattern = line.stipple_pattern;
  m.point_smooth = point.smooth;
  m.point_attenuated =
      point.attenuation[0] != 1.0f || point.attenuation[1] != 0.0f || point.attenuation[2] != 0.0f;
  // GL 2.1 §3.3 eq 3.1: the derived size is clamped to POINT_SIZE_MIN / MAX, also without
  // attenuation (llvmpipe does the same); with attenuation the geometry stage derives and clamps
  // it per vertex from the unclamped size.
  m.point_size = point.size;
  if (!m.point_attenuated)
    m.point_size =
        std::min(std::max(std::min(point.size, point.size_max), point.size_min), kMaxPointSize);
  m.point_size_min = point.size_min;
  m.point_size_max = std::min(point.size_max, kMaxPointSize);
  m.point_fade_threshold = point.fade_threshold;
  std::copy(point.attenuation, point.attenuation + 3, m.point_attenuation);
  m.point_sprite = point.sprite;
  m.sprite_lower_left = point.sprite_origin == GL_LOWER_LEFT;
  m.sprite_coord_replace = 0;
  for (int u = 0; u < kMaxTexUnits; ++u)
    if (point.coord_replace[u]) m.sprite_coord_replace |= static_cast<uint8_t>(1u << u);
  // The stipple pattern all ones stipples nothing: skip the per-block AND.
  const uint32_t* rows = ctx.polygon_stipple.rows;
  bool all_ones = true;
  for (int r = 0; r < 32; ++r)
    all_ones = all_ones && rows[r] == 0xffffffffu;
  m.polygon_stipple = polygon.stipple && !all_ones;
  std::copy(rows, rows + 32, m.polygon_stipple_rows);
  m.offset_point = polygon.offset_point;
  m.offset_line = polygon.offset_line;
  m.offset_fill = polygon.offset_fill;
  m.offset_factor = polygon.offset_factor;
  m.offset_units = polygon.offset_units;
  const Framebuffer& fb = ctx.fb;
  const int bits = fb.depth != nullptr ? fb.depth_bits : 24;
  m.depth_mrd = 1.0 / (bits >= 32 ? 4294967295.0 : static_cast<double>((uint64_t{1} << bits) - 1));
}

} // namespace

void derive_raster_state(Context& ctx, uint32_t dirty) {
  RasterState& rs = ctx.raster;
  if (dirty & kDirtyViewport) {
    const ViewportGroup& vp = ctx.viewport;
    rs.viewport.x = static_cast<float>(vp.x);
    rs.viewport.y = static_cast<float>(vp.y);
    rs.viewport.w = static_cast<float>(vp.w);
    rs.viewport.h = static_cast<float>(vp.h);
    rs.viewport.near = static_cast<float>(vp.near);
    rs.viewport.far = static_cast<float>(vp.far);
  }
  const ProgramDerived& program = *ctx.program_draw;
  if (dirty & (kDirtyClipPlanes | kDirtyTransform | kDirtyProgram)) {
    // GL 2.1 §2.12: a point is inside a user plane when dot(plane_eye, eye) >= 0. With
    // clip = P * eye that equals dot(plane_eye * P^-1, clip), so the test moves to clip space
    // and eye coordinates are never computed. A vertex shader gives the eye coordinates
    // itself, gl_ClipVertex (§2.20.3): the planes stay in eye space and the vertex stage
    // hands each vertex's distances to the clipper in the last attribute floats, unless the
    // varyings take them (then, as without a shader, the test is on the clip coordinates).
    rs.user_clip_mask = 0;
    rs.user_dist = program.has_vertex && program.attr_count <= kAttrClipDist ? kAttrClipDist : -1;
    const glm::dmat4 inv_p =
        rs.user_dist >= 0 ? glm::dmat4(1.0) : glm::inverse(glm::dmat4(ctx.projection.top()));
    for (int i = 0; i < kMaxClipPlanes; ++i) {
      if (!ctx.transform.clip_enabled[i]) continue;
      const double* e = ctx.transform.clip_plane[i];
      const glm::dvec4 c = glm::dvec4(e[0], e[1], e[2], e[3]) * inv_p;
      for (int k = 0; k < 4; ++k)
        rs.user_planes[i][k] = static_cast<float>(c[k]);
      rs.user_clip_mask |= 1u << i;
    }
  }
  if (dirty & kDirtyPolygon) {
    const PolygonGroup& p = ctx.polygon;
    rs.cull_enabled = p.cull_enabled;
    rs.cull_face = p.cull_face;
    rs.front_face = p.front_face;
    rs.polygon_mode[0] = p.mode[0];
    rs.polygon_mode[1] = p.mode[1];
    rs.flat = ctx.lighting.shade_model == GL_FLAT;
  }
  if (dirty & (kDirtyFragment | kDirtyFramebuffer)) {
    const ColorBufferGroup& cb = ctx.color_buffer;
    // GL 2.1 §4.1.6: without a depth buffer the depth test always passes and nothing is
    // written, which is the same as the test being off.
    rs.depth_test = ctx.depth.test && ctx.fb.depth != nullptr;
    rs.depth_func = ctx.depth.func;
    rs.depth_write = ctx.depth.mask;
    // GL 2.1 §4.2.1: with the draw buffer NONE no colour is written (the derived
    // framebuffer then has no colour buffer, framebuffer_object.cpp).
    const bool draws_color = ctx.fb.color != nullptr;
    for (int i = 0; i < 4; ++i)
      rs.color_write[i] = cb.color_mask[i] && draws_color;
    rs.blend = cb.blend;
    rs.blend_state = cb.blend_state;
    rs.scissor_test = ctx.scissor.test;
    for (int i = 0; i < 4; ++i)
      rs.scissor[i] = ctx.scissor.box[i];
    rs.alpha_test = cb.alpha_test;
    rs.alpha_func = cb.alpha_func;
    rs.alpha_ref = cb.alpha_ref;
    // GL 2.1 §4.1.5: without a stencil buffer the test always passes and writes nothing.
    rs.stencil_test = ctx.stencil.test && ctx.fb.stencil != nullptr;
    rs.stencil = ctx.stencil.front;
    rs.stencil_back = ctx.stencil.back;
    rs.logic_op = cb.color_logic_op;
    rs.logic_op_mode = cb.logic_op;
  }
  // §2.14.1: back colours are computed and selected only with two-sided lighting on; with a
  // vertex shader, under VERTEX_PROGRAM_TWO_SIDE (§2.20.3).
  if (dirty & (kDirtyLighting | kDirtyTransform | kDirtyProgram))
    rs.two_sided =
        program.has_vertex ? ctx.program.two_side : ctx.lighting.enabled && ctx.lighting.two_side;
  // An active occlusion query makes the fragment stage count (GL 2.1 §4.1.7, query.cpp).
  if (dirty & kDirtyRenderMode) rs.count_samples = ctx.queries.active != 0;
  // The offset's depth step depends on the framebuffer's depth bits.
  if (dirty & (kDirtyRasterMode | kDirtyFramebuffer | kDirtyProgram)) {
    derive_raster_modes(ctx, rs.modes);
    // §3.3: with a vertex shader the size is gl_PointSize per vertex under
    // VERTEX_PROGRAM_POINT_SIZE (the vertex stage clamps it), else POINT_SIZE without
    // distance attenuation.
    if (program.has_vertex) {
      RasterModes& m = rs.modes;
      m.point_attenuated = ctx.program.point_size;
      if (!m.point_attenuated)
        m.point_size =
            std::min(std::max(std::min(ctx.point.size, ctx.point.size_max), ctx.point.size_min),
                     kMaxPointSize);
    }
  }
  // Texturing and fog (the texture area's setups, validate_texpipe.cpp): per-fragment shading
  // and the live attribute count.
  rs.shade = ctx.texpipe.shading ? ctx.texpipe.shade.get() : nullptr;
  rs.attr_count = ctx.texpipe.attr_count;
  // A fragment shader replaces texturing, colour sum and fog (GL 2.1 §3.11).
  if (program.has_fragment) {
    rs.shade = program.shade.get();
    rs.attr_count = program.attr_count;
  }
}

} // namespace pineda
