// The attribute stacks (GL 2.1 §6.1.14): what glPushAttrib and glPushClientAttrib save, and
// glXCopyContext's copy of attribute groups between contexts. attrib.cpp saves and restores
// the groups every area lists in its StateArea (area.h).
#pragma once

#include <GL/gl.h>

#include <memory>
#include <vector>

#include "state/area.h"

namespace pineda {

struct Context;

// One glPushAttrib or glPushClientAttrib: a copy of each group of the mask, and for
// ENABLE_BIT every server capability's flag in the areas' order.
struct AttribFrame {
  struct Saved {
    const AttribGroup* group;
    std::unique_ptr<SavedAttrib> copy;
  };
  GLbitfield mask = 0;
  std::vector<Saved> groups;
  std::vector<bool> enables;
};

// glXCopyContext (GLX 1.4 §3.3.7): copies the groups of `mask` (glPushAttrib's bits; others
// are ignored) from src to dst, in the order glPopAttrib restores them. Texture objects are not
// copied: when the two contexts have different share groups, dst keeps its own texture
// bindings and object parameters. Neither context needs to be current.
void copy_attrib_groups(const Context* src, Context* dst, GLbitfield mask);

// ATTRIB_STACK_DEPTH, CLIENT_ATTRIB_STACK_DEPTH and their maxima (Table 6.34, 6.37).
extern const StateArea kAttribStackArea; // attrib.cpp

} // namespace pineda
