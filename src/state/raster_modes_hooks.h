// The hooks through which the shared front-end files (enable.cpp, get.cpp, attrib.cpp,
// validate.cpp) reach the rasterization-mode state of src/state/raster_modes.cpp.
#pragma once

#include "core/context.h"

namespace pineda {

// The enable flag behind cap (POINT_SMOOTH, LINE_SMOOTH, LINE_STIPPLE, POLYGON_SMOOTH,
// POLYGON_STIPPLE, POLYGON_OFFSET_*), or nullptr. Changing it dirties kDirtyRasterMode.
bool* raster_mode_capability(Context* ctx, GLenum cap);

// glGet values of the rasterization-mode state and limits.
struct RasterModeValues {
  int n = 0;
  bool is_float = true; // false: integer state (stipple pattern and repeat)
  double v[4] = {};
};
bool raster_mode_query(Context* ctx, GLenum pname, RasterModeValues& out);

// glPushAttrib / glPopAttrib: LINE_BIT, POINT_BIT, POLYGON_STIPPLE_BIT, the stipple, smooth and
// offset parts of POLYGON_BIT and the enables of ENABLE_BIT. restore returns the dirty bits.
void save_raster_modes(const Context* ctx, RasterModeAttrib& a);
uint32_t restore_raster_modes(Context* ctx, const RasterModeAttrib& a, GLbitfield mask);

// The back end's RasterModes from the context (validate.cpp, on kDirtyRasterMode).
void derive_raster_modes(const Context* ctx, RasterModes& m);

} // namespace pineda
