// The back end's interface: the front end derives a RasterState from GL state at draw time
// (validate.cpp), transforms vertices into PVertex arrays, and calls draw_primitives. Everything
// from primitive assembly to the framebuffer lives behind this header.
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <cstddef>

#include "framebuffer/framebuffer.h"
#include "geometry/vertex.h"
#include "raster/raster_modes.h"
#include "raster/workers.h"

namespace pineda {

// Subpixel precision of the rasterizer (GL_SUBPIXEL_BITS).
constexpr int kSubpixelBits = 8;
constexpr int kSubpixelOne = 1 << kSubpixelBits;

// Window x and y handed to the rasterizer stay within +-kGuardBand pixels; primitives
// reaching further are clipped against guard-band planes first (kClipGuard), so fixed-point
// coordinates fit 24 bits and edge-function products fit 64 bits.
constexpr float kGuardBand = 16384.0f;

struct Viewport {
  float x = 0, y = 0, w = 0, h = 0; // glViewport, in pixels
  float near = 0, far = 1;          // glDepthRange, clamped to [0,1]
};

// Clip coordinates to window coordinates (GL 2.1 §2.11.1): perspective divide, viewport,
// depth range. Used by the geometry stage for unclipped vertices and by the clipper for the
// vertices it makes, so both agree to the bit.
inline void to_window(PVertex& v, const Viewport& vp) {
  const float inv_w = 1.0f / v.clip[3];
  const float xd = v.clip[0] * inv_w, yd = v.clip[1] * inv_w, zd = v.clip[2] * inv_w;
  v.win[0] = vp.x + (xd + 1.0f) * 0.5f * vp.w;
  v.win[1] = vp.y + (yd + 1.0f) * 0.5f * vp.h;
  v.win[2] = vp.near + (zd + 1.0f) * 0.5f * (vp.far - vp.near);
  v.win[3] = inv_w;
}

struct ShadeSetup; // fragment/shade.h

// Everything the back end needs, derived from GL state by the front end's validation step.
// Plain data: no pointers into the context.
struct RasterState {
  Viewport viewport;

  // Clipping (GL 2.1 §2.12): user planes already transformed to clip space, so the test is
  // dot(plane, clip) >= 0 for inside.
  uint32_t user_clip_mask = 0; // bit i: plane i enabled
  float user_planes[6][4] = {};

  // Polygons (GL 2.1 §3.5)
  bool cull_enabled = false;
  GLenum cull_face = GL_BACK;    // GL_FRONT, GL_BACK, GL_FRONT_AND_BACK
  GLenum front_face = GL_CCW;    // GL_CW, GL_CCW
  GLenum polygon_mode[2] = {GL_FILL, GL_FILL}; // [0] front, [1] back

  // Shading
  bool flat = false;     // GL_FLAT: colour slots take the provoking vertex's value
  bool two_sided = false; // back-facing polygons read kAttrBackColor/kAttrBackColor2
  int attr_count = 4;    // leading PVertex::attr floats that are live (clipped, interpolated)

  // Per-fragment operations (GL 2.1 §4.1), in pipeline order.
  bool scissor_test = false;
  int scissor[4] = {0, 0, 0, 0}; // glScissor x, y, width, height (§4.1.2)

  bool alpha_test = false;
  GLenum alpha_func = GL_ALWAYS;
  float alpha_ref = 0.0f; // clamped to [0,1] by glAlphaFunc (§4.1.4)

  bool stencil_test = false;
  GLenum stencil_func = GL_ALWAYS;
  int stencil_ref = 0; // as given; clamped to the buffer's range when used (§4.1.5)
  uint32_t stencil_value_mask = 0xffffffffu;
  GLenum stencil_fail = GL_KEEP, stencil_depth_fail = GL_KEEP, stencil_depth_pass = GL_KEEP;
  uint32_t stencil_writemask = 0xffffffffu; // glStencilMask (§4.2.2)

  bool depth_test = false;
  GLenum depth_func = GL_LESS;
  bool depth_write = true;
  bool color_write[4] = {true, true, true, true}; // glColorMask R,G,B,A

  bool blend = false;
  GLenum blend_src_rgb = GL_ONE, blend_dst_rgb = GL_ZERO;
  GLenum blend_src_a = GL_ONE, blend_dst_a = GL_ZERO;
  GLenum blend_eq_rgb = GL_FUNC_ADD, blend_eq_a = GL_FUNC_ADD;
  float blend_color[4] = {0, 0, 0, 0};

  // GL 2.1 §4.1.10: with the colour logic operation on, blending is off whatever BLEND says.
  bool logic_op = false;
  GLenum logic_op_mode = GL_COPY;

  // ---- texturing, colour sum and fog (src/fragment/shade.h, src/state/validate_texpipe.cpp) ----
  // Set while texturing or fog is on: primitives are then shaded per fragment. Derived state
  // owned by the context, valid while the draw runs.
  const ShadeSetup* shade = nullptr;
  // Wide, stippled and smooth lines and points, polygon stipple and offset (GL 2.1 §3.3-§3.5;
  // src/state/raster_modes.cpp derives them).
  RasterModes modes;
  // Occlusion queries (GL 2.1 §4.1.7, src/state/query.cpp): a SAMPLES_PASSED query is
  // active, so the fragment stage counts the fragments that pass the depth and stencil tests.
  bool count_samples = false;
};

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
  // The context's worker threads (workers.h): draw_primitives shares a large draw among them.
  // Null: the calling thread draws everything.
  RasterWorkers* workers = nullptr;
  // The rows this call rasterizes; draw_primitives sets it for each worker's share.
  Bands bands;
};

// Primitive assembly, clipping, culling and rasterization of `count` vertices in `mode`
// (GL_POINTS .. GL_POLYGON). With indices == nullptr the vertices are taken in order
// verts[0..count); otherwise verts[indices[i]]. Incomplete primitives are ignored (GL 2.1 §2.6.1).
void draw_primitives(const DrawCall& dc, GLenum mode, const PVertex* verts,
                     const uint32_t* indices, size_t count);

// Rasterize one primitive whose vertices have valid window coordinates inside the guard
// band. `provoking` supplies the colour slots under flat shading (GL 2.1 §2.14.7).
// raster_triangle does not cull; it fills whatever winding it is given.
void raster_triangle(const DrawCall& dc, const PVertex& a, const PVertex& b, const PVertex& c,
                     const PVertex& provoking, bool back_facing);
void raster_line(const DrawCall& dc, const PVertex& a, const PVertex& b, const PVertex& provoking);
void raster_point(const DrawCall& dc, const PVertex& p);

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

// Framebuffer clears (glClear), honouring the colour mask / depth mask / stencil mask.
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
// A large clear is split over `workers` when given.
void clear_buffers(Framebuffer& fb, const ClearState& cs, GLbitfield mask,
                   RasterWorkers* workers = nullptr);

} // namespace pineda
