// Vertex transformation (GL 2.1 §2.11, §2.12, §2.14.6): object coordinates to clip
// coordinates through the composite matrix, clip codes, window coordinates for vertices that
// need no clipping, and the vertex colours: lit (§2.14.1, light_eval.cpp) or the clamped
// current colours, with the colour sum (§3.9) folded in unless texturing or fog is on; texture
// and fog coordinates (texcoord.cpp); derived point sizes (GL 1.4 point parameters).
#include <cmath>

#include "geometry/clip.h"
#include "geometry/geometry.h"
#include "geometry/light_eval.h"
#include "geometry/texcoord.h"
#include "raster/raster.h"
#include "state/draw_read_buffer.h"

namespace pineda {

namespace {

// GL 2.1 §3.9 colour sum, folded into the primary colour at the vertex: the fragment's colour
// is clamp(c_pri + c_sec) with both colours interpolated, and interpolation (clipping, eq.
// 3.9) is linear, so interpolating the unclamped per-vertex sum and clamping per fragment (as
// the fragment stage does) gives the same value. With texturing (§3.8.13 precedes the colour
// sum) or fog on, the fragment stage adds it instead.
inline void add_secondary(float* attr, bool back) {
  for (int c = 0; c < 3; ++c) attr[kAttrColor + c] += attr[kAttrColor2 + c];
  if (back)
    for (int c = 0; c < 3; ++c) attr[kAttrBackColor + c] += attr[kAttrBackColor2 + c];
}

} // namespace

namespace {

void draw_vertices_once(Context* ctx, GLenum mode, const InputVertex* in, size_t n,
                        const uint32_t* indices, size_t count) {
  validate_state(ctx);
  const RasterState& rs = ctx->raster;
  const Viewport& vp = rs.viewport;
  if (vp.w <= 0.0f || vp.h <= 0.0f) return;

  // The clip codes come from the clipper's own plane setup (guard band, user planes), so a
  // vertex's code and the clipper's distances always agree.
  ClipSetup cs;
  init_clip_setup(cs, rs);

  std::vector<PVertex>& out = ctx->pvert_scratch;
  if (out.size() < n) out.resize(n);
  const float* m = &ctx->mvp[0][0]; // column-major

  // GL 2.1 §2.14.1: lighting replaces the current colour. Material calls between Begin and
  // End (§2.14.2) change the material from a given vertex of the primitive on.
  LightingState& lighting = ctx->lighting;
  const bool lit = lighting.enabled;
  const MaterialChange* changes = lighting.imm_changes.data();
  const size_t change_count = lit ? lighting.imm_changes.size() : 0;
  size_t next_change = 0;
  const Material* material = change_count != 0 ? lighting.begin_material : lighting.material;
  // §3.9: with lighting on the colour sum always applies and the secondary colour is zero
  // unless the specular term is separate; otherwise COLOR_SUM adds the current secondary
  // colour.
  // Feedback returns the primary colour alone (GL 2.1 §5.3), so nothing is folded in there.
  const bool color_sum = (lit ? lighting.setup.separate_specular : lighting.color_sum) &&
                         render_mode_is_render(ctx);
  // With texturing or fog on, the fragment stage adds the secondary colour after the texture
  // environments (fragment/shade.cpp); otherwise it is folded in here.
  const bool fold_sum = color_sum && rs.shade == nullptr;
  const TexVertexSetup& tvs = ctx->texpipe.vertex;
  const bool tex_live = rs.shade != nullptr && (tvs.units != 0 || tvs.fog);
  const bool two_sided = rs.two_sided;
  // GL 1.4 point parameters (GL 2.1 §3.3 eq 3.1): with distance attenuation every vertex gets
  // its derived size. Mesa takes the distance as |z| in eye coordinates rather than the
  // Euclidean distance the spec names; Pineda follows llvmpipe.
  const RasterModes& modes = rs.modes;
  const bool attenuate = modes.point_attenuated;
  const glm::mat4& mv = ctx->modelview.top();

  for (size_t i = 0; i < n; ++i) {
    const InputVertex& v = in[i];
    PVertex& p = out[i];
    const float x = v.pos[0], y = v.pos[1], z = v.pos[2], w = v.pos[3];
    for (int r = 0; r < 4; ++r)
      p.clip[r] = m[r] * x + m[4 + r] * y + m[8 + r] * z + m[12 + r] * w;
    p.clipmask = clip_code(cs, p.clip);
    if (p.clipmask == 0) to_window(p, vp);
    if (lit) {
      while (next_change < change_count && changes[next_change].vertex <= i)
        material = changes[next_change++].material;
      light_vertex(lighting.setup, material, v.pos, v.normal, v.color, p.attr);
      if (fold_sum) add_secondary(p.attr, two_sided);
    } else {
      // GL 2.1 §2.14.6: with lighting off the primary colour is the current colour, clamped.
      for (int c = 0; c < 4; ++c) {
        const float col = v.color[c];
        p.attr[kAttrColor + c] = col > 0.0f ? (col < 1.0f ? col : 1.0f) : 0.0f;
      }
      if (color_sum) {
        for (int c = 0; c < 3; ++c) {
          const float col = v.color2[c];
          p.attr[kAttrColor2 + c] = col > 0.0f ? (col < 1.0f ? col : 1.0f) : 0.0f;
        }
        if (fold_sum) add_secondary(p.attr, false);
      }
    }
    if (tex_live) tex_vertex(tvs, v.pos, v.normal, v.tex, v.fog, p.attr);
    p.edgeflag = v.edge;
    p.point_size = 1.0f;
    if (attenuate) {
      const float ez = mv[0][2] * x + mv[1][2] * y + mv[2][2] * z + mv[3][2] * w;
      const float d = ez < 0.0f ? -ez : ez;
      const float* a = modes.point_attenuation;
      const float size = modes.point_size / std::sqrt(a[0] + a[1] * d + a[2] * d * d);
      // A NaN (attenuation <= 0) becomes the minimum.
      p.point_size = size >= modes.point_size_min
                         ? (size < modes.point_size_max ? size : modes.point_size_max)
                         : modes.point_size_min;
    }
  }

  // GL 2.1 §5.2, §5.3: in SELECT and FEEDBACK mode the primitives go to selection or
  // feedback instead of the rasterizer.
  if (!render_mode_is_render(ctx)) {
    select_feedback_draw(ctx, in, out.data(), n, mode, indices, count);
    return;
  }
  Framebuffer& fb = ctx->fb;
  DrawCall dc;
  dc.state = &rs;
  dc.fb = &fb;
  if (rs.count_samples) dc.samples_passed = &ctx->queries.samples_passed;
  dc.workers = &ctx->workers;
  draw_primitives(dc, mode, out.data(), indices, count);
}

} // namespace

// GL 2.1 §4.2.1: with FRONT_AND_BACK the primitives reach both colour buffers.
void draw_vertices(Context* ctx, GLenum mode, const InputVertex* in, size_t n,
                   const uint32_t* indices, size_t count) {
  if (ctx->fb.color == nullptr || n == 0) return;
  for_each_draw_buffer(ctx, [&] { draw_vertices_once(ctx, mode, in, n, indices, count); });
}

} // namespace pineda
