// Pixel rectangles and bitmaps to fragments. Every fragment of a run of equal groups shares one
// colour and one depth, so runs go to the fragment stage's constant-colour block loop with a
// coverage mask per 8x8 block: the per-fragment operations are exactly those of primitives.
#include "pixel/pixel_draw.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "fragment/fragment_ops.h"
#include "fragment/shade.h"

namespace pineda {

namespace {

float clamp01(float v) {
  return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;
}

// Window pixels [lo[n], hi[n]) covered by group n along one axis (§3.6.4): the pixel whose
// centre c satisfies min <= c < max of the group's two edges. Kept far inside the int range.
void group_spans(int count, int64_t first, float origin, float zoom, std::vector<int>& lo,
                 std::vector<int>& hi) {
  lo.resize(static_cast<size_t>(count));
  hi.resize(static_cast<size_t>(count));
  const auto pixel = [](double edge) {
    if (std::isnan(edge)) return 0; // spans of NaN edges are empty
    const double v = std::ceil(edge - 0.5);
    return static_cast<int>(std::clamp(v, -1073741824.0, 1073741824.0));
  };
  for (int n = 0; n < count; ++n) {
    const double g = static_cast<double>(first) + n;
    const double a = static_cast<double>(origin) + static_cast<double>(zoom) * g;
    const double b = static_cast<double>(origin) + static_cast<double>(zoom) * (g + 1.0);
    lo[static_cast<size_t>(n)] = pixel(std::min(a, b));
    hi[static_cast<size_t>(n)] = pixel(std::max(a, b));
  }
}

// Runs the fragments of the window rectangle [x0, x1) x [y0, y1), clipped to the framebuffer
// and scissor box, through the constant-colour block loop, or the per-fragment one when
// in.shade is set.
void emit_rect(const FragCtx& fc, FragInputs& in, int x0, int y0, int x1, int y1) {
  x0 = std::max(x0, fc.clip_x0);
  y0 = std::max(y0, fc.clip_y0);
  x1 = std::min(x1, fc.clip_x1 + 1);
  y1 = std::min(y1, fc.clip_y1 + 1);
  if (x0 >= x1 || y0 >= y1) return;
  const BlockFn fn =
      fc.fn[static_cast<int>(in.shade != nullptr ? ShadePath::PerFragment : ShadePath::Const)];
  for (int by = y0 & ~(kBlockSize - 1); by < y1; by += kBlockSize) {
    for (int bx = x0 & ~(kBlockSize - 1); bx < x1; bx += kBlockSize) {
      const uint64_t mask = rect_block_mask(x0, y0, x1 - 1, y1 - 1, bx, by);
      if (mask == 0) continue;
      in.ox = bx;
      in.oy = by;
      fn(fc, in, bx, by, mask);
    }
  }
}

// True when a fragment's only effect is to store its colour in every channel: no texturing
// or fog, no depth or stencil test, no alpha test, blending or logic op, full colour mask.
// Such runs are written straight into the colour buffer.
bool plain_store(const FragCtx& fc) {
  const StateKey& k = fc.key;
  return fc.shade == nullptr && !k.depth_test && !k.ext() && k.blend_path() == BlendPath::Off &&
         k.color_path() == ColorPath::All;
}

// The per-fragment inputs of pixel fragments (§3.6.4 "Conversion to Fragments", §3.7): every
// value constant, the texture coordinates and fog distance those of the raster position. The
// caller sets the colours.
void raster_shade_inputs(const ShadeSetup& ss, const RasterPos& rp, ShadeInputs& si) {
  si.inv_w = PlaneF{1.0f, 0.0f, 0.0f};
  if (ss.program != nullptr) {
    // A fragment shader (§3.11): the raster position's colours, coordinates and distance for
    // every fragment; varyings are zero (no vertex shader ran for them).
    const FragmentProgram& fp = *ss.program;
    si.front_facing = true;
    if (fp.point_coord) si.point_coord[0] = si.point_coord[1] = PlaneF{};
    for (int i = 0; i < fp.input_count; ++i) {
      const int a = fp.input_attr[i];
      float v = 0.0f;
      if (a >= kAttrColor && a < kAttrColor + 4)
        v = rp.color[a - kAttrColor];
      else if (a >= kAttrColor2 && a < kAttrColor2 + 4)
        v = rp.color2[a - kAttrColor2];
      else if (a >= kAttrTex0 && a < kAttrTex0 + 4 * kMaxTexUnits)
        v = rp.tex[(a - kAttrTex0) / 4][(a - kAttrTex0) % 4];
      else if (a == kAttrFog)
        v = rp.distance;
      si.prog_w[i] = {v, 0.0f, 0.0f};
    }
  }
  for (int k = 0; k < ss.unit_count; ++k) {
    const int u = ss.unit[k].index;
    for (int c = 0; c < 4; ++c)
      si.tex_w[u][c] = PlaneF{rp.tex[u][c], 0.0f, 0.0f};
  }
  si.fog_w = PlaneF{rp.distance, 0.0f, 0.0f};
  si.const_colors = true;
  for (int c = 0; c < 4; ++c)
    si.color[c] = 0.0f;
  for (int c = 0; c < 3; ++c)
    si.color2[c] = 0.0f;
}

// Stores `rgba` into the colour buffer over [x0, x1) x [y0, y1), clipped like emit_rect.
void store_rect(const FragCtx& fc, const Framebuffer& fb, const uint8_t rgba[4], int x0, int y0,
                int x1, int y1) {
  x0 = std::max(x0, fc.clip_x0);
  y0 = std::max(y0, fc.clip_y0);
  x1 = std::min(x1, fc.clip_x1 + 1);
  y1 = std::min(y1, fc.clip_y1 + 1);
  if (x0 >= x1 || y0 >= y1) return;
  uint8_t px[4];
  switch (fb.color_format) {
  case ColorFormat::RGBA8:
    std::memcpy(px, rgba, 4);
    break;
  case ColorFormat::BGRA8:
    px[0] = rgba[2], px[1] = rgba[1], px[2] = rgba[0], px[3] = rgba[3];
    break;
  case ColorFormat::ARGB8:
    px[0] = rgba[3], px[1] = rgba[0], px[2] = rgba[1], px[3] = rgba[2];
    break;
  case ColorFormat::RGB8:
    std::memcpy(px, rgba, 3);
    break;
  }
  const size_t bpp = static_cast<size_t>(bytes_per_pixel(fb.color_format));
  for (int y = y0; y < y1; ++y) {
    uint8_t* row = fb.color_row(y) + static_cast<size_t>(x0) * bpp;
    for (int x = x0; x < x1; ++x, row += bpp)
      std::memcpy(row, px, bpp);
  }
}

// The plain store of an unzoomed colour rectangle whose first group lands on pixel (x, y):
// row by row, each group converted and written in the buffer's byte order.
void store_unzoomed(const FragCtx& fc, const Framebuffer& fb, const float* rgba, int w, int h,
                    int x, int y) {
  const int64_t n0 = std::max<int64_t>(0, int64_t{fc.clip_x0} - x);
  const int64_t n1 = std::min<int64_t>(w, int64_t{fc.clip_x1} + 1 - x);
  if (n0 >= n1) return;
  int off[4] = {0, 1, 2, 3}; // byte of R, G, B, A in a stored pixel; -1: not stored
  switch (fb.color_format) {
  case ColorFormat::RGBA8:
    break;
  case ColorFormat::BGRA8:
    off[0] = 2, off[2] = 0;
    break;
  case ColorFormat::ARGB8:
    off[0] = 1, off[1] = 2, off[2] = 3, off[3] = 0;
    break;
  case ColorFormat::RGB8:
    off[3] = -1;
    break;
  }
  const int channels = off[3] < 0 ? 3 : 4;
  const size_t bpp = static_cast<size_t>(bytes_per_pixel(fb.color_format));
  for (int m = 0; m < h; ++m) {
    const int64_t py = int64_t{y} + m;
    if (py < fc.clip_y0 || py > fc.clip_y1) continue;
    uint8_t* dst = fb.color_row(static_cast<int>(py)) + static_cast<size_t>(x + n0) * bpp;
    const float* src =
        rgba + (static_cast<size_t>(m) * static_cast<size_t>(w) + static_cast<size_t>(n0)) * 4;
    for (int64_t n = n0; n < n1; ++n, dst += bpp, src += 4)
      for (int c = 0; c < channels; ++c)
        dst[off[c]] = color_to_unorm8(src[c]);
  }
}

void set_color(FragInputs& in, const float* rgba) {
  for (int c = 0; c < 4; ++c)
    in.const_color[c] = color_to_unorm8(rgba[c]);
}

} // namespace

uint64_t draw_pixel_rect(const RasterState& rs, const Framebuffer& fb, const PixelRect& r) {
  const PixelPlacement& p = r.place;
  if (p.w <= 0 || p.h <= 0 || (r.rgba == nullptr) == (r.depth == nullptr)) return 0;
  // A raster position given as NaN or infinity (glWindowPos accepts any value) covers no pixel.
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) return 0;
  FragCtx fc;
  prepare_fragments(rs, fb, fc);
  if (fc.noop) return 0;
  std::vector<int> col_lo, col_hi, row_lo, row_hi;
  group_spans(p.w, p.col0, p.x, p.zoom_x, col_lo, col_hi);
  group_spans(p.h, p.row0, p.y, p.zoom_y, row_lo, row_hi);

