// The table of state areas (area.h). The order is the order of validation: the transform's
// composite matrix, then lighting (which reads the model-view matrix), then the texture units
// (which read the lighting setup); RasterState is derived after all of them
// (raster_state.cpp).
#include "state/area.h"

#include "state/attrib.h"
#include "state/context.h"
#include "state/draw_read_buffer.h"

namespace pineda {

namespace {

const StateArea* const kAreas[] = {
    &kCurrentArea,       // current.h: Table 6.5
    &kTransformArea,     // transform.h: Table 6.7
    &kViewportArea,      // viewport.h: Table 6.8
    &kLightingArea,      // lighting.h: Tables 6.9-6.11
    &kFogArea,           // fog.h: Table 6.11
    &kRasterizationArea, // rasterization.h: Tables 6.12-6.14
    &kMultisampleArea,   // multisample.h: Table 6.15
    &kTextureEnvArea,    // texenv.h: Tables 6.15-6.19
    &kTextureObjectArea, // texture_object.h: Tables 6.16-6.19 bindings and objects
    &kFragmentArea,      // fragment_state.h: Tables 6.20-6.22
    &kAccumArea,         // fragment_state.h: Table 6.22
    &kFramebufferArea,   // draw_read_buffer.h: Tables 6.21, 6.35
    &kPixelArea,         // pixel.h: Tables 6.23-6.27
    &kEvalArea,          // eval.h: Table 6.28
    &kSelectArea,        // select.h: Table 6.31 selection and feedback
    &kListArea,          // dlist_state.h: Table 6.31 display lists
    &kHintArea,          // hints.h: Table 6.32
    &kVertexArrayArea,   // varray.h: Tables 6.6-6.9
    &kAttribStackArea,   // attrib.h: Table 6.34 attribute stacks
    &kProgramArea,       // program.h: Tables 6.29-6.31 shaders and programs
    // framebuffer_object.h: framebuffer objects (ARB_framebuffer_object)
    &kFramebufferObjectArea,
};

} // namespace

std::span<const StateArea* const> state_areas() {
  return kAreas;
}

bool* capability_flag(Context& ctx, GLenum cap, const Capability** found) {
  for (const StateArea* area : kAreas)
    for (const Capability& c : area->capabilities)
      if (cap >= c.cap && cap - c.cap < c.count) {
        if (found != nullptr) *found = &c;
        const unsigned unit = c.kind == CapabilityKind::kPerUnit ? ctx.texture.active : 0;
        // GL 2.1 §2.7: the texture enables are state of the conventional units (and of the
        // coordinate sets, as many): none for a higher active texture.
        if (unit >= unsigned(kMaxTexUnits)) return nullptr;
        return c.flag(ctx, cap - c.cap, unit);
      }
  return nullptr;
}

} // namespace pineda
