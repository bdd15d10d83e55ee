// Triangle rasterization (GL 2.1 §3.5.1): traversal of the bounding box in 8x8 blocks
// aligned to multiples of 8. A block outside one edge is skipped, a block inside all three is
// handed on whole without per-pixel edge tests, and only blocks on an edge are tested pixel
// by pixel. Coverage masks go to the fragment stage's key-selected block loop.
#include <algorithm>
#include <cstdint>

#include "fragment/fragment_ops.h"
#include "raster/raster.h"
#include "raster/setup.h"

namespace pineda {

namespace {

// Floor and ceiling of a / b for b > 0.
inline int64_t floor_div(int64_t a, int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }
inline int64_t ceil_div(int64_t a, int64_t b) { return -floor_div(-a, b); }

// Per-pixel coverage of one block within the pixel bounds [c0,c1]x[r0,r1] of the block.
inline uint64_t partial_mask(const TriEdges& te, const int64_t e[3], int c0, int c1, int r0,
                             int r1) {
  uint64_t mask = 0;
  for (int r = r0; r <= r1; ++r) {
    int64_t e0 = e[0] + r * te.e[0].sy + c0 * te.e[0].sx;
    int64_t e1 = e[1] + r * te.e[1].sy + c0 * te.e[1].sx;
    int64_t e2 = e[2] + r * te.e[2].sy + c0 * te.e[2].sx;
    for (int c = c0; c <= c1; ++c) {
      const uint64_t inside = static_cast<uint64_t>(~(e0 | e1 | e2)) >> 63;
      mask |= inside << (8 * r + c);
      e0 += te.e[0].sx;
      e1 += te.e[1].sx;
      e2 += te.e[2].sx;
    }
  }
  return mask;
}

// Bounding boxes wider than this get the block range of each block row narrowed to the
// columns the edges allow, so long thin triangles do not visit every block of their box.
constexpr int kNarrowWidth = 32;

void traverse(const TriEdges& te, const FragCtx& ctx, const FragInputs& in, BlockFn fn) {
  constexpr int B = kBlockSize;
  // Offsets from a block's first pixel to its corner pixel where an edge function is largest
  // (reject if even that is negative) and smallest (accept if even that is non-negative).
  int64_t reject_off[3], accept_off[3];
  for (int i = 0; i < 3; ++i) {
    const int64_t sx = te.e[i].sx * (B - 1), sy = te.e[i].sy * (B - 1);
    reject_off[i] = std::max<int64_t>(sx, 0) + std::max<int64_t>(sy, 0);
    accept_off[i] = std::min<int64_t>(sx, 0) + std::min<int64_t>(sy, 0);
  }
  const int bx_first = te.minx & ~(B - 1);
  const int bx_last = te.maxx & ~(B - 1);
  const bool narrow = te.maxx - te.minx >= kNarrowWidth;

  for (int by = te.miny & ~(B - 1); by <= te.maxy; by += B) {
    int64_t lo = bx_first, hi = bx_last;
    int64_t erow[3];
    bool skip = false;
    for (int i = 0; i < 3; ++i) {
      erow[i] = te.e[i].base + by * te.e[i].sy;
      if (!narrow) continue;
      // Blocks starting at column bx survive edge i when erow + bx*sx + reject_off >= 0.
      const int64_t k = erow[i] + reject_off[i], sx = te.e[i].sx;
      if (sx > 0) {
        lo = std::max(lo, (ceil_div(-k, sx) + (B - 1)) & ~int64_t{B - 1});
      } else if (sx < 0) {
        hi = std::min(hi, floor_div(k, -sx) & ~int64_t{B - 1});
      } else if (k < 0) {
        skip = true;
      }
    }
    if (skip || lo > hi) continue;
    const int bx0 = static_cast<int>(lo), bx1 = static_cast<int>(hi);
    const int r0 = std::max(te.miny - by, 0), r1 = std::min(te.maxy - by, B - 1);
    int64_t e[3];
    for (int i = 0; i < 3; ++i) e[i] = erow[i] + bx0 * te.e[i].sx;
    for (int bx = bx0; bx <= bx1; bx += B) {
      const bool out = (e[0] + reject_off[0] < 0) | (e[1] + reject_off[1] < 0) |
                       (e[2] + reject_off[2] < 0);
      if (!out) {
        uint64_t mask;
        if (e[0] + accept_off[0] >= 0 && e[1] + accept_off[1] >= 0 &&
            e[2] + accept_off[2] >= 0) {
          // Every centre of the block is inside; only the bounding box (which is clipped to
          // the clip rectangle) limits it.
          mask = rect_block_mask(te.minx, te.miny, te.maxx, te.maxy, bx, by);
        } else {
          const int c0 = std::max(te.minx - bx, 0), c1 = std::min(te.maxx - bx, B - 1);
          mask = partial_mask(te, e, c0, c1, r0, r1);
        }
        if (mask != 0) fn(ctx, in, bx, by, mask);
      }
      for (int i = 0; i < 3; ++i) e[i] += te.e[i].sx * B;
    }
  }
}

} // namespace

void raster_triangle(const DrawCall& dc, const PVertex& a, const PVertex& b, const PVertex& c,
                     const PVertex& provoking, bool back_facing) {
  FragCtx ctx;
  prepare_fragments(*dc.state, *dc.fb, ctx);
  if (ctx.noop) return;
  const SnappedTri t = snap_triangle(a, b, c);
  TriEdges te;
  if (!setup_edges(t, ctx.clip_x0, ctx.clip_y0, ctx.clip_x1, ctx.clip_y1, te)) return;
  const RasterState& rs = *dc.state;
  // GL 2.1 §2.14.1: with two-sided lighting a back-facing polygon takes the back colours.
  const int slot = (rs.two_sided && back_facing) ? kAttrBackColor : kAttrColor;
  FragInputs in;
  const PlaneSetup ps = make_plane_setup(t);
  const ShadePath shade = setup_triangle_inputs(ctx, ps, a, b, c, provoking, rs.flat, slot, in);
  traverse(te, ctx, in, ctx.fn[static_cast<int>(shade)]);
}

} // namespace pineda
