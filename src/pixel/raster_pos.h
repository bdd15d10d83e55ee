// The current raster position and its associated data (GL 2.1 §2.13, Table 6.5), set by
// glRasterPos / glWindowPos (src/state/raster_pos.cpp) and used by glDrawPixels, glBitmap and
// glCopyPixels.
#pragma once

#include "core/limits.h"

namespace pineda {

struct RasterPos {
  float win[4] = {0.0f, 0.0f, 0.0f, 1.0f}; // x_w, y_w, z_w (after depth range), w_c
  bool valid = true;
  float distance = 0.0f; // CURRENT_RASTER_DISTANCE
  float color[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  float color2[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  float index = 1.0f; // CURRENT_RASTER_INDEX: always its initial value in RGBA mode
  float tex[kMaxTexUnits][4] = {{0, 0, 0, 1}, {0, 0, 0, 1}, {0, 0, 0, 1}, {0, 0, 0, 1}};
};

} // namespace pineda
