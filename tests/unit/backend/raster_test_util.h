// Helpers for the rasterizer and fragment tests: a small owned framebuffer, vertices, and an
// independent brute-force coverage reference.
#pragma once

#include <array>
#include <cstdint>
#include <cstring>
#include <vector>

#include "framebuffer/framebuffer.h"
#include "raster/raster.h"

namespace pineda::test {

struct TestFb {
  std::vector<uint8_t> color_mem;
  std::vector<uint32_t> depth_mem;
  std::vector<uint8_t> stencil_mem;
  Framebuffer fb;

  TestFb(int w, int h, ColorFormat fmt = ColorFormat::RGBA8, int depth_bits = 24,
         bool top_down = false) {
    fb.width = w;
    fb.height = h;
    fb.color_format = fmt;
    fb.alpha_bits = fmt == ColorFormat::RGB8 ? 0 : 8;
    const int bpp = bytes_per_pixel(fmt);
    color_mem.assign(static_cast<size_t>(w) * h * bpp, 0);
    const ptrdiff_t row = static_cast<ptrdiff_t>(w) * bpp;
    if (top_down) {
      // Memory row 0 is the top of the image: GL row 0 is the last memory row.
      fb.color = color_mem.data() + (h - 1) * row;
      fb.color_stride = -row;
    } else {
      fb.color = color_mem.data();
      fb.color_stride = row;
    }
    if (depth_bits > 0) {
      depth_mem.assign(static_cast<size_t>(w) * h, fb_depth_max(depth_bits));
      fb.depth = depth_mem.data();
      fb.depth_bits = depth_bits;
      fb.depth_stride = w;
    }
    stencil_mem.assign(static_cast<size_t>(w) * h, 0);
    fb.stencil = stencil_mem.data();
    fb.stencil_bits = 8;
    fb.stencil_stride = w;
  }

  static uint32_t fb_depth_max(int bits) { return bits >= 32 ? 0xffffffffu : (1u << bits) - 1; }

  uint8_t* pixel(int x, int y) {
    return fb.color_row(y) + static_cast<ptrdiff_t>(x) * bytes_per_pixel(fb.color_format);
  }
  // R, G, B, A of a pixel (alpha 255 for RGB8).
  std::array<uint8_t, 4> rgba(int x, int y) {
    const uint8_t* p = pixel(x, y);
    switch (fb.color_format) {
    case ColorFormat::RGBA8:
      return {p[0], p[1], p[2], p[3]};
    case ColorFormat::BGRA8:
      return {p[2], p[1], p[0], p[3]};
    case ColorFormat::ARGB8:
      return {p[1], p[2], p[3], p[0]};
    case ColorFormat::RGB8:
      return {p[0], p[1], p[2], 255};
    }
    return {0, 0, 0, 0};
  }
  uint32_t depth(int x, int y) const { return depth_mem[static_cast<size_t>(y) * fb.width + x]; }
  void fill_color(uint8_t v) { std::memset(color_mem.data(), v, color_mem.size()); }
};

inline PVertex vtx(float x, float y, float z = 0.5f, float inv_w = 1.0f,
                   std::array<float, 4> c = {1, 1, 1, 1}) {
  PVertex v{};
  v.win[0] = x;
  v.win[1] = y;
  v.win[2] = z;
  v.win[3] = inv_w;
  v.clip[3] = 1.0f / inv_w;
  for (int k = 0; k < 4; ++k)
    v.attr[kAttrColor + k] = c[k];
  return v;
}

// Additive counting: each fragment adds 1 to red (ONE, ONE, FUNC_ADD with colour 1/255).
inline RasterState counting_state() {
  RasterState rs;
  rs.blend = true;
  rs.blend_state.src_rgb = rs.blend_state.src_a = GL_ONE;
  rs.blend_state.dst_rgb = rs.blend_state.dst_a = GL_ONE;
  return rs;
}
constexpr std::array<float, 4> kCountColor = {1.0f / 255.0f, 0, 0, 0};

// Independent reference: pixel (px, py) is covered when its centre is strictly inside the
// snapped triangle, or on an edge that owns it (a counter-clockwise edge going down, or
// going right when horizontal: interior at +x or above).
inline bool ref_covers(const int64_t x[3], const int64_t y[3], int px, int py) {
  const int64_t area = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
  if (area == 0) return false;
  const int o[3] = {0, area > 0 ? 1 : 2, area > 0 ? 2 : 1};
  const int64_t cx = int64_t{px} * 256 + 128, cy = int64_t{py} * 256 + 128;
  for (int i = 0; i < 3; ++i) {
    const int64_t x0 = x[o[i]], y0 = y[o[i]], x1 = x[o[(i + 1) % 3]], y1 = y[o[(i + 1) % 3]];
    const int64_t cross = (x1 - x0) * (cy - y0) - (y1 - y0) * (cx - x0);
    const bool owner = y1 < y0 || (y1 == y0 && x1 > x0);
    if (cross < 0 || (cross == 0 && !owner)) return false;
  }
  return true;
}

} // namespace pineda::test
