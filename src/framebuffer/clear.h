// Framebuffer clears (glClear, GL 2.1 §4.2.3) of the colour, depth and stencil surfaces,
// honouring the colour, depth and stencil write masks (§4.2.2) and the scissor box.
#pragma once

#include <GL/gl.h>

#include <cstdint>

#include "framebuffer/framebuffer.h"

namespace pineda {

// What a clear writes, derived from the GL state by glClear (state/buffers.cpp).
struct ClearState {
  float color[4] = {0, 0, 0, 0};
  double depth = 1.0;
  int stencil = 0;
  bool color_write[4] = {true, true, true, true};
  bool depth_write = true;
  uint32_t stencil_writemask = 0xffffffffu;
  // GL 2.1 §4.2.3: the scissor test applies to clears.
  bool scissor_test = false;
  int scissor[4] = {0, 0, 0, 0};
};

// A rectangle of pixels, half-open: [x0, x1) x [y0, y1).
struct ClearRect {
  int x0, y0, x1, y1;
  int w() const { return x1 - x0; }
  int h() const { return y1 - y0; }
};

// The rectangle a clear writes: the whole framebuffer, narrowed by the scissor box when the
// scissor test is on.
ClearRect clear_rect(const Framebuffer& fb, const ClearState& cs);

// Clears the buffers of `mask` within `r` (a part of clear_rect: a large clear's rows are
// shared among the worker threads, raster/schedule.h; each pixel is written once).
void clear_buffers(Framebuffer& fb, const ClearState& cs, GLbitfield mask, const ClearRect& r);

// The whole clear on the calling thread.
inline void clear_buffers(Framebuffer& fb, const ClearState& cs, GLbitfield mask) {
  clear_buffers(fb, cs, mask, clear_rect(fb, cs));
}

} // namespace pineda
