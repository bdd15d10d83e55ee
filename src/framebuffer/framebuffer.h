// The surfaces one context draws into. The window-system layer (OSMesa, GLX) owns the memory;
// the pipeline only sees this plain description. Row 0 is the bottom row (GL window origin);
// a top-down user buffer is described with a negative stride.
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/limits.h"

namespace pineda {

// Byte order of a colour pixel in memory. Every format is 8 bits per channel.
enum class ColorFormat : uint8_t {
  RGBA8, // bytes R,G,B,A
  BGRA8, // bytes B,G,R,A
  ARGB8, // bytes A,R,G,B
  RGB8,  // bytes R,G,B (3 bytes per pixel, alpha reads as 255)
};

inline int bytes_per_pixel(ColorFormat f) {
  return f == ColorFormat::RGB8 ? 3 : 4;
}

// A colour buffer drawing writes besides the primary one (GL 2.0 §4.2.1: DrawBuffers, or
// FRONT_AND_BACK of a double-buffered window), laid out in the framebuffer's colour format.
struct ColorTarget {
  uint8_t* data = nullptr; // pixel (0,0)
  ptrdiff_t stride = 0;    // bytes from row y to row y+1
  int alpha_bits = 8;
  int output = 0; // the draw buffer i (DRAW_BUFFERi) it is: gl_FragData[i] goes to it
};

// A window's buffers (the window-system layer owns the memory) or the images attached to a
// framebuffer object (ARB_framebuffer_object), as the back end sees them: plain memory.
struct Framebuffer {
  int width = 0;
  int height = 0;

  ColorFormat color_format = ColorFormat::RGBA8;
  uint8_t* color = nullptr;   // address of pixel (0,0), the bottom-left one
  ptrdiff_t color_stride = 0; // bytes from row y to row y+1 (negative for top-down memory)
  int alpha_bits = 8;         // 0 for formats without alpha (RGB8)
  int color_output = 0;       // the draw buffer i `color` is (ColorTarget::output)

  uint32_t* depth = nullptr; // row 0 at the bottom, depth_stride values a row
  int depth_bits = 0;        // 0 (no depth buffer), 16, 24 or 32; values in [0, 2^bits - 1]
  int depth_stride = 0;      // values from row y to row y+1 (>= width)

  uint8_t* stencil = nullptr; // row 0 at the bottom, stencil_stride values a row
  int stencil_bits = 0;       // 0 or 8
  int stencil_stride = 0;

  // Accumulation buffer (GL 2.1 §4.2.4): RGBA, each a signed 16-bit fixed-point value
  // v / 32767 as Mesa stores it; width*4 values per row, row 0 at the bottom.
  int16_t* accum = nullptr;
  int accum_bits = 0; // 0 (none) or 16

  // The further colour buffers drawing writes (DrawBuffers, FRONT_AND_BACK), each drawn in a
  // pass of its own after the primary `color` (draw/draw_buffers.h).
  ColorTarget more[kMaxDrawBuffers - 1];
  int more_count = 0;

  // A window with a front and a back colour buffer (a double-buffered GLX window, GL 2.1
  // table 4.4): both use color_format and color_stride. nullptr for a single colour buffer.
  // framebuffer_object.cpp points `color` and `more` at the buffers DRAW_BUFFERi name.
  uint8_t* front_color = nullptr;
  uint8_t* back_color = nullptr;

  uint8_t* color_row(int y) const { return color + static_cast<ptrdiff_t>(y) * color_stride; }
  uint32_t depth_max() const { return depth_bits >= 32 ? 0xffffffffu : ((1u << depth_bits) - 1u); }
  // A framebuffer to draw into or read from is there (a bound window, or a framebuffer
  // object with an image); its colour may still be absent (draw buffer NONE, depth only).
  bool present() const { return width > 0 && height > 0; }
  // The framebuffer with its colour buffer `t` as the primary one and no other.
  Framebuffer with_color(const ColorTarget& t) const {
    Framebuffer f = *this;
    f.color = t.data;
    f.color_stride = t.stride;
    f.alpha_bits = t.alpha_bits;
    f.color_output = t.output;
    f.more_count = 0;
    return f;
  }
};

} // namespace pineda
