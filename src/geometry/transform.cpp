// Vertex transformation (GL 2.1 §2.11, §2.12, §2.14.6): object coordinates to clip
// coordinates through the composite matrix, clip codes, window coordinates for vertices that
// need no clipping, and the clamped primary colour.
#include "geometry/clip.h"
#include "geometry/geometry.h"
#include "raster/raster.h"

namespace pineda {

void draw_vertices(Context* ctx, GLenum mode, const InputVertex* in, size_t n,
                   const uint32_t* indices, size_t count) {
  if (ctx->fb.color == nullptr || n == 0) return;
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
  for (size_t i = 0; i < n; ++i) {
    const InputVertex& v = in[i];
    PVertex& p = out[i];
    const float x = v.pos[0], y = v.pos[1], z = v.pos[2], w = v.pos[3];
    for (int r = 0; r < 4; ++r)
      p.clip[r] = m[r] * x + m[4 + r] * y + m[8 + r] * z + m[12 + r] * w;
    p.clipmask = clip_code(cs, p.clip);
    if (p.clipmask == 0) to_window(p, vp);
    // GL 2.1 §2.14.6: with lighting off the primary colour is the current colour, clamped.
    for (int c = 0; c < 4; ++c) {
      const float col = v.color[c];
      p.attr[kAttrColor + c] = col > 0.0f ? (col < 1.0f ? col : 1.0f) : 0.0f;
    }
    p.edgeflag = v.edge;
  }

  Framebuffer& fb = ctx->fb;
  DrawCall dc;
  dc.state = &rs;
  dc.fb = &fb;
  draw_primitives(dc, mode, out.data(), indices, count);
}

} // namespace pineda
