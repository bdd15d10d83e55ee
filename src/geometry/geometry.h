// The geometry stage's entry points: from InputVertex (object coordinates + current
// attributes) to the back end (GL 2.1 §2.11-§2.14).
#pragma once

#include <cstddef>
#include <cstdint>

#include "state/context.h"
#include "state/validate.h"

namespace pineda {

// The texture units whose InputVertex::tex coordinates a draw in the current state reads
// (kAllTexUnits-style bit mask); validates the state.
uint32_t input_tex_units(Context* ctx);

// Transform `n` vertices and draw them in `mode`; indices (optional) select among them.
void draw_vertices(Context* ctx, GLenum mode, const InputVertex* verts, size_t n,
                   const uint32_t* indices, size_t count);

} // namespace pineda
