// Fragments of pixel rectangles and bitmaps (GL 2.1 §3.6.4 "Conversion to Fragments", §3.7,
// §4.3.1): the groups, already through the pixel transfer operations, become fragments that
// go through the per-fragment operations of the fragment stage (fragment_ops.h), or for
// stencil indices straight into the stencil buffer.
#pragma once

#include <cstdint>

#include "framebuffer/framebuffer.h"
#include "pixel/raster_pos.h"
#include "raster/raster.h"

namespace pineda {

// Where a w x h rectangle of groups lands: group (n, m) covers the window rectangle with
// corners (x + zoom_x n, y + zoom_y m) and (x + zoom_x (n + 1), y + zoom_y (m + 1)); a pixel
// belongs to it when its centre is inside or on its bottom or left edge (§3.6.4).
// A sub-rectangle of a larger one starts at group (col0, row0) of it.
struct PixelPlacement {
  int w = 0, h = 0;
  int64_t col0 = 0, row0 = 0;
  float x = 0.0f, y = 0.0f; // the current raster position
  float zoom_x = 1.0f, zoom_y = 1.0f;
};

// A colour or depth rectangle. Exactly one of rgba (w h RGBA groups) and depth (w h values)
// is set; the other part of each fragment comes from the raster position: colour groups take
// `z`, depth groups take `color` (§3.6.4). `present`, when set, marks the groups that exist
// (CopyPixels from outside the window); absent groups make no fragments.
struct PixelRect {
  PixelPlacement place;
  const float* rgba = nullptr;
  const float* depth = nullptr;
  const uint8_t* present = nullptr;
  float color[4] = {0, 0, 0, 0};
  float z = 0.0f;
  // While texturing or fog is on (RasterState::shade), the fragments take the texture
  // coordinates and fog distance of this raster position (§3.6.4 "Conversion to Fragments")
  // and go through texturing and fog like a primitive's (§3.8, §3.10); no colour sum, as in
  // llvmpipe. Null: no shading.
  const RasterPos* raster = nullptr;
};

// Colour values are clamped to [0, 1] and depth values too before they become fragments
// (§3.6.4 "Final Conversion"). Returns the fragments that passed the depth and stencil
// tests when rs.count_samples is set (occlusion queries count pixel fragments too, GL 2.1
// §4.1.7), else 0.
uint64_t draw_pixel_rect(const RasterState& rs, const Framebuffer& fb, const PixelRect& r);

// §4.3.1: stencil indices written with only the pixel ownership and scissor tests and the
// stencil write mask; indices are masked to the buffer's 8 bits.
void draw_stencil_rect(const RasterState& rs, const Framebuffer& fb, const PixelPlacement& p,
                       const uint32_t* index, const uint8_t* present);

// §3.7: fragments where bits[j * w + i] is non-zero, lower left corner at (x, y), all with
// the raster position's colour and window z. While texturing or fog is on they are shaded
// with `raster`'s texture coordinates, secondary colour (colour sum) and fog distance, as
// PixelRect::raster says. Returns the samples passed, as draw_pixel_rect.
uint64_t draw_bitmap(const RasterState& rs, const Framebuffer& fb, int x, int y, int w, int h,
                     const uint8_t* bits, const float color[4], float z, const RasterPos& raster);

} // namespace pineda
