// Triangle rasterization (GL 2.1 §3.5.1): traversal of the bounding box in 8x8 blocks
// aligned to multiples of 8. A block outside one edge is skipped, a block inside all three is
// handed on whole without per-pixel edge tests, and only blocks on an edge are tested pixel
// by pixel. Coverage masks go to the fragment stage's key-selected block loop.
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <new>

#include "fragment/fragment_ops.h"
#include "core/simd.h"
#include "raster/bin.h"
#include "raster/raster.h"
#include "raster/setup.h"
#include "raster/setup_shade.h"

namespace pineda {

namespace {

// Floor and ceiling of a / b for b > 0.
inline int64_t floor_div(int64_t a, int64_t b) {
  return a >= 0 ? a / b : -((-a + b - 1) / b);
}
inline int64_t ceil_div(int64_t a, int64_t b) {
  return -floor_div(-a, b);
}

// Per-pixel coverage of one block within the pixel bounds [c0,c1]x[r0,r1] of the block,
// in exact 64-bit arithmetic.
inline uint64_t partial_mask64(const TriEdges& te, const int64_t e[3], int c0, int c1, int r0,
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

// The same four lanes at a time in 32 bits, for blocks where every edge value fits: the
// edge functions of a block on an edge are bounded by |E(corner)| + 7 (|sx| + |sy|).
struct Edges32 {
  bool usable = false;          // the steps themselves are small enough
  int64_t limit[3] = {};        // |E(block corner)| must stay below this
  i32x4 lane_lo[3], lane_hi[3]; // column offsets 0..3 and 4..7 times sx
  int32_t sy[3] = {};
};

inline Edges32 make_edges32(const TriEdges& te) {
  Edges32 v;
  constexpr int64_t kMax = int64_t{1} << 31;
  v.usable = true;
  for (int i = 0; i < 3; ++i) {
    const int64_t sx = te.e[i].sx, sy = te.e[i].sy;
    const int64_t span = (kBlockSize - 1) * ((sx < 0 ? -sx : sx) + (sy < 0 ? -sy : sy));
    if (span >= kMax / 2) {
      v.usable = false;
      return v;
    }
    v.limit[i] = kMax - span;
    const auto sx32 = static_cast<int32_t>(sx);
    v.lane_lo[i] = i32x4{0, 1, 2, 3} * sx32;
    v.lane_hi[i] = i32x4{4, 5, 6, 7} * sx32;
    v.sy[i] = static_cast<int32_t>(sy);
  }
  return v;
}

// Eight bits, set where a lane of lo (bits 0-3) or hi (bits 4-7) is negative.
inline unsigned negative_lanes(i32x4 lo, i32x4 hi) {
#if defined(__SSE2__)
  return lane_bits(lo, hi); // the sign bits themselves
#else
  const i32x4 zero = {};
  return lane_bits(lo < zero, hi < zero);
#endif
}

// Rows r0..r1 of the block only (the rows the bounding box reaches; the caller masks off the
// others anyway): one-pixel triangles then test one or two rows, not eight.
inline uint64_t partial_mask32(const Edges32& v, const int64_t e[3], int r0, int r1) {
  i32x4 row[3];
  for (int i = 0; i < 3; ++i)
    row[i] = i32x4{} + static_cast<int32_t>(e[i] + r0 * v.sy[i]);
  // The OR of the three edge values is negative exactly where some edge excludes the pixel:
  // its sign bits, collected as lane masks, are the pixels outside; the mask is their
  // complement.
  uint64_t outside = 0;
  for (int r = r0; r <= r1; ++r) {
    const i32x4 lo = (row[0] + v.lane_lo[0]) | (row[1] + v.lane_lo[1]) | (row[2] + v.lane_lo[2]);
    const i32x4 hi = (row[0] + v.lane_hi[0]) | (row[1] + v.lane_hi[1]) | (row[2] + v.lane_hi[2]);
    outside |= static_cast<uint64_t>(negative_lanes(lo, hi)) << (8 * r);
    if (r < r1) // stay within the bound: no step past the last row
      for (int i = 0; i < 3; ++i)
        row[i] += v.sy[i];
  }
  return ~outside;
}

// Bounding boxes wider than this get the block range of each block row narrowed to the
// columns the edges allow, so long thin triangles do not visit every block of their box.
constexpr int kNarrowWidth = 32;

// GL 2.1 §3.5.2: the polygon stipple's coverage of the 8x8 block at (bx, by), bx a multiple of
// 8: window pixel (x, y) survives when bit x mod 32 of row y mod 32 is set.
inline uint64_t stipple_block_mask(const uint32_t* rows, int bx, int by) {
  const int shift = bx & 31;
  uint64_t m = 0;
  for (int r = 0; r < kBlockSize; ++r)
    m |= static_cast<uint64_t>((rows[(by + r) & 31] >> shift) & 0xffu) << (8 * r);
  return m;
}

// `stipple`: the polygon stipple rows (kStipple), unused otherwise: the unstippled instance
// carries no trace of stippling in its loops. Only the block rows of `bands` are visited.
template <bool kStipple>
void traverse(const TriEdges& te, const FragCtx& ctx, const FragInputs& in, BlockFn fn,
              const uint32_t* stipple, const Bands& bands) {
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
  const Edges32 e32 = make_edges32(te);

  for (int by = te.miny & ~(B - 1); by <= te.maxy; by += B) {
    if (!bands_own(bands, by)) continue;
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
    for (int i = 0; i < 3; ++i)
      e[i] = erow[i] + bx0 * te.e[i].sx;
    for (int bx = bx0; bx <= bx1; bx += B) {
      const bool out =
          (e[0] + reject_off[0] < 0) | (e[1] + reject_off[1] < 0) | (e[2] + reject_off[2] < 0);
      if (!out) {
        uint64_t mask;
        if (e[0] + accept_off[0] >= 0 && e[1] + accept_off[1] >= 0 && e[2] + accept_off[2] >= 0) {
          // Every centre of the block is inside; only the bounding box (which is clipped to
          // the clip rectangle) limits it, and not at all for a block inside the box.
          const bool in_box =
              bx >= te.minx && bx + (B - 1) <= te.maxx && by >= te.miny && by + (B - 1) <= te.maxy;
          mask =
              in_box ? ~uint64_t{0} : rect_block_mask(te.minx, te.miny, te.maxx, te.maxy, bx, by);
        } else if (e32.usable && std::abs(e[0]) < e32.limit[0] && std::abs(e[1]) < e32.limit[1] &&
                   std::abs(e[2]) < e32.limit[2]) {
          mask = partial_mask32(e32, e, r0, r1) &
                 rect_block_mask(te.minx, te.miny, te.maxx, te.maxy, bx, by);
        } else {
          const int c0 = std::max(te.minx - bx, 0), c1 = std::min(te.maxx - bx, B - 1);
          mask = partial_mask64(te, e, c0, c1, r0, r1);
        }
        if constexpr (kStipple) mask &= stipple_block_mask(stipple, bx, by);
        if (mask != 0) fn(ctx, in, bx, by, mask);
      }
      for (int i = 0; i < 3; ++i)
        e[i] += te.e[i].sx * B;
    }
  }
}

// Bounding boxes of at most this many pixels inside one block are tested pixel by pixel
// before the planes are set up (raster_triangle); larger ones go through traverse.
constexpr int kSmallBox = 16;

// Triangle setup (GL 2.1 §3.5.1), shared by direct rasterization and binning (bin.h): the
// edge functions and bounding box, the coverage of a triangle inside one block, and the
// interpolation planes; the result goes to `out`, which either rasterizes it at once or keeps
// it for the tiles. Out provides inputs() and shade_inputs() (storage for the planes) and
// one_block() and traversed() (the set-up triangle).
//
// Inlined into its callers: with one-pixel triangles the call itself is a measurable part of
// the cost.
template <class Out>
[[gnu::always_inline]] inline void
setup_triangle(const DrawCall& dc, const FragCtx& ctx, const SnappedTri& t, const PVertex& a,
               const PVertex& b, const PVertex& c, const PVertex& provoking, bool back_facing,
               Out& out) {
  if (ctx.noop) return;
  if (dc.bands.count > 1) {
    // Another worker draws the whole triangle: skip its setup. Pixel centres inside lie in
    // the rows from floor(ymin) to floor(ymax).
    const int32_t ymin = std::min({t.y[0], t.y[1], t.y[2]});
    const int32_t ymax = std::max({t.y[0], t.y[1], t.y[2]});
    if (!bands_own_rows(dc.bands, std::max(ymin >> kSubpixelBits, ctx.clip_y0),
                        std::min(ymax >> kSubpixelBits, ctx.clip_y1)))
      return;
  }
  TriEdges te;
  if (!setup_edges(t, ctx.clip_x0, ctx.clip_y0, ctx.clip_x1, ctx.clip_y1, te)) return;
  const RasterState& rs = *dc.state;
  const RasterModes& modes = rs.modes;
  // A small bounding box inside one block (most small triangles): its coverage is found before any
  // plane is set up, so a triangle that covers no pixel centre costs no more, and the block
  // goes straight to the fragment stage. The mask is the one traverse would find (the exact
  // edge tests inside the bounding box).
  constexpr int B = kBlockSize;
  const int bx = te.minx & ~(B - 1), by = te.miny & ~(B - 1);
  const bool one_block = bx == (te.maxx & ~(B - 1)) && by == (te.maxy & ~(B - 1)) &&
                         (te.maxx - te.minx + 1) * (te.maxy - te.miny + 1) <= kSmallBox;
  uint64_t mask = 0;
  if (one_block) {
    if (!bands_own(dc.bands, by)) return;
    int64_t e[3];
    for (int i = 0; i < 3; ++i)
      e[i] = te.e[i].base + by * te.e[i].sy + bx * te.e[i].sx;
    mask = partial_mask64(te, e, te.minx - bx, te.maxx - bx, te.miny - by, te.maxy - by);
    if (modes.polygon_stipple) mask &= stipple_block_mask(modes.polygon_stipple_rows, bx, by);
    if (mask == 0) return;
  }
  // GL 2.1 §2.14.1: with two-sided lighting a back-facing polygon takes the back colours.
  const int slot = (rs.two_sided && back_facing) ? kAttrBackColor : kAttrColor;
  FragInputs& in = out.inputs();
  const PlaneSetup ps = make_plane_setup(t);
  ShadePath shade = setup_triangle_inputs(ctx, ps, a, b, c, provoking, rs.flat, slot, in);
  in.back_facing = back_facing ? 1 : 0; // GL 2.1 §4.1.5: the back face's stencil state
  // GL 2.1 §3.5.5: the offset moves the whole depth plane (the fragment stage clamps).
  if (modes.offset_fill && ctx.needs_depth)
    in.z.v0 += polygon_offset_depth(modes, in.z.dx, in.z.dy, ctx.depth_max);
  if (ctx.shade != nullptr) {
    // Texturing and fog (fragment/shade.h): their planes exist only for the draws that use
    // them.
    ShadeInputs& si = out.shade_inputs();
    setup_shade_triangle(*ctx.shade, ps, a, b, c, provoking, rs.flat, slot, back_facing, si);
    in.shade = &si;
    shade = ShadePath::PerFragment;
  }
  const BlockFn fn = ctx.fn[static_cast<int>(shade)];
  if (one_block)
    out.one_block(in, fn, bx, by, mask);
  else
    out.traversed(te, in, fn);
}

// Straight to the fragment stage, within the rows of dc.bands. The planes' storage is
// constructed only when setup reaches them: most one-pixel triangles cover no pixel centre,
// and most draws have no texturing or fog.
struct DirectOut {
  DirectOut(const DrawCall& d, const FragCtx& c) : dc(d), ctx(c) {}
  const DrawCall& dc;
  const FragCtx& ctx;
  alignas(FragInputs) unsigned char in[sizeof(FragInputs)];
  alignas(ShadeInputs) unsigned char si[sizeof(ShadeInputs)];

  FragInputs& inputs() { return *new (in) FragInputs; }
  ShadeInputs& shade_inputs() { return *new (si) ShadeInputs; }
  void one_block(const FragInputs& fi, BlockFn fn, int bx, int by, uint64_t mask) {
    fn(ctx, fi, bx, by, mask);
  }
  void traversed(const TriEdges& te, const FragInputs& fi, BlockFn fn) {
    const RasterModes& modes = dc.state->modes;
    if (modes.polygon_stipple)
      traverse<true>(te, ctx, fi, fn, modes.polygon_stipple_rows, dc.bands);
    else
      traverse<false>(te, ctx, fi, fn, nullptr, dc.bands);
  }
};

[[gnu::always_inline]] inline void triangle(const DrawCall& dc, const FragCtx& ctx,
                                            const SnappedTri& t, const PVertex& a, const PVertex& b,
                                            const PVertex& c, const PVertex& provoking,
                                            bool back_facing) {
  DirectOut out(dc, ctx);
  setup_triangle(dc, ctx, t, a, b, c, provoking, back_facing, out);
}

// Into the bins of a binned draw (bin.h): one record, linked into every tile that the
// bounding box reaches and no edge excludes.
struct BinOut {
  TriBins& bins;
  uint32_t tri = kNoIndex;

  FragInputs& inputs() {
    tri = static_cast<uint32_t>(bins.tris.size());
    return bins.tris.emplace_back().in;
  }
  ShadeInputs& shade_inputs() {
    bins.tris[tri].shade_index = static_cast<uint32_t>(bins.shades.size());
    return bins.shades.emplace_back();
  }
  void one_block(const FragInputs&, BlockFn fn, int bx, int by, uint64_t mask) {
    BinnedTri& r = bins.tris[tri];
    r.fn = fn;
    r.mask = mask;
    r.bx = bx;
    r.by = by;
    bins.add(tri, bx >> kTileShiftX, by >> kTileShiftY);
  }
  void traversed(const TriEdges& te, const FragInputs&, BlockFn fn) {
    BinnedTri& r = bins.tris[tri];
    r.fn = fn;
    r.edge_index = static_cast<uint32_t>(bins.edges.size());
    bins.edges.push_back(te);
    const int tx0 = te.minx >> kTileShiftX, tx1 = te.maxx >> kTileShiftX;
    const int ty0 = te.miny >> kTileShiftY, ty1 = te.maxy >> kTileShiftY;
    if (tx0 == tx1 && ty0 == ty1) return bins.add(tri, tx0, ty0);
    // A tile is skipped when some edge function is negative all over it: at the tile's
    // corner pixel where it is largest (as traverse does for blocks).
    int64_t reject_off[3];
    for (int i = 0; i < 3; ++i)
      reject_off[i] = std::max<int64_t>(te.e[i].sx * (kTileW - 1), 0) +
                      std::max<int64_t>(te.e[i].sy * (kTileH - 1), 0);
    for (int ty = ty0; ty <= ty1; ++ty)
      for (int tx = tx0; tx <= tx1; ++tx) {
        bool out = false;
        for (int i = 0; i < 3; ++i)
          out |= te.e[i].base + int64_t{tx} * kTileW * te.e[i].sx +
                     int64_t{ty} * kTileH * te.e[i].sy + reject_off[i] <
                 0;
        if (!out) bins.add(tri, tx, ty);
      }
  }
};

} // namespace

void raster_triangle(const DrawCall& dc, const PVertex& a, const PVertex& b, const PVertex& c,
                     const PVertex& provoking, bool back_facing) {
  const SnappedTri t = snap_triangle(a, b, c);
  if (dc.frag != nullptr) return triangle(dc, *dc.frag, t, a, b, c, provoking, back_facing);
  FragCtx ctx;
  prepare_fragments(*dc.state, *dc.fb, ctx);
  triangle(dc, ctx, t, a, b, c, provoking, back_facing);
}

void bin_triangle(TriBins& bins, const DrawCall& dc, const SnappedTri& t, const PVertex& a,
                  const PVertex& b, const PVertex& c, const PVertex& provoking, bool back_facing) {
  BinOut out{bins};
  setup_triangle(dc, *dc.frag, t, a, b, c, provoking, back_facing, out);
}

void raster_tile(const DrawCall& dc, const FragCtx& ctx, const TriBins* const* bins, int n,
                 int tile) {
  const TileGrid& grid = bins[0]->grid;
  const int x0 = (tile % grid.tiles_x) * kTileW, y0 = (tile / grid.tiles_x) * kTileH;
  const RasterModes& modes = dc.state->modes;
  const auto t = static_cast<size_t>(tile);
  for (int k = 0; k < n; ++k) {
    const TriBins& b = *bins[k];
    for (uint32_t e = b.head[t]; e != kNoIndex; e = b.entries[e].next) {
      const BinnedTri& r = b.tris[b.entries[e].tri];
      if (r.bx >= 0) {
        r.fn(ctx, r.in, r.bx, r.by, r.mask);
        continue;
      }
      // The triangle within the tile: the tile's edges are block edges, so every block of the
      // tile gets the coverage it gets in the whole triangle's traversal.
      TriEdges te = b.edges[r.edge_index];
      te.minx = std::max(te.minx, x0);
      te.miny = std::max(te.miny, y0);
      te.maxx = std::min(te.maxx, x0 + kTileW - 1);
      te.maxy = std::min(te.maxy, y0 + kTileH - 1);
      if (modes.polygon_stipple)
        traverse<true>(te, ctx, r.in, r.fn, modes.polygon_stipple_rows, Bands{});
      else
        traverse<false>(te, ctx, r.in, r.fn, nullptr, Bands{});
    }
  }
}

void TriBins::reset(const TileGrid& g) {
  const auto tiles = static_cast<size_t>(g.count());
  if (g.tiles_x != grid.tiles_x || g.tiles_y != grid.tiles_y || head.size() != tiles) {
    grid = g;
    head.assign(tiles, kNoIndex);
    tail.assign(tiles, kNoIndex);
  } else {
    // Only the tiles of the last batch hold entries.
    for (int ty = ty0; ty <= ty1; ++ty)
      for (int tx = tx0; tx <= tx1; ++tx)
        head[static_cast<size_t>(ty * grid.tiles_x + tx)] = kNoIndex;
  }
  tx0 = ty0 = 1 << 30;
  tx1 = ty1 = -1;
  tris.clear();
  edges.clear();
  shades.clear();
  entries.clear();
}

void TriBins::link_shades() {
  if (shades.empty()) return;
  for (BinnedTri& r : tris)
    if (r.shade_index != kNoIndex) r.in.shade = &shades[r.shade_index];
}

void raster_triangle_snapped(const DrawCall& dc, const SnappedTri& t, const PVertex& a,
                             const PVertex& b, const PVertex& c, const PVertex& provoking,
                             bool back_facing) {
  if (dc.frag != nullptr) return triangle(dc, *dc.frag, t, a, b, c, provoking, back_facing);
  FragCtx ctx;
  prepare_fragments(*dc.state, *dc.fb, ctx);
  triangle(dc, ctx, t, a, b, c, provoking, back_facing);
}

} // namespace pineda
