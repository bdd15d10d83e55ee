// Triangle setup (GL 2.1 §3.5.1). See setup.h for the fill rule.
#include "raster/setup.h"

#include <algorithm>

namespace pineda {

namespace {
constexpr int64_t kHalfPixel = kSubpixelOne / 2; // pixel centres sit at +0.5
} // namespace

namespace {

// Edge p->q of a counter-clockwise triangle (setup.h): E(x, y) = (xq - xp)(y - yp) -
// (yq - yp)(x - xp) = A x + B y + C, positive inside.
inline void make_edge(int64_t xp, int64_t yp, int64_t xq, int64_t yq, EdgeFn& out) {
  const int64_t A = yp - yq, B = xq - xp, C = xp * yq - xq * yp;
  // Owning edges (setup.h): interior towards +x (A > 0), or horizontal with the interior
  // towards +y (A == 0, B > 0). The others need E >= 1 at a centre.
  const bool owns = A > 0 || (A == 0 && B > 0);
  out.base = C + kHalfPixel * (A + B) - (owns ? 0 : 1);
  out.sx = A * kSubpixelOne;
  out.sy = B * kSubpixelOne;
}

} // namespace

bool setup_edges(const SnappedTri& t, int cx0, int cy0, int cx1, int cy1, TriEdges& out) {
  // The bounding box first: most tiny triangles hold no pixel centre and need nothing else.
  // Snapped positions lie inside the guard band (23 bits): 32-bit arithmetic is exact here.
  const int32_t min_x = std::min({t.x[0], t.x[1], t.x[2]});
  const int32_t max_x = std::max({t.x[0], t.x[1], t.x[2]});
  const int32_t min_y = std::min({t.y[0], t.y[1], t.y[2]});
  const int32_t max_y = std::max({t.y[0], t.y[1], t.y[2]});
  constexpr int32_t kHalf = kSubpixelOne / 2, kOne = kSubpixelOne;
  // Pixels whose centres lie in [min, max]: ceil((min - 128) / 256) .. floor((max - 128) / 256).
  out.minx = std::max((min_x - kHalf + kOne - 1) >> kSubpixelBits, cx0);
  out.maxx = std::min((max_x - kHalf) >> kSubpixelBits, cx1);
  out.miny = std::max((min_y - kHalf + kOne - 1) >> kSubpixelBits, cy0);
  out.maxy = std::min((max_y - kHalf) >> kSubpixelBits, cy1);
  if (out.minx > out.maxx || out.miny > out.maxy) return false;

  const int64_t area2 = snapped_area2(t);
  if (area2 == 0) return false; // GL 2.1 §3.5.1: zero area produces no fragments

  // Walk the vertices counter-clockwise (y up) so that every edge function is positive
  // inside; raster_triangle does not cull, so clockwise input is just reordered.
  const int64_t x0 = t.x[0], y0 = t.y[0];
  int64_t x1 = t.x[1], y1 = t.y[1], x2 = t.x[2], y2 = t.y[2];
  if (area2 < 0) {
    std::swap(x1, x2);
    std::swap(y1, y2);
  }
  make_edge(x0, y0, x1, y1, out.e[0]);
  make_edge(x1, y1, x2, y2, out.e[1]);
  make_edge(x2, y2, x0, y0, out.e[2]);
  return true;
}

PlaneSetup make_plane_setup(const SnappedTri& t) {
  constexpr double kInvOne = 1.0 / kSubpixelOne;
  PlaneSetup ps;
  ps.x0 = t.x[0] * kInvOne;
  ps.y0 = t.y[0] * kInvOne;
  // Differences of 24-bit integers scaled by a power of two: exact in double, and so is det.
  ps.dx1 = (t.x[1] - t.x[0]) * kInvOne;
  ps.dy1 = (t.y[1] - t.y[0]) * kInvOne;
  ps.dx2 = (t.x[2] - t.x[0]) * kInvOne;
  ps.dy2 = (t.y[2] - t.y[0]) * kInvOne;
  const double det = ps.dx1 * ps.dy2 - ps.dx2 * ps.dy1;
  ps.inv_det = det != 0.0 ? 1.0 / det : 0.0;
  ps.ox = t.x[0] >> kSubpixelBits;
  ps.oy = t.y[0] >> kSubpixelBits;
  ps.cx = (ps.ox + 0.5) - ps.x0;
  ps.cy = (ps.oy + 0.5) - ps.y0;
  return ps;
}

// The plane v(x, y) = v0 + dvdx (x - x0) + dvdy (y - y0) through the three vertices
// (Cramer's rule on the two edge vectors), rebased to the centre of the origin pixel.
PlaneD plane_d(const PlaneSetup& ps, double v0, double v1, double v2) {
  const double d1 = v1 - v0, d2 = v2 - v0;
  const double dx = (d1 * ps.dy2 - d2 * ps.dy1) * ps.inv_det;
  const double dy = (d2 * ps.dx1 - d1 * ps.dx2) * ps.inv_det;
  return {v0 + dx * ps.cx + dy * ps.cy, dx, dy};
}

PlaneF plane_f(const PlaneSetup& ps, double v0, double v1, double v2) {
  const PlaneD p = plane_d(ps, v0, v1, v2);
  return {static_cast<float>(p.v0), static_cast<float>(p.dx), static_cast<float>(p.dy)};
}

ShadePath setup_triangle_inputs(const FragCtx& ctx, const PlaneSetup& ps, const PVertex& a,
                                const PVertex& b, const PVertex& c, const PVertex& provoking,
                                bool flat, int color_slot, FragInputs& in) {
  in.ox = ps.ox;
  in.oy = ps.oy;
  // GL 2.1 §3.5.1 eq 3.10: window z is interpolated linearly, without perspective.
  if (ctx.needs_depth)
    in.z =
        plane_d(ps, a.win[2] * ctx.depth_max, b.win[2] * ctx.depth_max, c.win[2] * ctx.depth_max);
  if (!ctx.needs_color) return ShadePath::Const;
  // GL 2.1 §2.14.7: flat shading takes the provoking vertex's colour.
  if (flat) {
    const_color(provoking, color_slot, in.const_color);
    return ShadePath::Const;
  }
  const float* ca = a.attr + color_slot;
  const float* cb = b.attr + color_slot;
  const float* cc = c.attr + color_slot;
  bool same = true;
  for (int k = 0; k < 4; ++k)
    same = same && ca[k] == cb[k] && ca[k] == cc[k];
  if (same) {
    const_color(a, color_slot, in.const_color);
    return ShadePath::Const;
  }
  // GL 2.1 §3.5.1 eq 3.9: interpolate c/w and 1/w linearly, divide per fragment.
  const double wa = a.win[3], wb = b.win[3], wc = c.win[3];
  in.inv_w = plane_f(ps, wa, wb, wc);
  for (int k = 0; k < 4; ++k)
    in.color_w[k] = plane_f(ps, ca[k] * wa, cb[k] * wb, cc[k] * wc);
  return ShadePath::Smooth;
}

} // namespace pineda
