// Current values (GL 2.1 §2.7, §2.13; Table 6.5 "Current Values and Associated Data", the
// "current" attribute group) and the primitive being specified between Begin and End (§2.6).
// Commands in begin_end.cpp (Color, Normal, TexCoord, Vertex, EdgeFlag, Begin, End),
// texenv.cpp (MultiTexCoord), fog.cpp (FogCoord), color_index.cpp (Index) and raster_pos.cpp
// (RasterPos, WindowPos).
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <vector>

#include "core/limits.h"
#include "geometry/input_vertex.h"
#include "geometry/light_eval.h"
#include "pixel/raster_pos.h"

namespace pineda {

struct Context;
struct StateArea;

// CURRENT_BIT: Table 6.5.
struct CurrentGroup {
  float color[4] = {1, 1, 1, 1};
  float color2[4] = {0, 0, 0, 1}; // CURRENT_SECONDARY_COLOR
  float normal[3] = {0, 0, 1};
  float tex[kMaxTexUnits][4] = {{0, 0, 0, 1}, {0, 0, 0, 1}, {0, 0, 0, 1}, {0, 0, 0, 1}};
  float fog_coord = 0.0f; // CURRENT_FOG_COORD
  // CURRENT_INDEX: kept as given (Mesa keeps the float; no masking in RGBA mode).
  float index = 1.0f;
  bool edge = true;
  RasterPos raster_pos; // the current raster position and its data (§2.13)
};

constexpr GLenum kOutsideBeginEnd = 0xffffffffu;

// The primitive between Begin and End (§2.6): no attribute group.
struct BeginEndState {
  GLenum mode = kOutsideBeginEnd;
  std::vector<InputVertex> verts;
  // Texture units whose current coordinates the vertices copy (set by glBegin from the
  // validated state, which cannot change before glEnd).
  uint32_t tex_units = kAllTexUnits;
  // Material calls between Begin and End (§2.14.2): the materials at Begin and every change
  // since, applied per vertex by the draw that End issues.
  Material begin_material[2];
  std::vector<MaterialChange> material_changes;
  // The generic attributes the current vertex shader reads (set by glBegin; GL 2.1 §2.7): four
  // floats each per vertex, the current values when the vertex was specified.
  uint32_t generic_mask = 0;
  std::vector<float> generic;
};

// Appends to the primitive between Begin and End a vertex with the current attributes
// (colour, normal, secondary colour, fog coordinate, edge flag and the texture coordinates of
// the units in BeginEndState::tex_units) and returns it; the caller sets its position
// (glVertex and the evaluators).
InputVertex& append_current_vertex(Context* ctx);

// Appends the current values of the generic attributes of BeginEndState::generic_mask for a
// vertex appended to the primitive (push_current_vertex does it; glArrayElement too).
void append_current_generics(Context* ctx);

extern const StateArea kCurrentArea; // begin_end.cpp

} // namespace pineda
