// The rasterizer's interface: one draw's state, surfaces and rows (DrawCall), and the
// rasterization of one primitive. Primitive assembly (geometry/assemble.h) calls it; the state
// is derived by the state layer (core/raster_state.h) and handed down by the draw home.
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <cstddef>

#include "framebuffer/framebuffer.h"
#include "core/raster_state.h"
#include "raster/workers.h"

namespace pineda {

// Subpixel precision of the rasterizer (GL_SUBPIXEL_BITS, core/limits.h).
constexpr int kSubpixelOne = 1 << kSubpixelBits;

struct FragCtx; // fragment/fragment_ops.h

// One draw: the state, the surfaces, and the primitive mode's vertices.
struct DrawCall {
  const RasterState* state = nullptr;
  Framebuffer* fb = nullptr;
  // The fragment stage's setup for state and fb, made once per draw by draw_primitives. When
  // null (tests calling the rasterizers directly) each primitive makes its own.
  const FragCtx* frag = nullptr;
  // The line stipple counter (GL 2.1 §3.4.2), owned by draw_primitives: primitive assembly
  // resets it for each independent segment, strip, loop and outlined polygon, the line
  // rasterizer advances it. Null: every segment starts at 0.
  float* stipple_counter = nullptr;
  // With RasterState::count_samples, draw_primitives adds the samples that passed here.
  uint64_t* samples_passed = nullptr;
  // The rows this call rasterizes: all, or a worker's share of a draw shared by bands
  // (schedule.h).
  Bands bands;
};

// Rasterize one primitive whose vertices have valid window coordinates inside the guard
// band. `provoking` supplies the colour slots under flat shading (GL 2.1 §2.14.7).
// raster_triangle does not cull; it fills whatever winding it is given.
void raster_triangle(const DrawCall& dc, const PVertex& a, const PVertex& b, const PVertex& c,
                     const PVertex& provoking, bool back_facing);
// `back_facing`: the line or point outlines a back-facing polygon (polygon mode LINE or
// POINT), whose fragments take the back face's stencil state (GL 2.1 §4.1.5).
void raster_line(const DrawCall& dc, const PVertex& a, const PVertex& b, const PVertex& provoking,
                 bool back_facing = false);
void raster_point(const DrawCall& dc, const PVertex& p, bool back_facing = false);

// Fixed-point window coordinate as the rasterizer and the culling test both see it:
// round to nearest 1/256 pixel.
inline int32_t to_fixed(float win) {
  const float s = win * static_cast<float>(kSubpixelOne);
  return static_cast<int32_t>(s >= 0.0f ? s + 0.5f : s - 0.5f);
}

// Twice the signed area of the fixed-point triangle (counter-clockwise positive in GL's
// lower-left-origin window space), in 1/65536 pixel^2 units.
inline int64_t fixed_area2(const PVertex& a, const PVertex& b, const PVertex& c) {
  const int64_t ax = to_fixed(a.win[0]), ay = to_fixed(a.win[1]);
  const int64_t bx = to_fixed(b.win[0]), by = to_fixed(b.win[1]);
  const int64_t cx = to_fixed(c.win[0]), cy = to_fixed(c.win[1]);
  return (bx - ax) * (cy - ay) - (cx - ax) * (by - ay);
}

} // namespace pineda
