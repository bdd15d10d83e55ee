// Line rasterization, width 1, not antialiased (GL 2.1 §3.4.1).
//
// Which fragments: the diamond-exit rule. A fragment is produced for every pixel whose
// diamond |x - xc| + |y - yc| < 1/2 the segment intersects, except the diamond containing
// the end point; the end points are perturbed by (epsilon, epsilon^2) so ties resolve.
//
// For an x-major segment (|dx| >= |dy|) every pixel column holds at most one diamond the
// segment passes through, and a segment entering a diamond through one of its slanted
// sides (slopes +-1, steeper than the segment) stays inside until it crosses the column's
// centre line. So a diamond that contains neither end point is hit exactly when the segment
// crosses the centre line inside it: the pixel row containing the segment's height there.
// The diamonds containing an end point are then fixed up: the start one is always produced
// (the segment exits it), the end one never. y-major segments swap the roles of x and y.
//
// Ties under the perturbation: crossing a centre line exactly on a pixel boundary, an
// x-major segment with positive slope goes to the upper row and otherwise to the lower row;
// a y-major segment goes to the left column. An end point exactly on a diamond's boundary is
// inside it when it lies on the right half (x > xc), since the -epsilon shift moves it inward.
//
// Values: t is the projection of the fragment centre on the segment (GL 2.1 §3.4.1 eq 3.6),
// a linear function of the window position, so z, c/w and 1/w are planes like a
// triangle's: depth linear in t, colour perspective-correct (eq 3.7).
#include <climits>
#include <cstdint>
#include <cstdlib>

#include "fragment/fragment_ops.h"
#include "raster/raster.h"
#include "raster/setup.h"
#include "raster/setup_shade.h"

