// The attribute groups of glPushAttrib (src/state/attrib.cpp) as seen from outside the GL
// command stream.
#pragma once

#include <GL/gl.h>

#include "core/context.h"

namespace pineda {

// glXCopyContext (GLX 1.4 §3.3.7): copies the groups of `mask` (glPushAttrib's bits; others
// are ignored) from src to dst, in the order glPopAttrib restores them. Texture objects are not
// copied: when the two contexts have different share groups, dst keeps its own texture
// bindings and object parameters. Neither context needs to be current.
void copy_attrib_groups(const Context* src, Context* dst, GLbitfield mask);

} // namespace pineda
