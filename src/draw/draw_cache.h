// The per-draw setup of the geometry and fragment stages, kept by the draw home across draws
// while nothing it is derived from changes: a glBegin/glEnd of one triangle then pays for its
// vertices and pixels only, not for rebuilding the state key, the block-loop selection and the
// clip planes each time.
#pragma once

#include <cstdint>

#include "fragment/fragment_ops.h"
#include "framebuffer/framebuffer.h"
#include "geometry/clip.h"

namespace pineda {

struct DrawCache {
  // DrawInput::raster_serial when `frag` and `clip` were made; ~0 never matches.
  uint64_t serial = ~uint64_t{0};
  Framebuffer surfaces; // the framebuffer fields prepare_fragments read, as they were then
  ClipSetup clip;
  FragCtx frag;
};

// Whether prepare_fragments would see the same surfaces in a and b.
inline bool same_surfaces(const Framebuffer& a, const Framebuffer& b) {
  return a.width == b.width && a.height == b.height && a.color_format == b.color_format &&
         a.color == b.color && a.color_stride == b.color_stride && a.alpha_bits == b.alpha_bits &&
         a.color_output == b.color_output && a.depth == b.depth && a.depth_bits == b.depth_bits &&
         a.depth_stride == b.depth_stride && a.stencil == b.stencil &&
         a.stencil_bits == b.stencil_bits && a.stencil_stride == b.stencil_stride;
}

} // namespace pineda
