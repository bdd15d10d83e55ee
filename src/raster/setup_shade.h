// Interpolation planes of the per-fragment shading path (fragment/shade.h) for triangles, lines
// and points: perspective-correct colours, texture coordinates and fog coordinate.
#pragma once

#include "fragment/shade.h"
#include "raster/setup.h"

namespace pineda {

// Triangle: colours from attribute slot `color_slot` (kAttrColor or kAttrBackColor; the
// secondary colour 4 floats after it), constant from `provoking` under flat shading.
// `back_facing` is the polygon's facing (gl_FrontFacing of a fragment shader).
void setup_shade_triangle(const ShadeSetup& ss, const PlaneSetup& ps, const PVertex& a,
                          const PVertex& b, const PVertex& c, const PVertex& provoking, bool flat,
                          int color_slot, bool back_facing, ShadeInputs& out);

// Line: the planes of t(x, y) (raster_line.cpp): value at the origin pixel va + dv * t0, steps
// dv * tdx and dv * tdy.
void setup_shade_line(const ShadeSetup& ss, const PVertex& a, const PVertex& b,
                      const PVertex& provoking, bool flat, double t0, double tdx, double tdy,
                      ShadeInputs& out);

// Point: every value constant.
void setup_shade_point(const ShadeSetup& ss, const PVertex& p, ShadeInputs& out);

} // namespace pineda
