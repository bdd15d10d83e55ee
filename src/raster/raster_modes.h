// The back end's view of the rasterization modes of GL 2.1 §3.3 (points), §3.4 (lines) and
// §3.5 (polygon stipple and offset): plain data derived by validate.cpp from the context's
// RasterModeState (src/state/raster_mode_state.h). The defaults reproduce the plain 1-pixel
// rasterization, so the paths that read these fields cost nothing when the modes are off.
#pragma once

#include <cstdint>

namespace pineda {

// Implementation limits, as Mesa llvmpipe reports them (ALIASED_/POINT_SIZE_RANGE,
// ALIASED_/LINE_WIDTH_RANGE and the granularities, GL 2.1 Table 6.36).
constexpr float kMaxPointSize = 255.0f;
constexpr float kMaxLineWidth = 255.0f;
constexpr float kSizeGranularity = 0.1f;

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

} // namespace pineda
