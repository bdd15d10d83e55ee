// Rasterization state (GL 2.1 §3.3 points, §3.4 lines, §3.5 polygons; Tables 6.12-6.14
// "Rasterization", the "point", "line", "polygon" and "polygon-stipple" attribute groups).
// Commands in raster_modes.cpp (points, lines, stipples, offset) and polygon.cpp (CullFace,
// FrontFace, PolygonMode); the back end sees RasterModes (core/raster_state.h), derived in
// state/raster_state.cpp.
#pragma once

#include <GL/gl.h>

#include <cstdint>

#include "core/limits.h"

namespace pineda {

struct StateArea;

// POINT_BIT: Table 6.12 (POINT_SMOOTH is also "enable").
struct PointGroup {
  float size = 1.0f;
  bool smooth = false;
  float size_min = 0.0f;
  float size_max = kMaxPointSize; // the largest size supported (Table 6.12's initial value)
  float fade_threshold = 1.0f;
  float attenuation[3] = {1.0f, 0.0f, 0.0f}; // POINT_DISTANCE_ATTENUATION
  // Point sprites (GL 2.1 §3.3, Table 6.12; POINT_SPRITE is also "enable"): COORD_REPLACE of
  // each texture unit (set with TexEnv, texenv.cpp) and POINT_SPRITE_COORD_ORIGIN.
  bool sprite = false;
  bool coord_replace[kMaxTexUnits] = {};
  GLenum sprite_origin = GL_UPPER_LEFT;
};

// LINE_BIT: Table 6.13 (LINE_SMOOTH and LINE_STIPPLE are also "enable").
struct LineGroup {
  float width = 1.0f;
  bool smooth = false;
  bool stipple = false;
  GLint stipple_repeat = 1; // clamped to [1, 256] (§3.4.2)
  GLushort stipple_pattern = 0xffff;
};

// POLYGON_BIT: Table 6.14 (CULL_FACE, POLYGON_SMOOTH, POLYGON_STIPPLE and the
// POLYGON_OFFSET_* enables are also "enable").
struct PolygonGroup {
  bool cull_enabled = false; // CULL_FACE
  GLenum cull_face = GL_BACK;
  GLenum front_face = GL_CCW;
  GLenum mode[2] = {GL_FILL, GL_FILL}; // front, back
  bool smooth = false;
  bool stipple = false; // POLYGON_STIPPLE
  float offset_factor = 0.0f;
  float offset_units = 0.0f;
  bool offset_point = false, offset_line = false, offset_fill = false;
};

// POLYGON_STIPPLE_BIT: Table 6.14. Row r (bottom first) of the 32x32 stipple; bit c is
// column c. Initially all ones (§3.5.2).
struct PolygonStippleGroup {
  uint32_t rows[32] = {0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu,
                       0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu,
                       0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu,
                       0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu,
                       0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu,
                       0xffffffffu, 0xffffffffu};
};

extern const StateArea kRasterizationArea; // raster_modes.cpp

} // namespace pineda
