// Point rasterization (GL 2.1 §3.3).
//
// Size: the point size, or with distance attenuation the size the geometry stage derived per
// vertex (PVertex::point_size, §3.3 eq 3.1, already clamped to POINT_SIZE_MIN/MAX).
//
// Aliased points (§3.3.1): the size is rounded to an integer w >= 1 (halves round down, as
// llvmpipe rounds) and the fragments form the w x w square whose lower-left pixel is
// floor(x) - (w-1)/2 for odd w and floor(x + 1/2) - w/2 for even w (the same for y), each
// taking the vertex's depth and colour.
//
// Smooth points (§3.3.2) as llvmpipe draws them (Mesa's draw "aapoint" stage): a square of
// radius r = size/2 (at least 1 for sizes <= 2 without attenuation) around the point; a
// fragment whose centre lies at squared normalized distance d = ((cx-x)^2 + (cy-y)^2) / r^2
// is produced when d <= 1. The stage means to multiply the alpha by a coverage ramp, 1 for
// d <= k = (1 - 1/r)^2 and (1 - d) / (1 - k) beyond, but Mesa 22.3's shader selects the ramp
// for d <= k and 1 beyond: the factor is (1 - d) / (1 - k) >= 1 inside k and 1 elsewhere, so
// opaque colours give a solid aliased disc. The spec asks for the area of the pixel square
// covered by the disc; Pineda follows llvmpipe (the factor multiplies the alpha, which is
// then clamped).
#include <cmath>

#include "fragment/fragment_ops.h"
#include "raster/frag_emit.h"
#include "raster/raster.h"
#include "raster/setup.h"
#include "raster/setup_shade.h"

