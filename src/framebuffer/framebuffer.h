// The surfaces one context draws into. The window-system layer (OSMesa, GLX) owns the memory;
// the pipeline only sees this plain description. Row 0 is the bottom row (GL window origin);
// a top-down user buffer is described with a negative stride.
#pragma once

#include <cstddef>
#include <cstdint>

namespace pineda {

// Byte order of a colour pixel in memory. Every format is 8 bits per channel.
enum class ColorFormat : uint8_t {
  RGBA8, // bytes R,G,B,A
  BGRA8, // bytes B,G,R,A
  ARGB8, // bytes A,R,G,B
  RGB8,  // bytes R,G,B (3 bytes per pixel, alpha reads as 255)
};

inline int bytes_per_pixel(ColorFormat f) { return f == ColorFormat::RGB8 ? 3 : 4; }

struct Framebuffer {
  int width = 0;
  int height = 0;

  ColorFormat color_format = ColorFormat::RGBA8;
  uint8_t* color = nullptr;    // address of pixel (0,0), the bottom-left one
  ptrdiff_t color_stride = 0;  // bytes from row y to row y+1 (negative for top-down memory)
  int alpha_bits = 8;          // 0 for formats without alpha (RGB8)

  uint32_t* depth = nullptr;   // width*height values, row 0 at the bottom, stride = width
  int depth_bits = 0;          // 0 (no depth buffer), 16, 24 or 32; values in [0, 2^bits - 1]

  uint8_t* stencil = nullptr;  // width*height, row 0 at the bottom, stride = width
  int stencil_bits = 0;        // 0 or 8

  // Accumulation buffer (GL 2.1 §4.2.4): RGBA, each a signed 16-bit fixed-point value
  // v / 32767 as Mesa stores it; width*4 values per row, row 0 at the bottom.
  int16_t* accum = nullptr;
  int accum_bits = 0; // 0 (none) or 16

  // A drawable with a front and a back colour buffer (a double-buffered GLX window, GL 2.1
  // table 4.4): both use color_format and color_stride. nullptr for a single colour buffer,
  // which is then `color` alone. draw_read_buffer.cpp points `color` at the buffer drawing
  // writes (the back one when both are drawn), `color_also` at the second buffer of
  // FRONT_AND_BACK (else nullptr) and `read_color` at the read buffer (§4.3.2).
  uint8_t* front_color = nullptr;
  uint8_t* back_color = nullptr;
  uint8_t* color_also = nullptr;
  uint8_t* read_color = nullptr;

  uint8_t* color_row(int y) const { return color + static_cast<ptrdiff_t>(y) * color_stride; }
  uint32_t depth_max() const {
    return depth_bits >= 32 ? 0xffffffffu : ((1u << depth_bits) - 1u);
  }
};

// The framebuffer as seen by commands that read colour (ReadPixels, CopyPixels,
// CopyTexImage, Accum): its colour is the read buffer.
inline Framebuffer read_view(const Framebuffer& fb) {
  Framebuffer r = fb;
  if (fb.read_color != nullptr) r.color = fb.read_color;
  r.color_also = nullptr;
  return r;
}

} // namespace pineda