  const bool direct = plain_store(fc);
  if (direct && r.rgba != nullptr && r.present == nullptr && p.zoom_x == 1.0f && p.zoom_y == 1.0f) {
    // Zoom 1: group (n, m) is the single pixel (col_lo[0] + n, row_lo[0] + m). No query
    // counts: a plain store has no extended state (StateKey::ext).
    store_unzoomed(fc, fb, r.rgba, p.w, p.h, col_lo[0], row_lo[0]);
    return 0;
  }
  FragInputs in;
  if (r.rgba == nullptr) set_color(in, r.color);
  ShadeInputs si;
  const FragmentProgram* program = nullptr;
  if (fc.shade != nullptr && r.raster != nullptr) {
    raster_shade_inputs(*fc.shade, *r.raster, si);
    in.shade = &si;
    program = fc.shade->program;
  }
  const double fixed_z = clamp01(r.z) * fc.depth_max;
  in.z.v0 = fixed_z;
  for (int m = 0; m < p.h; ++m) {
    const int y0 = row_lo[static_cast<size_t>(m)], y1 = row_hi[static_cast<size_t>(m)];
    if (y0 >= y1 || y1 <= fc.clip_y0 || y0 > fc.clip_y1) continue;
    const size_t row = static_cast<size_t>(m) * static_cast<size_t>(p.w);
    // A run of neighbouring groups with equal fragments: [run_x0, run_x1).
    bool run = false;
    int run_x0 = 0, run_x1 = 0;
    uint8_t run_color[4] = {};
    double run_z = 0.0;
    const auto flush = [&]() {
      if (!run) return;
      run = false;
      if (direct) return store_rect(fc, fb, run_color, run_x0, y0, run_x1, y1);
      std::memcpy(in.const_color, run_color, 4);
      for (int c = 0; c < 4; ++c)
        si.color[c] = static_cast<float>(run_color[c]) * (1.0f / 255.0f);
      // A fragment shader's gl_Color is the group's colour (§3.6.4, §3.11).
      if (program != nullptr)
        for (int i = 0; i < program->input_count; ++i) {
          const int a = program->input_attr[i];
          if (a >= kAttrColor && a < kAttrColor + 4)
            si.prog_w[i] = {si.color[a - kAttrColor], 0, 0};
        }
      in.z.v0 = run_z;
      emit_rect(fc, in, run_x0, y0, run_x1, y1);
    };
    for (int n = 0; n < p.w; ++n) {
      const size_t g = row + static_cast<size_t>(n);
      const int x0 = col_lo[static_cast<size_t>(n)], x1 = col_hi[static_cast<size_t>(n)];
      if (x0 >= x1 || (r.present != nullptr && r.present[g] == 0)) {
        flush();
        continue;
      }
      uint8_t color[4];
      double z = fixed_z;
      if (r.rgba != nullptr) {
        for (int c = 0; c < 4; ++c)
          color[c] = color_to_unorm8(r.rgba[g * 4 + c]);
      } else {
        std::memcpy(color, in.const_color, 4);
        z = clamp01(r.depth[g]) * fc.depth_max;
      }
      if (run && z == run_z && std::memcmp(color, run_color, 4) == 0) {
        if (x0 == run_x1) {
          run_x1 = x1;
          continue;
        }
        if (x1 == run_x0) { // negative zoom: groups go leftwards
          run_x0 = x0;
          continue;
        }
      }
      flush();
      run = true;
      run_x0 = x0;
      run_x1 = x1;
      std::memcpy(run_color, color, 4);
      run_z = z;
    }
    flush();
  }
  return fc.samples_passed;
}

