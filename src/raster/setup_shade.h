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

// A point sprite of side `size` whose fragments start at pixel (ox, oy) (GL 2.1 §3.3.1): as
// setup_shade_point, but the units of modes.sprite_coord_replace get the sprite coordinates
// s = 1/2 + (x_f + 1/2 - x_w) / size, t likewise in y (negated for the UPPER_LEFT origin),
// r = 0, q = 1 (eqs. 3.3, 3.4).
void setup_shade_sprite(const ShadeSetup& ss, const RasterModes& modes, const PVertex& p,
                        float size, int ox, int oy, ShadeInputs& out);

// gl_PointCoord of an aliased point that is not a sprite, at window (x, y) with size `size`,
// whose fragments start at pixel (ox, oy): the sprite coordinates of eqs. 3.3, 3.4 with the
// UPPER_LEFT origin whatever POINT_SPRITE_COORD_ORIGIN says, as llvmpipe gives them (GL 2.1
// leaves them undefined).
void setup_point_coord(double x, double y, double size, int ox, int oy, ShadeInputs& out);

} // namespace pineda
