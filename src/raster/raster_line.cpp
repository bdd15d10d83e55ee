// Line rasterization (GL 2.1 §3.4): aliased lines of any width, stippled or not, and smooth
// lines.
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
// Wide lines (§3.4.2) as llvmpipe draws them: the width is rounded to an integer w, and each
// column (x-major; rows for y-major) that the 1-pixel line produces gets the run of w pixels
// whose centres lie within w/2 of the line along the minor axis, i.e. inside the
// parallelogram llvmpipe rasterizes with its polygon fill rule (centres on an edge belong to
// it when the edge is a left or bottom one). Values then vary along the major axis only, as in
// llvmpipe ("the preferred wide-lines formula"); the spec's column of w fragments centred on the
// diamond-exit fragment differs from this by one pixel at some positions of even widths.
//
// Stipple (§3.4.2): the fragment of each column takes bit ((s + round(d)) / factor) mod 16 of
// the pattern, where d is the column centre's major-axis distance from the segment start and s
// the counter carried over from the previous segments of a strip, advanced by the segment's
// major-axis length rounded up. This is what llvmpipe (Mesa 22.3) produces, measured against
// it; the spec counts fragments instead, which differs where strip vertices or segment ends
// are not at pixel centres.
//
// Smooth lines (§3.4.3) follow Mesa's draw "aaline" stage: the rectangle around the segment
// extended by 1/2 pixel at both ends, of half width 1 (w <= 1) or w/2 + 1/2; a fragment at
// perpendicular distance p from the line and distance a from the segment's midpoint has its
// alpha multiplied by clamp(hw - |p|, 0, 1) * clamp(len/2 + 1/2 - |a|, 0, 1), and its values
// are interpolated from the first vertex at the rectangle's start to the second at its end.
//
// Values: t is the projection of the fragment centre on the segment (GL 2.1 §3.4.1 eq 3.6),
// a linear function of the window position, so z, c/w and 1/w are planes like a
// triangle's: depth linear in t, colour perspective-correct (eq 3.7).
#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include "fragment/fragment_ops.h"
#include "raster/frag_emit.h"
#include "raster/raster.h"
#include "raster/setup.h"
#include "raster/setup_shade.h"

namespace pineda {

namespace {

inline int64_t floor_div(int64_t a, int64_t b) {
  return a >= 0 ? a / b : -((-a + b - 1) / b);
}

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
  const Bands& bands;
  const FragInputs& in;
  BlockFn fn;
  int bx = INT_MIN, by = INT_MIN;
  uint64_t mask = 0;

