// The draw path in SELECT and FEEDBACK mode (GL 2.1 §5.2, §5.3), inside the draw home.
#pragma once

#include "core/vertex.h"
#include "draw/draw.h"

namespace pineda {

// The `in.n` transformed vertices `verts` (of in.in) are assembled in in.mode, clipped and
// culled like a draw, and the primitives become selection hits or feedback values in
// in.records instead of fragments.
void select_feedback_draw(const DrawInput& in, const DrawSources& src, PVertex* verts);

} // namespace pineda
