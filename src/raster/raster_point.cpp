// Point rasterization, size 1, not antialiased (GL 2.1 §3.3.1): the window x and y are
// truncated to integers and that one fragment takes the vertex's depth and colour.
#include <cmath>

#include "fragment/fragment_ops.h"
#include "raster/raster.h"
#include "raster/setup.h"
#include "raster/setup_shade.h"

namespace pineda {

namespace {

void point(const FragCtx& ctx, const PVertex& p) {
  if (ctx.noop) return;
  // "Truncating" for the (possibly negative, guard band) window coordinates means floor:
  // the fragment is the pixel whose square [x, x+1) x [y, y+1) contains the point.
  const float fx = std::floor(p.win[0]), fy = std::floor(p.win[1]);
  if (!(fx >= static_cast<float>(ctx.clip_x0) && fx <= static_cast<float>(ctx.clip_x1) &&
        fy >= static_cast<float>(ctx.clip_y0) && fy <= static_cast<float>(ctx.clip_y1)))
    return;
  const int x = static_cast<int>(fx), y = static_cast<int>(fy);
  FragInputs in;
  in.ox = x;
  in.oy = y;
  in.z.v0 = p.win[2] * ctx.depth_max;
  const_color(p, kAttrColor, in.const_color);
  const int bx = x & ~(kBlockSize - 1), by = y & ~(kBlockSize - 1);
  const uint64_t bit = uint64_t{1} << (8 * (y - by) + (x - bx));
  ShadeInputs si; // texturing and fog (fragment/shade.h)
  ShadePath shade = ShadePath::Const;
  if (ctx.shade != nullptr) {
    setup_shade_point(*ctx.shade, p, si);
    in.shade = &si;
    shade = ShadePath::PerFragment;
  }
  ctx.fn[static_cast<int>(shade)](ctx, in, bx, by, bit);
}

} // namespace

void raster_point(const DrawCall& dc, const PVertex& p) {
  if (dc.frag != nullptr) return point(*dc.frag, p);
  FragCtx ctx;
  prepare_fragments(*dc.state, *dc.fb, ctx);
  point(ctx, p);
}

} // namespace pineda
