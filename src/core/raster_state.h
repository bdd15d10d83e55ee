// The back end's state: everything the rasterizer and the fragment stage read, derived from
// the GL state by the state layer's validation (state/raster_state.cpp) and handed down as
// plain data, never the Context. At the bottom of the layers with the processed vertex
// (core/vertex.h) and the implementation limits (core/limits.h).
#pragma once

#include <GL/gl.h>

#include <cstdint>

#include "core/limits.h"
#include "core/vertex.h"

namespace pineda {

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

// The back end's view of the rasterization modes of GL 2.1 §3.3 (points), §3.4 (lines) and
// §3.5 (polygon stipple and offset). The defaults reproduce the plain 1-pixel rasterization, so
// the paths that read these fields cost nothing when the modes are off.
struct RasterModes {
  // Lines (GL 2.1 §3.4).
  float line_width = 1.0f; // glLineWidth, clamped to [1, kMaxLineWidth]
  bool line_smooth = false;
  bool line_stipple = false;
  int line_stipple_factor = 1;            // 1..256
  uint16_t line_stipple_pattern = 0xffff; // bit 0 first

  // Points (GL 2.1 §3.3, GL 1.4 point parameters).
  float point_size = 1.0f;
  bool point_smooth = false;
  // The distance attenuation differs from (1, 0, 0): the geometry stage then derives a size per
  // vertex (PVertex::point_size); otherwise every point has point_size clamped to the limits.
  bool point_attenuated = false;
  float point_size_min = 0.0f;
  float point_size_max = kMaxPointSize;
  float point_fade_threshold = 1.0f;
  float point_attenuation[3] = {1.0f, 0.0f, 0.0f};
  // Point sprites (GL 2.1 §3.3.1): squares of the unrounded size, point_smooth ignored; the
  // texture coordinates of the units in sprite_coord_replace (bit u: unit u) vary across the
  // square, t upwards when sprite_lower_left (POINT_SPRITE_COORD_ORIGIN LOWER_LEFT).
  bool point_sprite = false;
  bool sprite_lower_left = false;
  uint8_t sprite_coord_replace = 0;

  // Polygons (GL 2.1 §3.5.5 offset, §3.5.2 stipple). Row r of the stipple applies to window
  // rows y with y mod 32 == r; bit c of a row to window columns x with x mod 32 == c.
  bool polygon_stipple = false;
  uint32_t polygon_stipple_rows[32] = {};
  bool offset_point = false, offset_line = false, offset_fill = false;
  float offset_factor = 0.0f;
  float offset_units = 0.0f;
  // The minimum resolvable difference of the depth buffer in window z, 1 / (2^bits - 1).
  double depth_mrd = 1.0 / 16777215.0;
};

// GL 2.1 §3.5.5: the polygon offset o = m * factor + r * units, here in depth-buffer units for a
// plane with slopes (dzdx, dzdy) also in depth-buffer units per pixel. m is max(|dzdx|,
// |dzdy|), which the spec allows in place of the gradient's length, and r is two depth-buffer
// steps: llvmpipe scales units by twice its minimum resolvable difference (where the spec
// would use one step).
inline double polygon_offset_depth(const RasterModes& m, double dzdx, double dzdy,
                                   double depth_max) {
  const double ax = dzdx < 0 ? -dzdx : dzdx, ay = dzdy < 0 ? -dzdy : dzdy;
  return m.offset_factor * (ax > ay ? ax : ay) + 2.0 * m.offset_units * (depth_max * m.depth_mrd);
}

// Blending (GL 2.1 §4.1.8): the factors, equations and constant colour, as the colour-buffer
// group keeps them (state/fragment_state.h) and the fragment stage reads them.
struct BlendState {
  GLenum src_rgb = GL_ONE, dst_rgb = GL_ZERO;
  GLenum src_a = GL_ONE, dst_a = GL_ZERO;
  GLenum eq_rgb = GL_FUNC_ADD, eq_a = GL_FUNC_ADD;
  float color[4] = {0, 0, 0, 0}; // BLEND_COLOR, clamped to [0,1] when specified
};

// The stencil test and operations of one face (GL 2.1 §4.1.5) and its write mask (§4.2.2), as
// the stencil-buffer group keeps them (state/fragment_state.h) and the fragment stage reads
// them.
struct StencilFace {
  GLenum func = GL_ALWAYS;
  int ref = 0; // as given; clamped to the buffer's range when used (§4.1.5)
  uint32_t value_mask = 0xffffffffu;
  GLenum fail = GL_KEEP, depth_fail = GL_KEEP, depth_pass = GL_KEEP;
  uint32_t writemask = 0xffffffffu; // glStencilMask (§4.2.2)
};

struct ShadeSetup; // fragment/shade.h

// Everything the back end needs, derived from GL state by the front end's validation step.
// Plain data: no pointers into the context.
struct RasterState {
  Viewport viewport;

