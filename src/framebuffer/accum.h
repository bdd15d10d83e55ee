// The accumulation buffer's arithmetic (GL 2.1 §4.2.4) on the Framebuffer's 16-bit signed
// fixed-point RGBA values (v / 32767), with Mesa's conversions, so that results match
// llvmpipe's value for value.
#pragma once

#include <GL/gl.h>

#include <cstdint>

#include "framebuffer/framebuffer.h"

namespace pineda {

// A half-open pixel rectangle [x0, x1) x [y0, y1) inside the framebuffer.
struct AccumRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

// float to the stored value as Mesa converts clear values: (trunc(65535 c) - 1) / 2,
// truncating; c is in [-1, 1].
int16_t accum_clear_value(float c);

// Fill `r` with the clear colour `c` (each in [-1, 1]).
void accum_fill(Framebuffer& fb, const float c[4], const AccumRect& r);

// glAccum(op, value) over `r`: ACCUM and LOAD read the colour buffer, RETURN writes it
// through `color_write` (GL 2.1 §4.2.2 colour mask), MULT and ADD touch only the
// accumulation buffer. `op` must be one of the five.
void accum_apply(Framebuffer& fb, GLenum op, float value, const AccumRect& r,
                 const bool color_write[4]);

} // namespace pineda
