// What the scaling and bench scenes (scaling_scenes.cpp, bench_scenes.cpp) borrow from the sweep
// scenes (sweep_scenes.cpp).
#pragma once

#include "scene.h"

namespace sweep {

// The textured family's accurate variant (sweep_tex_lml) at whatever size the frame has: a
// trilinear-filtered ground plane and a textured torus in perspective.
void draw_textured_accurate(const scenes::Frame& frame);

} // namespace sweep