  // Clipping (GL 2.1 §2.12): user planes already transformed to clip space, so the test is
  // dot(plane, clip) >= 0 for inside.
  uint32_t user_clip_mask = 0; // bit i: plane i enabled
  float user_planes[6][4] = {};
  // With a vertex shader (GL 2.1 §2.20.3): user_planes are the eye-space planes and each
  // vertex carries its distances at attr[user_dist + i] (geometry/clip.h); -1 otherwise.
  int user_dist = -1;

  // Polygons (GL 2.1 §3.5)
  bool cull_enabled = false;
  GLenum cull_face = GL_BACK;                  // GL_FRONT, GL_BACK, GL_FRONT_AND_BACK
  GLenum front_face = GL_CCW;                  // GL_CW, GL_CCW
  GLenum polygon_mode[2] = {GL_FILL, GL_FILL}; // [0] front, [1] back

  // Shading
  bool flat = false;      // GL_FLAT: colour slots take the provoking vertex's value
  bool two_sided = false; // back-facing polygons read kAttrBackColor/kAttrBackColor2
  int attr_count = 4;     // leading PVertex::attr floats that are live (clipped, interpolated)

  // Per-fragment operations (GL 2.1 §4.1), in pipeline order.
  bool scissor_test = false;
  int scissor[4] = {0, 0, 0, 0}; // glScissor x, y, width, height (§4.1.2)

  bool alpha_test = false;
  GLenum alpha_func = GL_ALWAYS;
  float alpha_ref = 0.0f; // clamped to [0,1] by glAlphaFunc (§4.1.4)

  bool stencil_test = false;
  // GL 2.1 §4.1.5: back-facing polygons (also drawn as points or lines by the polygon mode)
  // use the back face's state; every other fragment the front face's.
  StencilFace stencil;      // front
  StencilFace stencil_back; // back

  bool depth_test = false;
  GLenum depth_func = GL_LESS;
  bool depth_write = true;
  bool color_write[4] = {true, true, true, true}; // glColorMask R,G,B,A

  bool blend = false;
  BlendState blend_state;

  // GL 2.1 §4.1.10: with the colour logic operation on, blending is off whatever BLEND says.
  bool logic_op = false;
  GLenum logic_op_mode = GL_COPY;

  // ---- texturing, colour sum and fog (src/fragment/shade.h, src/state/validate_texpipe.cpp) ----
  // Set while texturing or fog is on: primitives are then shaded per fragment. Derived state
  // owned by the context, valid while the draw runs.
  const ShadeSetup* shade = nullptr;
  // Wide, stippled and smooth lines and points, polygon stipple and offset (GL 2.1 §3.3-§3.5).
  RasterModes modes;
  // Occlusion queries (GL 2.1 §4.1.7, src/state/query.cpp): a SAMPLES_PASSED query is
  // active, so the fragment stage counts the fragments that pass the depth and stencil tests.
  bool count_samples = false;
};

} // namespace pineda
