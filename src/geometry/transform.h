// Vertex transformation (GL 2.1 §2.11, §2.12, §2.14.6): object coordinates to clip
// coordinates through the composite matrix, clip codes, window coordinates for vertices that
// need no clipping, and the vertex colours: lit (§2.14.1, light_eval.cpp) or the clamped
// current colours, with the colour sum (§3.9) folded in unless texturing or fog is on; texture
// and fog coordinates (texcoord.cpp); derived point sizes (GL 1.4 point parameters). The draw
// home (draw/draw.cpp) gathers a VertexJob per draw and splits it among the worker threads.
#pragma once

#include <cstddef>

#include <glm/mat4x4.hpp>

#include "core/raster_state.h"
#include "core/vertex.h"
#include "geometry/clip.h"
#include "geometry/input_vertex.h"
#include "geometry/light_eval.h"
#include "geometry/texcoord.h"

namespace pineda {

// What the per-vertex loop reads, gathered once per draw.
struct VertexJob {
  const InputVertex* in;
  PVertex* out;
  size_t n;
  const float* m; // composite matrix, column-major
  const ClipSetup* cs;
  const Viewport* vp;
  const LightSetup* light;
  const MaterialChange* changes;
  size_t change_count;
  const Material* material;
  bool color_sum, fold_sum, two_sided;
  const TexVertexSetup* tvs;
  bool tex_live;
  const RasterModes* modes;
  const glm::mat4* mv;
};

// Transforms, lights and finishes job.in[0..n) into job.out[0..n): the loop instantiated for
// lighting on or off and for whether any of texture coordinates, fog or point attenuation is
// live (kExtra), so the common draws carry no test for what they do not use. The four
// instances are in transform.cpp.
template <bool kLit, bool kExtra> void transform_vertices(const VertexJob& job);
extern template void transform_vertices<false, false>(const VertexJob&);
extern template void transform_vertices<false, true>(const VertexJob&);
extern template void transform_vertices<true, false>(const VertexJob&);
extern template void transform_vertices<true, true>(const VertexJob&);

} // namespace pineda
