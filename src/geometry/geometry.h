// The geometry stage's entry points: from InputVertex (object coordinates + current
// attributes) to the back end (GL 2.1 §2.11-§2.14).
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/context.h"

namespace pineda {

// Bring ctx->raster and the composite matrices up to date with the GL state (validate.cpp).
void validate_state(Context* ctx);

// The texture units whose InputVertex::tex coordinates a draw in the current state reads
// (kAllTexUnits-style bit mask); validates the state.
uint32_t input_tex_units(Context* ctx);

// Appends to ctx->imm, the primitive between Begin and End, a vertex with the current
// attributes (colour, normal, secondary colour, fog coordinate, edge flag and the texture
// coordinates of the units in ctx->imm_tex_units) and returns it; the caller sets its
// position (begin_end.cpp; glVertex and the evaluators).
InputVertex& append_current_vertex(Context* ctx);

// Transform `n` vertices and draw them in `mode`; indices (optional) select among them.
void draw_vertices(Context* ctx, GLenum mode, const InputVertex* verts, size_t n,
                   const uint32_t* indices, size_t count);

} // namespace pineda