void draw_stencil_rect(const RasterState& rs, const Framebuffer& fb, const PixelPlacement& p,
                       const uint32_t* index, const uint8_t* present) {
  if (fb.stencil == nullptr || p.w <= 0 || p.h <= 0 || !std::isfinite(p.x) || !std::isfinite(p.y))
    return;
  int cx0 = 0, cy0 = 0, cx1 = fb.width, cy1 = fb.height;
  if (rs.scissor_test) {
    cx0 = std::max(cx0, rs.scissor[0]);
    cy0 = std::max(cy0, rs.scissor[1]);
    cx1 = static_cast<int>(std::min<int64_t>(cx1, int64_t{rs.scissor[0]} + rs.scissor[2]));
    cy1 = static_cast<int>(std::min<int64_t>(cy1, int64_t{rs.scissor[1]} + rs.scissor[3]));
  }
  const uint8_t wm = static_cast<uint8_t>(rs.stencil.writemask & 0xffu);
  if (wm == 0) return;
  std::vector<int> col_lo, col_hi, row_lo, row_hi;
  group_spans(p.w, p.col0, p.x, p.zoom_x, col_lo, col_hi);
  group_spans(p.h, p.row0, p.y, p.zoom_y, row_lo, row_hi);
  for (int m = 0; m < p.h; ++m) {
    const int y0 = std::max(row_lo[static_cast<size_t>(m)], cy0);
    const int y1 = std::min(row_hi[static_cast<size_t>(m)], cy1);
    for (int n = 0; n < p.w && y0 < y1; ++n) {
      const size_t g = static_cast<size_t>(m) * static_cast<size_t>(p.w) + static_cast<size_t>(n);
      if (present != nullptr && present[g] == 0) continue;
      const int x0 = std::max(col_lo[static_cast<size_t>(n)], cx0);
      const int x1 = std::min(col_hi[static_cast<size_t>(n)], cx1);
      const uint8_t v = static_cast<uint8_t>(index[g] & 0xffu);
      for (int y = y0; y < y1; ++y) {
        uint8_t* s = fb.stencil + static_cast<ptrdiff_t>(y) * fb.stencil_stride;
        for (int x = x0; x < x1; ++x)
          s[x] = static_cast<uint8_t>((s[x] & ~wm) | (v & wm));
      }
    }
  }
}

