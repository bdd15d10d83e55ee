// GL state of the rasterization modes (GL 2.1 §3.3-§3.5, Table 6.14) that
// src/state/raster_modes.cpp owns: line stipple and smoothing, point parameters and smoothing,
// polygon stipple, smoothing and offset. Point size and line width stay in Context (point_size,
// line_width).
#pragma once

#include <GL/gl.h>

#include <cstdint>

namespace pineda {

struct RasterModeState {
  bool line_smooth = false;
  bool line_stipple = false;
  GLint line_stipple_repeat = 1; // clamped to [1, 256] (§3.4.2)
  GLushort line_stipple_pattern = 0xffff;

  bool point_smooth = false;
  float point_size_min = 0.0f;
  float point_size_max = 255.0f; // the largest size supported (Table 6.14's initial value)
  float point_fade_threshold = 1.0f;
  float point_attenuation[3] = {1.0f, 0.0f, 0.0f};

  bool polygon_smooth = false;
  bool polygon_stipple = false;
  // Row r (bottom first) of the 32x32 stipple; bit c is column c. Initially all ones (§3.5.2).
  uint32_t polygon_stipple_rows[32] = {
      0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu,
      0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu,
      0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu,
      0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu,
      0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu};
  bool offset_point = false, offset_line = false, offset_fill = false;
  float offset_factor = 0.0f;
  float offset_units = 0.0f;
};

// What glPushAttrib saves of it (with the point size and line width): a copy, restored per group.
struct RasterModeAttrib {
  RasterModeState s;
  float point_size = 1.0f;
  float line_width = 1.0f;
};

} // namespace pineda