namespace pineda {

namespace {

// GL 2.1 §3.3: with the point fade threshold, a point whose derived size falls below it is
// drawn at the threshold size with its alpha scaled by (size / threshold)^2. Mesa's gallium
// drivers do not implement the fade (the size is only clamped), and Pineda follows them.
inline float point_size_of(const RasterModes& m, const PVertex& p) {
  if (m.point_attenuated) return p.point_size;
  return m.point_size;
}

void smooth_point(const FragCtx& ctx, const Bands& bands, const RasterModes& m, const PVertex& p,
                  float size) {
  const double r = (!m.point_attenuated && size <= 2.0f) ? 1.0 : 0.5 * size;
  if (!(r > 0.0)) return;
  const double x = p.win[0], y = p.win[1];
  const double k = (1.0 - 1.0 / r) * (1.0 - 1.0 / r);
  const double inv_r2 = 1.0 / (r * r);
  // Centres inside [x - r, x + r) x [y - r, y + r) (the square's left and bottom edges are
  // owned, as for polygons).
  const int px0 = static_cast<int>(std::ceil(x - r - 0.5)),
            px1 = static_cast<int>(std::ceil(x + r - 0.5)) - 1;
  const int py0 = static_cast<int>(std::ceil(y - r - 0.5)),
            py1 = static_cast<int>(std::ceil(y + r - 0.5)) - 1;
  if (!bands.owns_any(std::max(py0, ctx.clip_y0), std::min(py1, ctx.clip_y1))) return;
  uint8_t rgba[4];
  const_color(p, kAttrColor, rgba);
  const float alpha = p.attr[kAttrColor + 3];
  const double z = p.win[2] * ctx.depth_max;
  for (int py = std::max(py0, ctx.clip_y0); py <= std::min(py1, ctx.clip_y1); ++py) {
    const double dy = py + 0.5 - y;
    for (int px = std::max(px0, ctx.clip_x0); px <= std::min(px1, ctx.clip_x1); ++px) {
      const double dx = px + 0.5 - x;
      const double d = (dx * dx + dy * dy) * inv_r2;
      if (d > 1.0) continue;
      const double cov = d <= k ? (1.0 - d) / (1.0 - k) : 1.0;
      rgba[3] = color_to_unorm8(static_cast<float>(alpha * cov));
      emit_fragment(ctx, bands, px, py, z, rgba);
    }
  }
}

// GL 2.1 §3.3.1: a point sprite is every pixel whose centre lies inside the square of side
// `size` centred on the point (the left and bottom edges owned, as for polygons, and as
// llvmpipe draws sprites), all with the point's data but the replaced texture coordinates.
void sprite_point(const DrawCall& dc, const FragCtx& ctx, const RasterModes& m, const PVertex& p,
                  float size) {
  if (!(size > 0.0f)) return;
  const double h = 0.5 * size;
  const double x = p.win[0], y = p.win[1];
  const double fx0 = std::ceil(x - h - 0.5), fx1 = std::ceil(x + h - 0.5) - 1;
  const double fy0 = std::ceil(y - h - 0.5), fy1 = std::ceil(y + h - 0.5) - 1;
  // Reject squares outside the clip rectangle before converting to int.
  if (!(fx1 >= ctx.clip_x0 && fx0 <= ctx.clip_x1 && fy1 >= ctx.clip_y0 && fy0 <= ctx.clip_y1))
    return;
  const int x0 = static_cast<int>(std::max<double>(fx0, ctx.clip_x0 - 1.0));
  const int y0 = static_cast<int>(std::max<double>(fy0, ctx.clip_y0 - 1.0));
  const int x1 = static_cast<int>(std::min<double>(fx1, ctx.clip_x1 + 1.0));
  const int y1 = static_cast<int>(std::min<double>(fy1, ctx.clip_y1 + 1.0));
  if (x0 > x1 || y0 > y1) return;
  if (!dc.bands.owns_any(std::max(y0, ctx.clip_y0), std::min(y1, ctx.clip_y1))) return;
  FragInputs in;
  in.ox = x0;
  in.oy = y0;
  in.z.v0 = p.win[2] * ctx.depth_max;
  const_color(p, kAttrColor, in.const_color);
  ShadeInputs si;
  ShadePath shade = ShadePath::Const;
  if (ctx.shade != nullptr) {
    setup_shade_sprite(*ctx.shade, m, p, size, x0, y0, si);
    in.shade = &si;
    shade = ShadePath::PerFragment;
  }
  emit_rect(ctx, dc.bands, in, ctx.fn[static_cast<int>(shade)], x0, y0, x1, y1);
}

void point(const DrawCall& dc, const FragCtx& ctx, const PVertex& p) {
  if (ctx.noop) return;
  const RasterModes& m = dc.state->modes;
  const float size = point_size_of(m, p);
  // §3.3: with point sprites on, POINT_SMOOTH is ignored.
  if (m.point_sprite) return sprite_point(dc, ctx, m, p, size);
  if (m.point_smooth) return smooth_point(ctx, dc.bands, m, p, size);
  // Round to the nearest integer, halves down, at least 1 (llvmpipe's legacy points).
  int w = 1;
  if (size > 1.5f) w = static_cast<int>(std::min(std::ceil(size - 0.5f), kMaxPointSize));
  // "Truncating" for the (possibly negative, guard band) window coordinates means floor:
  // the fragment is the pixel whose square [x, x+1) x [y, y+1) contains the point.
  const float ox = (w & 1) ? std::floor(p.win[0]) : std::floor(p.win[0] + 0.5f);
  const float oy = (w & 1) ? std::floor(p.win[1]) : std::floor(p.win[1] + 0.5f);
  const float x0 = ox - static_cast<float>(w / 2), y0 = oy - static_cast<float>(w / 2);
  // Reject squares entirely outside the clip rectangle before converting to int.
  if (!(x0 + static_cast<float>(w) > static_cast<float>(ctx.clip_x0) &&
        x0 <= static_cast<float>(ctx.clip_x1) &&
        y0 + static_cast<float>(w) > static_cast<float>(ctx.clip_y0) &&
        y0 <= static_cast<float>(ctx.clip_y1)))
    return;
  const int x = static_cast<int>(x0), y = static_cast<int>(y0);
  if (!dc.bands.owns_any(std::max(y, ctx.clip_y0), std::min(y + w - 1, ctx.clip_y1))) return;
  FragInputs in;
  in.ox = x;
  in.oy = y;
  in.z.v0 = p.win[2] * ctx.depth_max;
  const_color(p, kAttrColor, in.const_color);
  ShadeInputs si; // texturing and fog (fragment/shade.h)
  ShadePath shade = ShadePath::Const;
  if (ctx.shade != nullptr) {
    setup_shade_point(*ctx.shade, p, si);
    if (ctx.shade->program != nullptr && ctx.shade->program->point_coord)
      setup_point_coord(p.win[0], p.win[1], size, x, y, si);
    in.shade = &si;
    shade = ShadePath::PerFragment;
  }
  emit_rect(ctx, dc.bands, in, ctx.fn[static_cast<int>(shade)], x, y, x + w - 1, y + w - 1);
}

} // namespace

void raster_point(const DrawCall& dc, const PVertex& p, bool back_facing) {
  FragCtx local;
  const FragCtx* ctx = dc.frag;
  if (ctx == nullptr) {
    prepare_fragments(*dc.state, *dc.fb, local);
    ctx = &local;
  }
  if (back_facing && ctx->key.stencil_test) {
    // GL 2.1 §4.1.5: a vertex of a back-facing polygon in POINT mode (see raster_line).
    const FragCtx back = with_back_stencil(*ctx);
    point(dc, back, p);
    ctx->samples_passed += back.samples_passed;
    return;
  }
  point(dc, *ctx, p);
}

} // namespace pineda
