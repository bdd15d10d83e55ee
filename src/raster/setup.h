// Triangle setup (GL 2.1 §3.5.1): snapped vertex positions, integer edge functions with the
// fill rule folded in, the pixel bounding box, and the attribute plane equations.
//
// Fill rule. Window x and y are snapped to 1/256 pixel (to_fixed, the same rounding the
// culling test uses, so facing and coverage agree). A fragment is produced for every pixel
// whose centre (x + 0.5, y + 0.5) lies strictly inside the triangle. A centre exactly on an
// edge belongs to the triangle when, in GL's y-up window space, the edge is
//   - a "left" edge: the interior lies towards +x of it, or
//   - a "bottom" edge: the edge is horizontal and the interior lies above it (+y).
// Two triangles sharing an edge lie on opposite sides of it, so exactly one of them owns the
// centres on it; a mesh is covered without gaps or double hits. This is the ownership
// llvmpipe produces for GL window-system framebuffers (gallium's "bottom_edge_rule" in its
// y-down raster space is GL's bottom edge), so both cover the same pixels for the same input.
//
// The rule is applied as a bias: with the edge function E positive inside, a centre is
// inside when E >= 0 on owning edges and E >= 1 (E - 1 >= 0) on the others, so the per-pixel
// test is just the sign of (E0 | E1 | E2).
#pragma once

#include <cstdint>

#include "fragment/fragment_ops.h"
#include "core/vertex.h"
#include "raster/raster.h"

namespace pineda {

// E(px, py) = base + px*sx + py*sy at the centre of pixel (px, py), in 1/65536 pixel^2.
// With window coordinates inside +-kGuardBand, positions need 23 bits, steps 32 bits and
// values about 47 bits: 64-bit arithmetic is exact.
struct EdgeFn {
  int64_t base = 0;
  int64_t sx = 0;
  int64_t sy = 0;
};

struct TriEdges {
  EdgeFn e[3];
  int minx = 0, miny = 0, maxx = -1, maxy = -1; // covered-pixel bounds, inclusive, clipped
};

// Snapped positions in 1/256 pixel.
struct SnappedTri {
  int32_t x[3];
  int32_t y[3];
};

inline SnappedTri snap_triangle(const PVertex& a, const PVertex& b, const PVertex& c) {
  return {{to_fixed(a.win[0]), to_fixed(b.win[0]), to_fixed(c.win[0])},
          {to_fixed(a.win[1]), to_fixed(b.win[1]), to_fixed(c.win[1])}};
}

// Bands::owns and Bands::owns_any (workers.h) with a mask instead of a division when the
// thread count is a power of two: the triangle path asks once or twice per triangle.
inline bool band_owned(const Bands& b, unsigned band) {
  const auto n = static_cast<unsigned>(b.count), i = static_cast<unsigned>(b.index);
  return ((n & (n - 1)) == 0 ? (band & (n - 1)) : band % n) == i;
}
inline bool bands_own(const Bands& b, int y) {
  return b.count == 1 || band_owned(b, static_cast<unsigned>(y >> kBandShift));
}
inline bool bands_own_rows(const Bands& b, int y0, int y1) {
  if (b.count == 1) return true;
  y0 = y0 > 0 ? y0 : 0;
  if (y1 < y0) return false;
  const auto b0 = static_cast<unsigned>(y0 >> kBandShift),
             b1 = static_cast<unsigned>(y1 >> kBandShift);
  if (b1 - b0 + 1 >= static_cast<unsigned>(b.count)) return true;
  for (unsigned band = b0; band <= b1; ++band)
    if (band_owned(b, band)) return true;
  return false;
}

// Twice the signed area of a snapped triangle, as fixed_area2 (raster.h) computes it.
inline int64_t snapped_area2(const SnappedTri& t) {
  const int64_t x0 = t.x[0], y0 = t.y[0];
  return (t.x[1] - x0) * (t.y[2] - y0) - (t.x[2] - x0) * (t.y[1] - y0);
}

// raster_triangle (raster.h) for a triangle whose snapped positions the caller has already
// (primitive assembly snaps them for the facing test).
void raster_triangle_snapped(const DrawCall& dc, const SnappedTri& t, const PVertex& a,
                             const PVertex& b, const PVertex& c, const PVertex& provoking,
                             bool back_facing);

// Edge functions and bounding box, clipped to [cx0,cx1]x[cy0,cy1]. Either winding; returns
// false for a zero-area triangle or one that covers no pixel centre of the clip rectangle.
bool setup_edges(const SnappedTri& t, int cx0, int cy0, int cx1, int cy1, TriEdges& out);

// Plane equations through three points given in pixels (snapped positions / 256).
struct PlaneSetup {
  double x0 = 0, y0 = 0;   // first vertex
  double dx1 = 0, dy1 = 0; // second - first
  double dx2 = 0, dy2 = 0; // third - first
  double inv_det = 0;
  int ox = 0, oy = 0;    // origin pixel of the planes (FragInputs::ox, oy)
  double cx = 0, cy = 0; // centre of the origin pixel minus the first vertex
};

PlaneSetup make_plane_setup(const SnappedTri& t);
PlaneD plane_d(const PlaneSetup& ps, double v0, double v1, double v2);
PlaneF plane_f(const PlaneSetup& ps, double v0, double v1, double v2);

// Fills `in` for a triangle: z (when ctx.needs_depth), and colour from attribute slot
// `color_slot` (kAttrColor or kAttrBackColor), constant from `provoking` under flat shading.
// Returns the shade path to run.
ShadePath setup_triangle_inputs(const FragCtx& ctx, const PlaneSetup& ps, const PVertex& a,
                                const PVertex& b, const PVertex& c, const PVertex& provoking,
                                bool flat, int color_slot, FragInputs& in);

// Constant colour of a primitive (points, flat shading) from an attribute slot.
inline void const_color(const PVertex& v, int slot, uint8_t out[4]) {
  for (int k = 0; k < 4; ++k)
    out[k] = color_to_unorm8(v.attr[slot + k]);
}

} // namespace pineda