  void add(int x, int y) {
    if (x < ctx.clip_x0 || x > ctx.clip_x1 || y < ctx.clip_y0 || y > ctx.clip_y1) return;
    if (!bands.owns(y)) return;
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

// Aliased width: llvmpipe rounds the width to the nearest integer, halves away from zero.
inline int aliased_width(const RasterModes& m) {
  return std::max(1, static_cast<int>(std::lround(m.line_width)));
}

void line(const DrawCall& dc, const FragCtx& ctx, const PVertex& a, const PVertex& b,
          const PVertex& provoking) {
  if (ctx.noop) return;
  const RasterModes& modes = dc.state->modes;
  const int width = aliased_width(modes);
  const bool stipple = modes.line_stipple;
  // Snapped like triangle vertices, so lines and polygon edges agree on positions.
  const int64_t xa = to_fixed(a.win[0]), ya = to_fixed(a.win[1]);
  const int64_t xb = to_fixed(b.win[0]), yb = to_fixed(b.win[1]);
  const int64_t dx = xb - xa, dy = yb - ya;
  // The counter advances by the segment's major-axis length even when nothing is drawn. The
  // length is taken from the snapped positions: a segment between pixel centres is a whole
  // number of pixels long even when rounding in the transforms left it a few ulps longer
  // (piglit linestipple: 32.000004 would advance the counter by 33).
  float* counter = dc.stipple_counter;
  const int64_t seg_sub = std::max(std::llabs(dx), std::llabs(dy));
  const int64_t seg_len = (seg_sub + kSubpixelOne - 1) / kSubpixelOne;
  const int64_t stipple_base = (stipple && counter != nullptr) ? static_cast<int64_t>(*counter) : 0;
  if (stipple && counter != nullptr) *counter += static_cast<float>(seg_len);
  if (dx == 0 && dy == 0) return; // the end point lies in every diamond the start point does
  // Another worker draws the whole line (its fragments lie within width + 1 rows of the
  // segment's rows): skip its setup.
  if (dc.bands.count > 1) {
    const int64_t pad = width + 1;
    const int64_t y0 = (std::min(ya, yb) >> kSubpixelBits) - pad;
    const int64_t y1 = (std::max(ya, yb) >> kSubpixelBits) + pad;
    if (!dc.bands.owns_any(static_cast<int>(std::max<int64_t>(y0, ctx.clip_y0)),
                           static_cast<int>(std::min<int64_t>(y1, ctx.clip_y1))))
      return;
  }

  // Interpolation planes from t(x, y) = ((p - pa) . (pb - pa)) / |pb - pa|^2.
  FragInputs in;
  in.ox = static_cast<int>(xa >> kSubpixelBits);
  in.oy = static_cast<int>(ya >> kSubpixelBits);
  constexpr double kInvOne = 1.0 / kSubpixelOne;
  const double fdx = dx * kInvOne, fdy = dy * kInvOne;
  const double inv_len2 = 1.0 / (fdx * fdx + fdy * fdy);
  const double tdx = fdx * inv_len2, tdy = fdy * inv_len2;
  const double t0 =
      ((in.ox + 0.5 - xa * kInvOne) * fdx + (in.oy + 0.5 - ya * kInvOne) * fdy) * inv_len2;
  const bool x_major = std::llabs(dx) >= std::llabs(dy);
  // Wide lines: t along the major axis only (see top).
  const double wt0 =
      x_major ? (in.ox + 0.5 - xa * kInvOne) / fdx : (in.oy + 0.5 - ya * kInvOne) / fdy;
  const bool wide = width > 1;
  const auto line_plane = [&](double va, double vb) {
    const double dv = vb - va;
    if (wide)
      return x_major ? PlaneD{va + dv * wt0, dv / fdx, 0.0} : PlaneD{va + dv * wt0, 0.0, dv / fdy};
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
      for (int k = 0; k < 4; ++k)
        in.color_w[k] = line_plane_f(ca[k] * wa, cb[k] * wb);
      shade = ShadePath::Smooth;
    }
  }
  ShadeInputs si; // texturing and fog (fragment/shade.h)
  if (ctx.shade != nullptr) {
    setup_shade_line(*ctx.shade, a, b, provoking, dc.state->flat, t0, tdx, tdy, si);
    in.shade = &si;
    shade = ShadePath::PerFragment;
  }
  BlockBatch batch{ctx, dc.bands, in, ctx.fn[static_cast<int>(shade)]};

  // Major axis u, minor axis v.
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

  // One fragment per column (x-major) or row (y-major) of the 1-pixel line, widened and
  // stippled here when asked to.
  const int64_t dun_all = du > 0 ? du : -du, dvn_all = du > 0 ? dv : -dv;
  const int64_t half_w = int64_t{width} * (kSubpixelOne / 2); // w/2 in 1/256 pixel
  // Fill-rule ownership of the parallelogram's two long edges (see top): the low-minor edge
  // is owned unless it is a "right" edge (x-major with a positive slope), the high one only
  // when it is a "left" edge (x-major with a positive slope).
  const bool pos_slope = x_major && ((dx > 0) == (dy > 0)) && dy != 0;
  const bool lo_owned = !pos_slope, hi_owned = pos_slope;
  const int64_t fac = modes.line_stipple_factor;
  const uint32_t pattern = modes.line_stipple_pattern;
  const auto emit = [&](int64_t x, int64_t y) {
    const int64_t col = x_major ? x : y;
    if (stipple) {
      // Major-axis distance of the column centre from the start, whole pixels, >= 0.
      const int64_t dist = (col * kSubpixelOne + kHalf - ua) * (du > 0 ? 1 : -1);
      const int64_t i = stipple_base + (dist > -kHalf ? (dist + kHalf) / kSubpixelOne : 0);
      if (((pattern >> ((i / fac) & 15)) & 1u) == 0) return;
    }
    if (!wide) {
      batch.add(static_cast<int>(x), static_cast<int>(y));
      return;
    }
    // Line's minor coordinate at the column centre, times dun (1/256 pixel units): V / dun.
    const int64_t V = va * dun_all + (col * kSubpixelOne + kHalf - ua) * dvn_all;
    const int64_t den = dun_all * kSubpixelOne;
    // Centres c = 256 m + 128 with V - half_w*dun <= c*dun (< when not owned), and so on.
    const int64_t lo_num = V - half_w * dun_all - kHalf * dun_all;
    const int64_t hi_num = V + half_w * dun_all - kHalf * dun_all;
    const int64_t m_lo = lo_owned ? -floor_div(-lo_num, den) : floor_div(lo_num, den) + 1;
    const int64_t m_hi = hi_owned ? floor_div(hi_num, den) : -floor_div(-hi_num, den) - 1;
    if (x_major)
      emit_rect(ctx, dc.bands, in, batch.fn, static_cast<int>(col), static_cast<int>(m_lo),
                static_cast<int>(col), static_cast<int>(m_hi));
    else
      emit_rect(ctx, dc.bands, in, batch.fn, static_cast<int>(m_lo), static_cast<int>(col),
                static_cast<int>(m_hi), static_cast<int>(col));
  };

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
        emit(x, y);
      } else {
        emit(x, y);
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
  if (start_in) emit(sx, sy);
  batch.flush();
}

// Smooth line (see top), fragment by fragment with its own colour and depth.
void smooth_line(const DrawCall& dc, const FragCtx& ctx, const PVertex& a, const PVertex& b,
                 const PVertex& provoking) {
  if (ctx.noop) return;
  const RasterModes& modes = dc.state->modes;
  const double xa = a.win[0], ya = a.win[1], xb = b.win[0], yb = b.win[1];
  const double dx = xb - xa, dy = yb - ya;
  const double len = std::sqrt(dx * dx + dy * dy);
  if (!(len > 0.0)) return;
  const double ux = dx / len, uy = dy / len; // unit direction
  const double hw = modes.line_width <= 1.0f ? 1.0 : 0.5 * modes.line_width + 0.5;
  const double hl = 0.5 * len + 0.5;
  const bool x_major = std::fabs(dx) >= std::fabs(dy);
  // Another worker draws the whole line: skip it.
  if (dc.bands.count > 1) {
    const double y0 = std::floor(std::min(ya, yb) - hw - 2.0);
    const double y1 = std::ceil(std::max(ya, yb) + hw + 2.0);
    if (!dc.bands.owns_any(static_cast<int>(std::max<double>(y0, ctx.clip_y0)),
                           static_cast<int>(std::min<double>(y1, ctx.clip_y1))))
      return;
  }
  // Walk the major axis over the extended segment; each column's minor range covers the
  // rectangle (half width hw perpendicular to the line: hw / cos along the minor axis).
  const double ext = (hw + 1.0) * len / (x_major ? std::fabs(dx) : std::fabs(dy));
  const double u0 = std::min(x_major ? xa : ya, x_major ? xb : yb) - hw - 1.0;
  const double u1 = std::max(x_major ? xa : ya, x_major ? xb : yb) + hw + 1.0;
  const int c0 = std::max(static_cast<int>(std::floor(u0)), x_major ? ctx.clip_x0 : ctx.clip_y0);
  const int c1 = std::min(static_cast<int>(std::ceil(u1)), x_major ? ctx.clip_x1 : ctx.clip_y1);
  const float* ca = (dc.state->flat ? provoking : a).attr + kAttrColor;
  const float* cb = (dc.state->flat ? provoking : b).attr + kAttrColor;
  const double za = a.win[2] * ctx.depth_max, zb = b.win[2] * ctx.depth_max;
  const double slope = x_major ? dy / dx : dx / dy;
  const double ma = x_major ? ya : xa, ua = x_major ? xa : ya;
  for (int c = c0; c <= c1; ++c) {
    const double vc = ma + (c + 0.5 - ua) * slope; // line's minor coordinate at this column
    const int m0 =
        std::max(static_cast<int>(std::floor(vc - ext)), x_major ? ctx.clip_y0 : ctx.clip_x0);
    const int m1 =
        std::min(static_cast<int>(std::ceil(vc + ext)), x_major ? ctx.clip_y1 : ctx.clip_x1);
    for (int m = m0; m <= m1; ++m) {
      const int px = x_major ? c : m, py = x_major ? m : c;
      const double rx = px + 0.5 - xa, ry = py + 0.5 - ya;
      const double along = rx * ux + ry * uy; // from the first vertex
      const double perp = -rx * uy + ry * ux; // signed distance from the line
      const double mid = along - 0.5 * len;
      // Inside the rectangle (strictly: its boundary has zero coverage).
      if (!(std::fabs(perp) < hw && std::fabs(mid) < hl)) continue;
      const double cov =
          std::clamp(hw - std::fabs(perp), 0.0, 1.0) * std::clamp(hl - std::fabs(mid), 0.0, 1.0);
      const double t = (along + 0.5) / (len + 1.0);
      uint8_t rgba[4];
      for (int k = 0; k < 4; ++k) {
        double v = ca[k] + (cb[k] - ca[k]) * t;
        if (k == 3) v *= cov;
        rgba[k] = color_to_unorm8(static_cast<float>(v));
      }
      emit_fragment(ctx, dc.bands, px, py, za + (zb - za) * t, rgba);
    }
  }
}

// A stippled smooth line is cut into dashes as Mesa's draw module does: with L the segment's
// Euclidean length and s the counter, unit step i in [0, ceil(L)) is on when bit
// ((s + i) / factor) mod 16 is set, and each run of on steps [i0, i1) is drawn as a smooth line
// from t = i0 / L to min(i1 / L, 1), its values interpolated linearly in window space.
void stippled_smooth_line(const DrawCall& dc, const FragCtx& ctx, const PVertex& a,
                          const PVertex& b, const PVertex& provoking) {
  const RasterModes& modes = dc.state->modes;
  const double dx = b.win[0] - a.win[0], dy = b.win[1] - a.win[1];
  const double len = std::sqrt(dx * dx + dy * dy);
  float* counter = dc.stipple_counter;
  const int64_t base = counter != nullptr ? static_cast<int64_t>(*counter) : 0;
  if (counter != nullptr) *counter += static_cast<float>(std::ceil(len));
  if (!(len > 0.0) || len > 1e6) return;
  const auto sub_vertex = [&](double t, PVertex& v) {
    v = a;
    for (int k = 0; k < 3; ++k)
      v.win[k] = static_cast<float>(a.win[k] + t * (b.win[k] - a.win[k]));
    for (int k = 0; k < 4; ++k)
      v.attr[kAttrColor + k] = static_cast<float>(
          a.attr[kAttrColor + k] + t * (b.attr[kAttrColor + k] - a.attr[kAttrColor + k]));
  };
  const int64_t steps = static_cast<int64_t>(std::ceil(len));
  const int64_t fac = modes.line_stipple_factor;
  const uint32_t pattern = modes.line_stipple_pattern;
  int64_t run_start = -1;
  for (int64_t i = 0; i <= steps; ++i) {
    const bool on = i < steps && ((pattern >> (((base + i) / fac) & 15)) & 1u) != 0;
    if (on && run_start < 0) run_start = i;
    if (!on && run_start >= 0) {
      PVertex va, vb;
      sub_vertex(static_cast<double>(run_start) / len, va);
      sub_vertex(std::min(static_cast<double>(i) / len, 1.0), vb);
      smooth_line(dc, ctx, va, vb, provoking);
      run_start = -1;
    }
  }
}

void any_line(const DrawCall& dc, const FragCtx& ctx, const PVertex& a, const PVertex& b,
              const PVertex& provoking) {
  const RasterModes& modes = dc.state->modes;
  if (modes.line_smooth) {
    if (modes.line_stipple) return stippled_smooth_line(dc, ctx, a, b, provoking);
    return smooth_line(dc, ctx, a, b, provoking);
  }
  line(dc, ctx, a, b, provoking);
}

} // namespace

void raster_line(const DrawCall& dc, const PVertex& a, const PVertex& b, const PVertex& provoking,
                 bool back_facing) {
  FragCtx local;
  const FragCtx* ctx = dc.frag;
  if (ctx == nullptr) {
    prepare_fragments(*dc.state, *dc.fb, local);
    ctx = &local;
  }
  if (back_facing && ctx->key.stencil_test) {
    // GL 2.1 §4.1.5: the outline of a back-facing polygon is still a polygon for the stencil
    // test; a copy of the fragment set-up with the back state in the front's place.
    const FragCtx back = with_back_stencil(*ctx);
    any_line(dc, back, a, b, provoking);
    ctx->samples_passed += back.samples_passed;
    return;
  }
  any_line(dc, *ctx, a, b, provoking);
}

} // namespace pineda
