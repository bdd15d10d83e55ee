// Small helpers shared by the point and line rasterizers for their wide and smooth forms:
// a constant-colour rectangle handed to the block loop block by block, and single fragments
// with their own depth and colour (smooth points and lines, whose coverage scales the alpha,
// GL 2.1 §3.3.2 / §3.4.3). Single fragments are slow, but only the smooth paths use them.
#pragma once

#include <algorithm>
#include <cstdint>

#include "fragment/fragment_ops.h"
#include "raster/workers.h"

namespace pineda {

// One fragment at pixel (x, y) inside the clip rectangle and the worker's bands, with window z
// already scaled to depth-buffer units and an 8-bit RGBA colour.
inline void emit_fragment(const FragCtx& ctx, const Bands& bands, int x, int y, double z,
                          const uint8_t rgba[4]) {
  if (x < ctx.clip_x0 || x > ctx.clip_x1 || y < ctx.clip_y0 || y > ctx.clip_y1) return;
  if (!bands.owns(y)) return;
  FragInputs in;
  in.ox = x;
  in.oy = y;
  in.z.v0 = z;
  for (int k = 0; k < 4; ++k)
    in.const_color[k] = rgba[k];
  const int bx = x & ~(kBlockSize - 1), by = y & ~(kBlockSize - 1);
  ctx.fn[static_cast<int>(ShadePath::Const)](ctx, in, bx, by,
                                             uint64_t{1} << (8 * (y - by) + (x - bx)));
}

// The pixels [x0, x1] x [y0, y1] (inclusive, clipped here to the clip rectangle and the
// worker's bands) with the inputs `in`.
inline void emit_rect(const FragCtx& ctx, const Bands& bands, const FragInputs& in, BlockFn fn,
                      int x0, int y0, int x1, int y1) {
  x0 = std::max(x0, ctx.clip_x0);
  y0 = std::max(y0, ctx.clip_y0);
  x1 = std::min(x1, ctx.clip_x1);
  y1 = std::min(y1, ctx.clip_y1);
  if (x0 > x1 || y0 > y1) return;
  for (int by = y0 & ~(kBlockSize - 1); by <= y1; by += kBlockSize) {
    if (!bands.owns(by)) continue;
    for (int bx = x0 & ~(kBlockSize - 1); bx <= x1; bx += kBlockSize)
      fn(ctx, in, bx, by, rect_block_mask(x0, y0, x1, y1, bx, by));
  }
}

} // namespace pineda