uint64_t draw_bitmap(const RasterState& rs, const Framebuffer& fb, int x, int y, int w, int h,
                     const uint8_t* bits, const float color[4], float z, const RasterPos& raster) {
  if (w <= 0 || h <= 0) return 0;
  FragCtx fc;
  prepare_fragments(rs, fb, fc);
  if (fc.noop) return 0;
  const int64_t x0 = std::max<int64_t>(x, fc.clip_x0), y0 = std::max<int64_t>(y, fc.clip_y0);
  const int64_t x1 = std::min<int64_t>(int64_t{x} + w, int64_t{fc.clip_x1} + 1);
  const int64_t y1 = std::min<int64_t>(int64_t{y} + h, int64_t{fc.clip_y1} + 1);
  if (x0 >= x1 || y0 >= y1) return 0;
  FragInputs in;
  set_color(in, color);
  in.z.v0 = clamp01(z) * fc.depth_max;
  ShadeInputs si;
  ShadePath path = ShadePath::Const;
  if (fc.shade != nullptr) {
    raster_shade_inputs(*fc.shade, raster, si);
    for (int c = 0; c < 4; ++c)
      si.color[c] = clamp01(color[c]);
    for (int c = 0; c < 3; ++c)
      si.color2[c] = fc.shade->color_sum ? clamp01(raster.color2[c]) : 0.0f;
    in.shade = &si;
    path = ShadePath::PerFragment;
  }
  const BlockFn fn = fc.fn[static_cast<int>(path)];
  // One block loop call per 8x8 block, its coverage gathered from the bits.
  for (int by = static_cast<int>(y0) & ~(kBlockSize - 1); by < y1; by += kBlockSize) {
    for (int bx = static_cast<int>(x0) & ~(kBlockSize - 1); bx < x1; bx += kBlockSize) {
      uint64_t mask = 0;
      for (int j = 0; j < kBlockSize; ++j) {
        const int py = by + j;
        if (py < y0 || py >= y1) continue;
        const uint8_t* row = bits + static_cast<size_t>(py - y) * static_cast<size_t>(w);
        for (int i = 0; i < kBlockSize; ++i) {
          const int px = bx + i;
          if (px >= x0 && px < x1 && row[px - x] != 0) mask |= uint64_t{1} << (8 * j + i);
        }
      }
      if (mask == 0) continue;
      in.ox = bx;
      in.oy = by;
      fn(fc, in, bx, by, mask);
    }
  }
  return fc.samples_passed;
}

} // namespace pineda
