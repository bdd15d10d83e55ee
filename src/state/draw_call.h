// The draws of the state layer: a glEnd, glDrawArrays, glDrawElements, an evaluator mesh or a
// compiled display-list block becomes one DrawInput for the draw home (draw/draw.h), made here
// from the validated state: the state layer's side of the interface it hands down.
#pragma once

#include <GL/gl.h>

#include <cstddef>
#include <cstdint>

#include "state/context.h"

namespace pineda {

// The texture units whose InputVertex::tex coordinates a draw in the current state reads
// (kAllTexUnits-style bit mask); validates the state.
uint32_t input_tex_units(Context* ctx);

// Transforms `n` vertices and draws them in `mode` (into the draw buffers, or in SELECT and
// FEEDBACK mode into the selection or feedback buffer); indices (optional) select `count` of
// them.
// `generic`: the generic vertex attributes of the vertices, where they do not take their
// current values (program.h).
void draw_vertices(Context* ctx, GLenum mode, const InputVertex* verts, size_t n,
                   const uint32_t* indices, size_t count, GenericVertices generic = {});

} // namespace pineda