namespace pineda {

namespace {

inline int64_t floor_div(int64_t a, int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

// The pixel whose diamond contains the (perturbed) point (x, y), given in 1/256 pixel, or
// false. Only the diamond of the pixel containing the perturbed point can hold it; moved by
// -epsilon, a point on a pixel's left or bottom boundary lies in the pixel before.
inline bool diamond_pixel(int64_t x, int64_t y, int64_t& px, int64_t& py) {
  px = floor_div(x - 1, kSubpixelOne);
  py = floor_div(y - 1, kSubpixelOne);
  const int64_t u = x - (px * kSubpixelOne + kSubpixelOne / 2);
  const int64_t v = y - (py * kSubpixelOne + kSubpixelOne / 2);
  const int64_t d = (u < 0 ? -u : u) + (v < 0 ? -v : v);
  return d < kSubpixelOne / 2 || (d == kSubpixelOne / 2 && u > 0);
}

// Collects the fragments of a line into aligned 8x8 blocks for the block loop. A line visits
// its blocks in order and never hits a pixel twice, so flushing on block change is enough.
struct BlockBatch {
  const FragCtx& ctx;
  const FragInputs& in;
  BlockFn fn;
  int bx = INT_MIN, by = INT_MIN;
  uint64_t mask = 0;

  void add(int x, int y) {
    if (x < ctx.clip_x0 || x > ctx.clip_x1 || y < ctx.clip_y0 || y > ctx.clip_y1) return;
    const int nbx = x & ~(kBlockSize - 1), nby = y & ~(kBlockSize - 1);
    if (nbx != bx || nby != by) {
      flush();
      bx = nbx;
      by = nby;
    }
    mask |= uint64_t{1} << (8 * (y - by) + (x - bx));
  }
  void flush() {
    if (mask != 0) fn(ctx, in, bx, by, mask);
    mask = 0;
  }
};

void line(const DrawCall& dc, const FragCtx& ctx, const PVertex& a, const PVertex& b,
          const PVertex& provoking) {
  if (ctx.noop) return;
  // Snapped like triangle vertices, so lines and polygon edges agree on positions.
  const int64_t xa = to_fixed(a.win[0]), ya = to_fixed(a.win[1]);
  const int64_t xb = to_fixed(b.win[0]), yb = to_fixed(b.win[1]);
  const int64_t dx = xb - xa, dy = yb - ya;
  if (dx == 0 && dy == 0) return; // the end point lies in every diamond the start point does

  // Interpolation planes from t(x, y) = ((p - pa) . (pb - pa)) / |pb - pa|^2.
  FragInputs in;
  in.ox = static_cast<int>(xa >> kSubpixelBits);
  in.oy = static_cast<int>(ya >> kSubpixelBits);
  constexpr double kInvOne = 1.0 / kSubpixelOne;
  const double fdx = dx * kInvOne, fdy = dy * kInvOne;
  const double inv_len2 = 1.0 / (fdx * fdx + fdy * fdy);
  const double tdx = fdx * inv_len2, tdy = fdy * inv_len2;
  const double t0 = ((in.ox + 0.5 - xa * kInvOne) * fdx + (in.oy + 0.5 - ya * kInvOne) * fdy) *
                    inv_len2;
  const auto line_plane = [&](double va, double vb) {
    const double dv = vb - va;
    return PlaneD{va + dv * t0, dv * tdx, dv * tdy};
  };
  const auto line_plane_f = [&](double va, double vb) {
    const PlaneD p = line_plane(va, vb);
    return PlaneF{static_cast<float>(p.v0), static_cast<float>(p.dx), static_cast<float>(p.dy)};
  };
  if (ctx.needs_depth) in.z = line_plane(a.win[2] * ctx.depth_max, b.win[2] * ctx.depth_max);
  ShadePath shade = ShadePath::Const;
  if (ctx.needs_color) {
    const float* ca = a.attr + kAttrColor;
    const float* cb = b.attr + kAttrColor;
    const bool same = ca[0] == cb[0] && ca[1] == cb[1] && ca[2] == cb[2] && ca[3] == cb[3];
    if (dc.state->flat || same) {
      // GL 2.1 §2.14.7: flat shading takes the provoking vertex's colour.
      const_color(dc.state->flat ? provoking : a, kAttrColor, in.const_color);
    } else {
      const double wa = a.win[3], wb = b.win[3];
      in.inv_w = line_plane_f(wa, wb);
      for (int k = 0; k < 4; ++k) in.color_w[k] = line_plane_f(ca[k] * wa, cb[k] * wb);
      shade = ShadePath::Smooth;
    }
  }
  ShadeInputs si; // texturing and fog (fragment/shade.h)
  if (ctx.shade != nullptr) {
    setup_shade_line(*ctx.shade, a, b, provoking, dc.state->flat, t0, tdx, tdy, si);
    in.shade = &si;
    shade = ShadePath::PerFragment;
  }
  BlockBatch batch{ctx, in, ctx.fn[static_cast<int>(shade)]};

  // Major axis u, minor axis v.
  const bool x_major = std::llabs(dx) >= std::llabs(dy);
  const int64_t ua = x_major ? xa : ya, va = x_major ? ya : xa;
  const int64_t ub = x_major ? xb : yb;
  const int64_t du = x_major ? dx : dy, dv = x_major ? dy : dx;
  constexpr int64_t kHalf = kSubpixelOne / 2;
  // Pixels p along u whose centre line u_c = 256 p + 128 the perturbed segment crosses: with
  // both ends moved by -epsilon (x) or -epsilon^2 (y), that is min(ua, ub) <= u_c < max.
  const int64_t u_lo = du > 0 ? ua : ub, u_hi = du > 0 ? ub : ua;
  int64_t p0 = floor_div(u_lo - kHalf + kSubpixelOne - 1, kSubpixelOne);
  int64_t p1 = floor_div(u_hi - 1 - kHalf, kSubpixelOne);
  const int64_t umin = x_major ? ctx.clip_x0 : ctx.clip_y0;
  const int64_t umax = x_major ? ctx.clip_x1 : ctx.clip_y1;
  if (p0 < umin) p0 = umin;
  if (p1 > umax) p1 = umax;

  // Diamonds holding the end points (see top).
  int64_t sx = 0, sy = 0, ex = 0, ey = 0;
  bool start_in = diamond_pixel(xa, ya, sx, sy);
  const bool end_in = diamond_pixel(xb, yb, ex, ey);
  if (start_in && end_in && sx == ex && sy == ey) start_in = false;

  if (p0 <= p1) {
    // v at the centre line, in 1/256 pixel: V / dun with dun = |du|; the minor pixel is
    // floor(V / (256 dun)), stepped as quotient and remainder to stay exact.
    const int64_t dun = du > 0 ? du : -du, dvn = du > 0 ? dv : -dv;
    const int64_t den = dun * kSubpixelOne;
    const int64_t v_start = va * dun + (p0 * kSubpixelOne + kHalf - ua) * dvn;
    int64_t q = floor_div(v_start, den);
    int64_t rem = v_start - q * den;
    const int64_t step = dvn * kSubpixelOne;
    const int64_t step_q = floor_div(step, den);
    const int64_t step_r = step - step_q * den;
    // On a pixel boundary (see top): the perturbed x-major segment passes above the corner
    // when its slope is positive, below otherwise; a y-major one passes to its left.
    const int64_t tie_adjust = (x_major && dvn > 0) ? 0 : 1;
    for (int64_t p = p0; p <= p1; ++p) {
      const int64_t minor = rem == 0 ? q - tie_adjust : q;
      const int64_t x = x_major ? p : minor, y = x_major ? minor : p;
      if (end_in && x == ex && y == ey) {
        // The segment ends inside this diamond: no fragment.
      } else if (start_in && x == sx && y == sy) {
        start_in = false; // produced here already
        batch.add(static_cast<int>(x), static_cast<int>(y));
      } else {
        batch.add(static_cast<int>(x), static_cast<int>(y));
      }
      q += step_q;
      rem += step_r;
      if (rem >= den) {
        rem -= den;
        ++q;
      }
    }
  }
  // The segment starts inside a diamond beyond its centre line: it still exits it.
  if (start_in) batch.add(static_cast<int>(sx), static_cast<int>(sy));
  batch.flush();
}

} // namespace

void raster_line(const DrawCall& dc, const PVertex& a, const PVertex& b,
                 const PVertex& provoking) {
  if (dc.frag != nullptr) return line(dc, *dc.frag, a, b, provoking);
  FragCtx ctx;
  prepare_fragments(*dc.state, *dc.fb, ctx);
  line(dc, ctx, a, b, provoking);
}

} // namespace pineda
