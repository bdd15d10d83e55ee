// Validation before a draw: each area derives its state for the draws (area.h:
// StateArea::derive) when the groups it depends on changed, then the back end's RasterState
// is derived from the groups in one place (raster_state.cpp).
#include "state/validate.h"

#include "state/area.h"
#include "state/context.h"

namespace pineda {

void validate_changed_state(Context* ctx) {
  // Objects of the share group change without this context's dirty bits (another context of
  // the group, or a command that changed an object bound nowhere here): when they changed since
  // the last validation, the areas whose derived state depends on them say what is stale.
  const uint64_t generation = ctx->shared->texture_generation;
  if (generation != ctx->validated_generation) {
    for (const StateArea* area : state_areas())
      if (area->stale != nullptr) ctx->dirty |= area->stale(*ctx);
    ctx->validated_generation = generation;
  }
  const uint32_t dirty = ctx->dirty;
  if (dirty == 0) return;
  for (const StateArea* area : state_areas())
    if (area->derive != nullptr && (dirty & area->derive_on) != 0) area->derive(*ctx, dirty);
  derive_raster_state(*ctx, dirty);
  ctx->dirty = 0;
  ++ctx->raster_serial; // the draw cache (draw/draw_cache.h) is stale
}

} // namespace pineda
